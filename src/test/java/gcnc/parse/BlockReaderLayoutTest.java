package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Span;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The accepted language: words, spacing, case, comments and line ends. */
class BlockReaderLayoutTest {

    private static void expectClean(String source, List<String> blocks) {
        Parsed p = Parsed.of(source);
        assertEquals(List.of(), p.errors(), "diagnostics of: " + source);
        assertEquals(blocks, p.shapes(), "blocks of: " + source);
    }

    @Test
    void wordsKeepTheirTextLetterAndColumns() {
        RawBlock b = Parsed.of("N1230 G01 X12.345 Z-45.678 F0.2\n").blocks().get(0);
        assertEquals(List.of(new Word(Letter.N, "1230", Span.of(1, 1, 6)), new Word(Letter.G, "01", Span.of(1, 7, 10)),
                new Word(Letter.X, "12.345", Span.of(1, 11, 18)), new Word(Letter.Z, "-45.678", Span.of(1, 19, 27)),
                new Word(Letter.F, "0.2", Span.of(1, 28, 32))), b.words());
        assertEquals(Span.of(1, 28, 32), b.last());
        assertEquals(1, b.line());
    }

    @Test
    void lettersInEitherCaseAndShortFormsKeepTheirText() {
        expectClean("g1 m3 x+5. z.5 f.2\n", List.of("1: G1 M3 X+5. Z.5 F.2"));
    }

    @Test
    void wordsWithoutSpacesAndWithTabs() {
        expectClean("G01X10Z5\n\tN20\tM03 S1200\n", List.of("1: G01 X10 Z5", "2: N20 M03 S1200"));
    }

    @Test
    void everyLetterOfTheLanguageTakesItsNumberShape() {
        expectClean("N1 O2 G3 M4 X-1 Z+2 U.3 W4. I-5.5 K6 R7 P8 S9 F10 T0101\n",
                List.of("1: N1 O2 G3 M4 X-1 Z+2 U.3 W4. I-5.5 K6 R7 P8 S9 F10 T0101"));
    }

    @Test
    void everyOtherLetterIsASignedDecimalWord() {
        expectClean("A1 B-2 C+3. D.4 E5 H6 J-7 L8 Q9.5 V-.1 Y10 a1 y-2.\n",
                List.of("1: A1 B-2 C+3. D.4 E5 H6 J-7 L8 Q9.5 V-.1 Y10 A1 Y-2."));
    }

    @Test
    void pIsADecimalWordForTheCheckerToJudge() {
        expectClean("G04 P3.\nG04P-1\np+.5\n", List.of("1: G04 P3.", "2: G04 P-1", "3: P+.5"));
    }

    @Test
    void aColonAndDigitsIsTheProgramNumberWordO() {
        RawBlock b = Parsed.of("%\n:0100( FLANGE OP.2 )\n").blocks().get(0);
        assertEquals(List.of(new Word(Letter.O, "0100", Span.of(2, 1, 6))), b.words());
        expectClean("N5:12 X1\n", List.of("1: N5 O12 X1"));
    }

    @Test
    void aSlashFirstOnTheLineMarksTheBlockForBlockDelete() {
        expectClean("/G00 X1.\n  / N10 X2\n\t/X3\n", List.of("1: /1 G00 X1.", "2: /1 N10 X2", "3: /1 X3"));
        RawBlock b = Parsed.of("/G00 X1.\n").blocks().get(0);
        assertEquals(1, b.blockDelete());
        assertEquals(Span.of(1, 6, 9), b.last());
    }

    @Test
    void aSlashRightAfterAFirstNWordMarksTheBlock() {
        expectClean("N20 /G00 X1.\nN30/G01 Z-1\nn40 / x1\n",
                List.of("1: /1 N20 G00 X1.", "2: /1 N30 G01 Z-1", "3: /1 N40 X1"));
    }

    @Test
    void aDigitAfterTheSlashIsTheSkipLevel() {
        expectClean("/3 G00 X1\nN10 /9X2\n/1N1\n", List.of("1: /3 G00 X1", "2: /9 N10 X2", "3: /1 N1"));
    }

