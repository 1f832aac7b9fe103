package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A block delete '/' in the middle of a block (Haas, Fanuc: with the switch on the block runs up
 * to the '/' and the rest is skipped; docs/grammar.md): both positions of the switch are checked,
 * as for a '/' at the start of a block.
 */
class MidBlockDeleteTest {

    @Test
    void withTheSwitchOffTheWholeBlockRuns() {
        CycleExpansionTest.Expanded e = CornerInsertionTest.run("haas", "G01 Z-5. F0.1 /X30.\nM30\n");
        assertEquals("", CornerInsertionTest.errs(e));
        assertEquals(List.of("5 G01 X30.0000 Z-5.0000"), CornerInsertionTest.moves(e, 5));
    }

    @Test
    void whatOnlyTheSwitchOnBreaksIsReportedWithTheNoteSayingSo() {
        // the switch on skips the M03 after the M05: the cut has no spindle (E037 in that variant only)
        CycleExpansionTest.Expanded e = CornerInsertionTest.run("haas",
                "M05\nG97 S800 /M03\nG01 Z-5. F0.1\nM30\n");
        assertTrue(CornerInsertionTest.errs(e).contains("E037@7:1"), CornerInsertionTest.errs(e));
        assertTrue(e.diagnostics().sorted().stream().anyMatch(d -> d.code() == Code.E118_BLOCK_DELETE_VARIANT
                && d.span().line() == 7 && d.args().equals(List.of("on"))), e.diagnostics().sorted()::toString);
    }

    @Test
    void aMidBlockSlashOnAControlWithoutBlockDeleteIsError10AtTheSlash() {
        assertTrue(CornerInsertionTest.errs(CornerInsertionTest.run("thesis-2004", "N5 G00 X30. /Z5.\nN6 M30\n"))
                .contains("E010@5:13"));
    }
}
