package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * G10 L2 (docs/semantics.md, "Work offsets written by the program"): P1-P6 write G54-G59 as a
 * machine position (G53's coordinates: the fanuc profile's machine zero is X210 Z560 mm, a radius,
 * and its G54 is X0 Z100, so G54 is X-420. Z-460. in the control's machine coordinates, X a
 * diameter), U/W add to it, P0 is the external offset every work offset adds.
 */
class OffsetSettingTest {
    private static final String HEAD = "G21 G99\nT0101\nG97 S1000 M03\n";
    private static final String MOVE = "G54\nG00 X60. Z5.\nM30\n";

    /** The machine position of every rapid's end, mm, "X Z" (X a radius). */
    private static String ends(Run r) {
        return ends(r.blocks);
    }

    private static String ends(List<CheckedBlock> blocks) {
        return blocks.stream().flatMap(b -> b.motions().stream()).filter(m -> m instanceof Motion.Linear)
                .map(m -> ((Motion.Linear) m).to()).map(p -> Math.round(p.x() / 500.0 * 1000) / 1000.0 + " "
                        + Math.round(p.z() / 500.0 * 1000) / 1000.0).collect(Collectors.joining(", "));
    }

    private static String errs(Run r) {
        return NoseCompensationTest.errs(r);
    }

    @Test
    void g10L2WritesAWorkOffsetAsAMachinePositionForTheBlocksAfter() {
        Run plain = Run.of("fanuc", HEAD + MOVE);
        assertEquals("30.0 105.0", ends(plain));
        // the profile's own G54, written again: the same move
        Run same = Run.of("fanuc", HEAD + "G10 L2 P1 X-420. Z-460.\n" + MOVE);
        assertEquals("", errs(same));
        assertEquals("30.0 105.0", ends(same));
        // 20 mm further from the chuck
        Run moved = Run.of("fanuc", HEAD + "G10 L2 P1 X-420. Z-440.\n" + MOVE);
        assertEquals("30.0 125.0", ends(moved));
        // W adds to it; P0 is the external offset every G54-G59 adds
        assertEquals("30.0 95.0", ends(Run.of("fanuc", HEAD + "G10 L2 P1 W-10.\n" + MOVE)));
        assertEquals("30.0 115.0", ends(Run.of("fanuc", HEAD + "G10 L2 P0 Z10.\n" + MOVE)));
        // another work offset leaves G54 alone
        assertEquals("30.0 105.0", ends(Run.of("fanuc", HEAD + "G10 L2 P2 Z-300.\n" + MOVE)));
        // the Haas form is the same (inch here: 1 in = 25.4 mm)
        Run haas = Run.of("haas", "G20 G99\nT101\nG97 S1000 M03\nG10 L2 P1 W-1.\nG54\nG00 X2. Z0.2\nM30\n");
        assertEquals("", errs(haas));
    }

    /** The block delete switch's other position sees the offsets written before its first '/' block. */
    @Test
    void theOtherBlockDeletePositionKeepsTheWrittenOffsets() throws Exception {
        CycleExpansionTest.Expanded e = CycleExpansionTest.expand("fanuc", new java.io.StringReader(
                HEAD + "G10 L2 P1 X-420. Z-440.\n/M08\nG54\n/G00 X60. Z5.\nG00 X60. Z-125.\nM30\n"));
        // Z-125. is inside the Z travel (-10 mm) from the written G54 (Z120), beyond it from the profile's (Z100)
        assertEquals("[]", e.diagnostics().sorted().toString());
        assertEquals("30.0 -5.0", ends(e.blocks()).substring(ends(e.blocks()).lastIndexOf(", ") + 2));
    }

    @Test
    void anotherLOrAWrongPIsAnError() {
        assertEquals("E625@4:5", errs(Run.of("fanuc", HEAD + "G10 L1 P1 X1.\n" + MOVE)));
        assertEquals("E625@4:1", errs(Run.of("fanuc", HEAD + "G10 P1 Z1.\n" + MOVE)));
        assertEquals("E626@4:8", errs(Run.of("fanuc", HEAD + "G10 L2 P7 Z1.\n" + MOVE)));
        assertEquals("E626@4:1", errs(Run.of("haas", "G20 G99\nT101\nG97 S1000 M03\nG10 L2 Z1.\nM30\n")));
        // system B has no U/W: an incremental offset is G91 Z
        Run b = Run.of(Run.profileWithControl("fanuc", "fanuc-b"), "G21 G95\nT0101\nG97 S1000 M03\nG10 L2 P1 W1.\nM30\n",
                Checker.ERROR_CAP);
        assertEquals("E161@4:11", errs(b));
    }
}