    @Test
    void commentsBeforeTheSlashAreWhitespace() {
        expectClean("(skip me) /2 X1\nN5 (then) / X2\n", List.of("1: /2 X1", "2: /1 N5 X2"));
    }

    @Test
    void aLineWithOnlyASlashAndCommentsMakesNoBlock() {
        Parsed p = Parsed.of("/\n/3 (nothing)\n / ; note\nN1\n");
        assertEquals(List.of("4: N1"), p.shapes());
        assertEquals(List.of(), p.errors());
        assertEquals(4, p.lines());
    }

    @Test
    void aMalformedBlockKeepsItsBlockDelete() {
        Parsed p = Parsed.of("/2 X1 $\n");
        assertEquals(List.of("1: /2 X1 !"), p.shapes());
        assertEquals(List.of("1:7 E003 [$]"), p.errors());
    }

    @Test
    void blocksWithoutASlashHaveNoBlockDelete() {
        assertEquals(0, Parsed.of("N1 X1\n").blocks().get(0).blockDelete());
        assertEquals(0, Parsed.of("N1 X1 :5\n").blocks().get(0).blockDelete());
    }

    @Test
    void commentsMidLineAndTrailingAreWhitespace() {
        expectClean("N10 (rough) G00 X5 ; rapid\nN20 (a)(b)Z1 (end)\n", List.of("1: N10 G00 X5", "2: N20 Z1"));
    }

    @Test
    void aMultiLineCommentSplitsBlocksByTheLineEachWordStandsOn() {
        expectClean("N10 X5 (begin\nmiddle\nend) Z7\nN20\n", List.of("1: N10 X5", "3: Z7", "4: N20"));
    }

    @Test
    void blankWhitespaceAndCommentOnlyLinesGiveNoBlock() {
        Parsed p = Parsed.of("%\n\n   \t\n(header)\n; note\nO1000\n%\n");
        assertEquals(List.of("6: O1000"), p.shapes());
        assertEquals(List.of(), p.errors());
        assertEquals(7, p.lines());
    }

    @Test
    void tapeMarkIgnoresTheRestOfItsLine() {
        expectClean("% anything $ Y goes\nN1\n", List.of("2: N1"));
    }

    @Test
    void crlfLoneCrAndMissingFinalNewline() {
        expectClean("N1 X1\r\nN2 X2\rN3 X3\r\n\r\nN5 X5", List.of("1: N1 X1", "2: N2 X2", "3: N3 X3", "5: N5 X5"));
        assertEquals(5, Parsed.of("N1 X1\r\nN2 X2\rN3 X3\r\n\r\nN5 X5").lines());
    }

    @Test
    void aByteOrderMarkIsIgnored() {
        expectClean("\uFEFFN1\n", List.of("1: N1"));
    }

    @Test
    void crlfColumnsAreUnaffected() {
        Parsed p = Parsed.of("N1\r\nN2 $\r\n");
        assertEquals(List.of("2:4 E003 [$]"), p.errors());
    }

    @Test
    void lastIsTheStartOfTheLastWord() {
        RawBlock b = Parsed.of("  N5   X10.5  \n").blocks().get(0);
        assertEquals(Span.of(1, 8, 13), b.last());
        assertTrue(!b.malformed());
    }

    @Test
    void emptyInput() {
        Parsed p = Parsed.of("");
        assertEquals(List.of(), p.blocks());
        assertEquals(0, p.lines());
    }

    @Test
    void theSamplesParseCleanly() throws java.io.IOException {
        for (String name : List.of("samples/bishop.nc", "samples/turning.nc")) {
            Parsed p = Parsed.of(new String(java.nio.file.Files.readAllBytes(java.nio.file.Path.of(name)),
                    java.nio.charset.StandardCharsets.UTF_8));
            assertEquals(List.of(), p.errors(), name);
            assertTrue(p.blocks().size() > 10, name);
        }
    }
}
