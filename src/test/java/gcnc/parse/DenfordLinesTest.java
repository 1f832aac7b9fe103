package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.diag.Diagnostics;
import gcnc.ir.RawBlock;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Denford / MIRAC set-up lines (docs/language.md, E261): a '[' and a name at the start of a line
 * is the training control's own line, read as a comment with a warning at its '[', never the
 * macro error (E111) a '[' would otherwise be; a macro line with a bracketed
 * expression stays a macro line.
 */
class DenfordLinesTest {
    private static final String PROGRAM = "[BILLET X50 Z100\n  [TOOLDEF T1 D0.4\nG21 G99\n[EDGEMOVE\nG00 X52. Z2.\n";

    @Test
    void aSetUpLineIsAWarningAtItsBracketAndNoBlock() {
        Parsed p = Parsed.of(PROGRAM);
        assertEquals(List.of("1:1 E261 [BILLET X50 Z100]", "2:3 E261 [TOOLDEF T1 D0.4]", "4:1 E261 [EDGEMOVE]"),
                p.errors());
        assertEquals(List.of("3: G21 G99", "5: G00 X52. Z2."), p.shapes());
    }

    @Test
    void onAControlWithMacrosTooAndAnExpressionStaysAMacroLine() throws Exception {
        Diagnostics d = new Diagnostics();
        BlockReader r = BlockReader.forControl(new StringReader(PROGRAM + "[#1+2]\n#1=[#2]\nM30\n"), d, true);
        List<String> kinds = new ArrayList<>();
        for (RawBlock b = r.next(); b != null; b = r.next()) {
            kinds.add(b.line() + (b.macro() != null ? " macro" : " words"));
        }
        assertEquals(List.of("3 words", "5 words", "6 macro", "7 macro", "8 words"), kinds);
        assertEquals(3, d.sorted().stream().filter(x -> x.code() == gcnc.diag.Code.E261_DENFORD_SETUP_LINE).count());
        // "[B" is not a name of two letters and more: not a set-up line
        assertEquals(List.of("1:1 E111 [[B X1]"), Parsed.of("[B X1\n").errors());
    }
}
