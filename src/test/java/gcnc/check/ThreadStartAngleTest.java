package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Multi-start threads (docs/threading.md, "Multi-start threads"): Q on a G92 (Fanuc B G78) or a Haas
 * one-block G76 is the spindle angle each pass starts at, in thousandths of a degree without a
 * point; a G92's Q stays in force for the blocks that repeat it and a new G92 without Q starts at 0.
 * The pass's {@code Motion.Thread.startAngle} carries it to the backend.
 */
class ThreadStartAngleTest {
    private static final String START = "G21 G99\nT0707\nG97 S800 M03\nG00 X30. Z5.\n";

    /** The start angle of each thread pass, in degrees. */
    private static List<Double> angles(Run r) {
        List<Double> out = new ArrayList<>();
        for (CheckedBlock b : r.blocks) {
            for (Motion m : b.motions()) {
                if (m instanceof Motion.Thread t) {
                    out.add(t.startAngle());
                }
            }
        }
        return out;
    }

    @Test
    void aG92QStaysForItsRepeatsAndANewG92StartsAtZero() {
        String two = "G92 X23.2 Z-25. Q0 F3.\nX22.8\nG92 X23.2 Z-25. Q180000 F3.\nX22.8\nG92 X23.2 Z-25. F3.\nM30\n";
        for (MachineProfile p : new MachineProfile[] {Run.profile("fanuc"), Run.profile("haas")}) {
            Run r = Run.of(p, START.replace("T0707", p.name().equals("haas") ? "T303" : "T0707") + two,
                    Checker.ERROR_CAP);
            assertEquals("", r.errors(), p.name());
            // Haas under M23: still one Motion.Thread per pass (the chamfer is part of it)
            assertEquals(List.of(0.0, 0.0, 180.0, 180.0, 0.0), angles(r), p.name());
        }
        Run b = Run.of(Run.profileWithControl("fanuc", "fanuc-b"),
                START.replace("G99", "G95") + "G78 X23.2 Z-25. Q90000 F3.\nX22.8\nM30\n", Checker.ERROR_CAP);
        assertEquals("", b.errors());
        assertEquals(List.of(90.0, 90.0), angles(b));
    }

    @Test
    void aHaasG76QStartsEveryPassAtIt() {
        Run r = Run.of("haas", "G21 G99\nT303\nG97 S700 M03\nG00 X30. Z5.\n"
                + "G76 X22.16 Z-25. K0.92 D0.35 A60 P1 Q120500 F3.\nM30\n");
        assertEquals("", r.errors());
        List<Double> a = angles(r);
        assertEquals(7, a.size());
        for (double v : a) {
            assertEquals(120.5, v, 1e-9);
        }
    }

    @Test
    void qIsAWholeNumberOfThousandthsOfADegreeUpToAWholeTurn() {
        assertEquals("5:17:E197", Run.of("fanuc", START + "G92 X23.2 Z-25. Q180. F3.\nM30\n").errors());
        assertEquals("5:17:E197", Run.of("fanuc", START + "G92 X23.2 Z-25. Q360001 F3.\nM30\n").errors());
        assertEquals("5:17:E197", Run.of("fanuc", START + "G92 X23.2 Z-25. Q-1000 F3.\nM30\n").errors());
        // Q360000 is a whole turn: the same start as Q0
        Run turn = Run.of("fanuc", START + "G92 X23.2 Z-25. Q360000 F3.\nM30\n");
        assertEquals("", turn.errors());
        assertEquals(List.of(0.0), angles(turn));
        // the Fanuc G76's second block Q is the first depth, never a start angle
        Run fanucG76 = Run.of("fanuc", START + "G76 X22.16 Z-25. P920 Q350 F1.5\nM30\n");
        assertEquals("", fanucG76.errors());
        assertEquals(0.0, (double) angles(fanucG76).get(0));
    }
}
