package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.CheckedBlock;
import gcnc.machine.MachineProfile;
import org.junit.jupiter.api.Test;

/**
 * Codes of the Haas and Fanuc 0i-TF manuals and the Fusion turning posts that gcnc names rather
 * than calling them undefined (docs/language.md): the exact stops the planner follows (G09, G61/G64),
 * the control's modes that change nothing in the path (function mode_only: E700, E701), codes not supported yet (E110: the sub-spindle, the bar
 * feeder, side drilling with live tools, polar interpolation) and the Haas M19 orientation angle (E703).
 */
class ControlCodesTest {
    private static final String FANUC = "G21 G99\nT0101\nG97 S500 M03\nG00 X70. Z2.\n";
    private static final String HAAS = "G20 G99\nT0101\nG97 S500 M03\nG00 X2.2 Z0.1\n";

    private static Run fanucB(String program) {
        MachineProfile b = Run.profileWithControl("fanuc", "fanuc-b");
        return Run.of(b, FANUC.replace("G99", "G95") + program, Checker.ERROR_CAP);
    }

    private static int moves(Run r) {
        int n = 0;
        for (CheckedBlock b : r.blocks) {
            n += b.motions().size();
        }
        return n;
    }

    @Test
    void exactStopModeAndCuttingModeAreFollowedOnEveryControl() {
        assertEquals("", Run.of("fanuc", FANUC + "G61\nG64\nM30\n").errors());
        assertEquals("", fanucB("G61\nG64\nM30\n").errors());
        assertEquals("", Run.of("haas", HAAS + "G61\nG64\nM30\n").errors());
        // one mode per block: they share a group
        assertEquals("5:5:E016", Run.of("fanuc", FANUC + "G61 G64\nM30\n").errors());
    }

    /** G09 stops its own block, G61 every block until G64: the checked block says where (CheckedBlock.stopAt). */
    @Test
    void theCheckedBlockSaysWhereTheProgramAsksForAnExactStop() {
        Run fanuc = Run.of("fanuc", FANUC + "G01 Z-5. F0.1\nG09 X72. Z-6.\nZ-10.\nG61 Z-12.\nX74.\nG64 Z-14.\nM30\n");
        assertEquals("BLEND BLEND BLEND BLEND BLEND BLOCK_END BLEND EVERY_MOTION EVERY_MOTION BLEND BLEND", stops(fanuc));
        Run haas = Run.of("haas", HAAS + "G01 Z-0.2 F0.01\nG09 X2.3\nG61\nZ-0.4\nG64\nZ-0.5\nM30\n");
        assertEquals("BLEND BLEND BLEND BLEND BLEND BLOCK_END EVERY_MOTION EVERY_MOTION BLEND BLEND BLEND", stops(haas));
    }

    private static String stops(Run r) {
        StringBuilder s = new StringBuilder();
        for (CheckedBlock b : r.blocks) {
            s.append(s.length() == 0 ? "" : " ").append(b.stopAt());
        }
        return s.toString();
    }

    @Test
    void theStoredStrokeCheckAreaIsAWarningAndMovesNothing() {
        Run area = Run.of("fanuc", FANUC + "G22 X100. Z100. I-100. K-100.\nG23\nM30\n");
        assertEquals("5:1:E701, 6:1:E700", area.errors());
        assertEquals(moves(Run.of("fanuc", FANUC + "M30\n")), moves(area));
        // G22 alone turns the check on with the area the machine holds: a note
        assertEquals("5:1:E700", fanucB("G22\nM30\n").errors());
        // the words are G22's, not a move of the modal G00 (which would take no I or K: E026)
        assertEquals("5:1:E701", Run.of("fanuc", FANUC + "G22 X100. Z100. I-100. K-100.\nG00 X60.\nM30\n").errors());
    }

    @Test
    void codesOfOtherOptionsAreNotSupportedYet() {
        // side drilling and tapping along X: live tooling (the Series 15 format G81/G82 are followed: BoringCyclesTest)
        assertEquals("6:1:E110", Run.of("fanuc", FANUC + "G00 X50. Z-10.\nG87 X40. R2. F0.1\nM30\n").errors());
        assertEquals("6:1:E110", fanucB("G00 X50. Z-10.\nG88 X40. R2. P500 F1.\nM30\n").errors());
        assertEquals("5:1:E110, 6:1:E110", fanucB("G112\nG113\nM30\n").errors());
        assertEquals("5:1:E110, 6:1:E110, 7:1:E110", Run.of("haas", HAAS + "G14\nG15\nG105\nM30\n").errors());
        for (int m : new int[] {114, 115, 119, 143, 144, 145}) {
            assertEquals("5:1:E110", Run.of("haas", HAAS + "M" + m + "\nM30\n").errors(), "M" + m);
        }
    }

    @Test
    void anM19AngleIsTheM19s() {
        // M19 has no output on the haas machine (E113, once): the angle is checked and goes nowhere
        assertEquals("6:1:E113", Run.of("haas", HAAS + "M05\nM19 P90.\nM19 P270\nM19 R90.5\nM19 R0\nM30\n").errors());
        assertEquals("6:5:E703", Run.of("haas", HAAS + "M05\nM19 P90.5\nM30\n").errors());
        assertEquals("6:5:E703", Run.of("haas", HAAS + "M05\nM19 R360.1\nM30\n").errors());
        // with a G or an axis word the P is not the M19's
        assertEquals("6:9:E036", Run.of("haas", HAAS + "M05\nM19 X2. P90\nM30\n").errors().replace("6:1:E113, ", ""));
    }
}
