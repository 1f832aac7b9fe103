package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.ProgramFrame;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/**
 * The chamfered pull-out of Haas M23 (docs/threading.md), one tiny program per behaviour on the haas
 * machine (metric programs: G21): under M23, on at power-up, each pass of a G92 or a G76 ends with a
 * chamfer over its last lead (Z going on at the lead, X moving out at 45 degrees), and the cycle's
 * retract starts where the chamfer ends; M24 keeps the square pull-out; G32 has none; the profile's
 * {@code thread.chamfer_leads} and {@code thread.chamfer_angle} shape it. The passes are read back in
 * program terms: X a diameter, "X23.2000 Z-25.0000".
 */
class ThreadChamferTest {
    /** Lines 1-4: metric, feed per revolution, G97 700 r/min forward, at X30 Z5 (outside an M20x1.5 thread). */
    private static final String START = "G21 G99\nT303\nG97 S700 M03\nG00 X30. Z5.\n";

    /** Each thread pass as "straight part end > pass end" ("X23.2000 Z-25.0000" when square). */
    private static List<String> passes(Run r) {
        List<String> out = new ArrayList<>();
        for (CheckedBlock b : r.blocks) {
            for (Motion m : b.motions()) {
                if (m instanceof Motion.Thread t) {
                    out.add(t.chamfered() ? at(t.chamferStart(), b.frame()) + " > " + at(t.to(), b.frame())
                            : at(t.to(), b.frame()));
                }
            }
        }
        return out;
    }

    /** The moves of the block after the first thread pass, where the cycle's retract goes. */
    private static List<String> afterFirstPass(Run r) {
        List<String> out = new ArrayList<>();
        boolean seen = false;
        for (CheckedBlock b : r.blocks) {
            for (Motion m : b.motions()) {
                if (seen && out.size() < 2 && m instanceof Motion.Linear l) {
                    out.add((l.rapid() ? "G00 " : "G01 ") + at(l.from(), b.frame()) + " > " + at(l.to(), b.frame()));
                }
                seen = seen || m instanceof Motion.Thread;
            }
        }
        return out;
    }

    static String at(Point p, ProgramFrame f) {
        return String.format(Locale.ROOT, "X%.4f Z%.4f", (p.x() - f.origin().x()) / f.perX(),
                (p.z() - f.origin().z()) / f.perZ());
    }

    @Test
    void underM23EachG92PassEndsWithAChamferOverItsLastLead() {
        Run r = Run.of("haas", START + "G92 X23.2 Z-25. F1.5\nX22.8\nG00 X40.\nM30\n");
        assertEquals("", r.errors());
        // one lead (1.5 mm) before the end the pass leaves its diameter; at the end it is 1.5 mm (radius) out
        assertEquals(List.of("X23.2000 Z-23.5000 > X26.2000 Z-25.0000", "X22.8000 Z-23.5000 > X25.8000 Z-25.0000"),
                passes(r));
        // then the retract out to the start's diameter and back, from where the chamfer ended
        assertEquals(List.of("G00 X26.2000 Z-25.0000 > X30.0000 Z-25.0000", "G00 X30.0000 Z-25.0000 > X30.0000 Z5.0000"),
                afterFirstPass(r));
    }

    @Test
    void underM23EachPassOfAHaasOneBlockG76EndsWithAChamfer() {
        Run r = Run.of("haas", START + "G76 X22.16 Z-25. K0.92 D0.35 F1.5\nM30\n");
        assertEquals("", r.errors());
        int chamfered = 0;
        for (CheckedBlock b : r.blocks) {
            for (Motion m : b.motions()) {
                if (m instanceof Motion.Thread t) {
                    assertTrue(t.chamfered(), at(t.to(), b.frame()));
                    ProgramFrame f = b.frame();
                    // along the pass's line (no taper: the pass's X) for all but the last lead of Z ...
                    assertEquals(t.from().x(), t.chamferStart().x(), 1e-6);
                    assertEquals(1.5, (t.chamferStart().z() - t.to().z()) / f.perZ(), 1e-6);
                    // ... then out at 45 degrees: as far out (radius) as along Z
                    assertEquals(1.5 * 2, (t.to().x() - t.chamferStart().x()) / f.perX(), 1e-6);
                    chamfered++;
                }
            }
        }
        // as many passes as the same G76 cuts under M24, each chamfered (D 0.35 to K 0.92 at constant area: 7)
        assertEquals(7, chamfered);
        assertEquals(7, passes(Run.of("haas", START + "M24\nG76 X22.16 Z-25. K0.92 D0.35 F1.5\nM30\n")).size());
    }

