package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Diagnostics;
import org.junit.jupiter.api.Test;

/**
 * A state per block, its seldom-changing modes shared until one of them changes (ModalState.Modes),
 * and each block checked from a draft emptied of the block before (BlockDraft.start).
 */
class ModalStateTest {
    private final Diagnostics diags = new Diagnostics();
    private final Checker checker = new Checker(Run.TABLES, Run.profile("fanuc"), diags);
    private int line;

    private ModalState after(String block) {
        checker.check(Run.block(++line, block));
        return checker.state();
    }

    @Test
    void movesShareTheModesAndAChangedModeMakesNewOnes() {
        for (String b : new String[] {"G21 G99", "T0101", "G97 S500 M03", "G00 X70. Z2."}) {
            after(b);
        }
        ModalState cut = after("N10 G01 Z-5. F0.1");
        ModalState next = after("N11 X72.");
        assertSame(cut.modes(), next.modes()); // only the motion, position and N changed
        assertNotEquals(cut.position(), next.position());
        assertEquals(11, next.lastN());
        ModalState slower = after("N12 Z-10. F0.05");
        assertNotSame(next.modes(), slower.modes());
        assertEquals(0.05, slower.feed(), 1e-12);
        ModalState perMinute = after("N13 G98 Z-12. F50.");
        assertNotEquals(slower.modes(), perMinute.modes());
        assertTrue(slower.feedPerRev() && !perMinute.feedPerRev());
        assertEquals(0, diags.errorCount(), () -> diags.sorted().toString());
    }

    /** What one block set in its draft (an exact stop, M functions, a G96) is not the next block's. */
    @Test
    void aBlockStartsFromAnEmptyDraft() {
        for (String b : new String[] {"G21 G99", "T0101", "G97 S500 M03", "G00 X70. Z2."}) {
            after(b);
        }
        var first = checker.check(Run.block(++line, "G09 G01 Z-5. F0.1 M08"));
        var second = checker.check(Run.block(++line, "X72."));
        assertEquals(gcnc.ir.StopAt.BLOCK_END, first.get(0).stopAt());
        assertEquals(1, first.get(0).before().size() + first.get(0).after().size());
        assertEquals(gcnc.ir.StopAt.BLEND, second.get(0).stopAt());
        assertEquals(0, second.get(0).before().size() + second.get(0).after().size());
        assertEquals(0, diags.errorCount(), () -> diags.sorted().toString());
    }
}
