package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Diagnostics;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The hot path takes the common line, leaves every unusual one to the lexer, and agrees with it. */
class FastScannerTest {

    private static boolean fast(String line) {
        return FastScanner.scan(line.toCharArray(), line.length(), 1, new ArrayList<>(), new NumberTexts());
    }

    @Test
    void theCommonLinesStayOnTheFastPath() {
        for (String line : List.of("N1230 G01 X12.345 Z-45.678 F0.2", "G04 P3.", "G04 P-1", "Y10 A-1 Q5 b.5",
                "T0101 M03 S1200 (rough)", "G28 U0. W0. ; home", "")) {
            assertTrue(fast(line), line);
        }
    }

    @Test
    void unusualLinesGoToTheLexer() {
        for (String line : List.of(":0100", "/N10 X1", "N10/X1", "N10 /2 X1", "#501=350.", "G1Z[#502]F0.35",
                "N1 ]", "roughing pass", "G00 Xabc", "P", "S1.", "P1.2.3")) {
            assertFalse(fast(line), line);
        }
    }

    @Test
    void theFastPathAndTheLexerPathAgreeOnTheNewForms() throws IOException {
        String src = "N1 Y10 A-1 Q5\nG04 P3.\n:0100(X)\n/N10 X1\nN10 /3 X1\nN10 G00 /X1\n#1=2\nG1Z[#1]\n"
                + "roughing pass\nG00 Xabc\np-.5 h1 j2. l3 v-4 e5 c6 d7 b8\n/\n";
        List<RawBlock> fast = Parsed.of(src).blocks();
        Diagnostics d = new Diagnostics();
        BlockReader slow = new BlockReader(new StringReader(src), d, false);
        List<RawBlock> blocks = new ArrayList<>();
        for (RawBlock b = slow.next(); b != null; b = slow.next()) {
            blocks.add(b);
        }
        assertEquals(blocks, fast);
        assertEquals(d.sorted(), Parsed.of(src).diagnostics());
        List<Word> words = new ArrayList<>();
        assertTrue(FastScanner.scan("p-.5 h1".toCharArray(), 7, 11, words, new NumberTexts()));
        assertEquals(blocks.get(10).words().subList(0, 2).toString(), words.toString());
    }
}