    @Test
    void m24KeepsTheSquarePullOutAndM23TurnsTheChamferOnAgain() {
        String g92 = "G92 X23.2 Z-25. F1.5\nG00 X40.\n";
        Run square = Run.of("haas", START + "M24\n" + g92 + "M30\n");
        assertEquals("", square.errors());
        assertEquals(List.of("X23.2000 Z-25.0000"), passes(square));
        assertEquals(List.of("G00 X23.2000 Z-25.0000 > X30.0000 Z-25.0000", "G00 X30.0000 Z-25.0000 > X30.0000 Z5.0000"),
                afterFirstPass(square));
        Run again = Run.of("haas", START + "M24\nM23\nG00 X30.\n" + g92 + "M30\n");
        assertEquals(List.of("X23.2000 Z-23.5000 > X26.2000 Z-25.0000"), passes(again));
    }

    @Test
    void g32HasNoPullOutUnderM23() {
        Run r = Run.of("haas", START + "G00 X23.\nG32 Z-25. F1.5\nG00 X30.\nM30\n");
        assertEquals("", r.errors());
        assertEquals(List.of("X23.0000 Z-25.0000"), passes(r));
    }

    @Test
    void theProfileGivesTheChamfersLengthAndAngle() {
        // two leads (3 mm) at 30 degrees: 3 x tan 30 = 1.7321 mm out (radius), 3.4641 on the diameter
        Run r = Run.of(ThreadErrorsTest.haasWith("thread.chamfer_leads = 1.0", "thread.chamfer_leads = 2",
                "thread.chamfer_angle = 45", "thread.chamfer_angle = 30"), START + "G92 X23.2 Z-25. F1.5\nM30\n",
                Checker.ERROR_CAP);
        assertEquals("", r.errors());
        assertEquals(List.of("X23.2000 Z-22.0000 > X26.6641 Z-25.0000"), passes(r));
        // a chamfer of zero leads is Haas's Setting 95 = 0: a square pull-out even under M23
        Run none = Run.of(ThreadErrorsTest.haasWith("thread.chamfer_leads = 1.0", "thread.chamfer_leads = 0"),
                START + "G92 X23.2 Z-25. F1.5\nG92 X23.2 Z4. F1.5\nM30\n", Checker.ERROR_CAP);
        assertEquals("", none.errors());
        assertEquals(List.of("X23.2000 Z-25.0000", "X23.2000 Z4.0000"), passes(none));
    }

    @Test
    void inABoreTheChamferPullsOutTowardTheCentre() {
        Run r = Run.of("haas", "G21 G99\nT303\nG97 S700 M03\nG00 X14. Z5.\nG92 X18.4 Z-20. F1.5\nG00 X10.\nM30\n");
        assertEquals("", r.errors());
        assertEquals(List.of("X18.4000 Z-18.5000 > X15.4000 Z-20.0000"), passes(r));
    }

    @Test
    void onATaperTheChamferLeavesTheTapersLine() {
        // Haas I: the cut starts 1 mm (radius) above its end, X25. at Z5. down to X23. at Z-25.; at Z-23.5
        // the line is at X23.1, and the chamfer ends 3 mm (diameter) above that
        Run r = Run.of("haas", START + "G92 X23. Z-25. I1. F1.5\nM30\n");
        assertEquals("", r.errors());
        assertEquals(List.of("X23.1000 Z-23.5000 > X26.1000 Z-25.0000"), passes(r));
    }

    @Test
    void aG92StartingOnItsOwnDiameterHasNoSideToPullOutTo() {
        String program = "G21 G99\nT303\nG97 S700 M03\nG00 X23. Z5.\n%sG92 X23. Z-25. F1.5\nM30\n";
        assertEquals("5:1:E160", Run.of("haas", String.format(program, "")).errors());
        assertEquals("", Run.of("haas", String.format(program, "M24\n")).errors());
    }

    @Test
    void aChamferedPassEndsOutOfTheGrooveAndTheBlockEndsThere() {
        Run r = Run.of("haas", START + "G92 X23.2 Z-25. F1.5\nM30\n");
        for (CheckedBlock b : r.blocks) {
            for (Motion m : b.motions()) {
                if (m instanceof Motion.Thread t) {
                    assertEquals(t.to(), b.end());
                    assertFalse(t.straightEnd().equals(t.to()));
                }
            }
        }
    }
}
