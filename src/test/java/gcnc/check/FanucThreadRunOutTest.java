package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/**
 * The Fanuc thread chamfer rr of {@code G76 P(mmrraa)} (docs/threading.md, "The Fanuc chamfer rr"):
 * every pass of a G76 then leaves the groove over its last rr/10 leads at the machine's chamfer
 * angle (parameter 5131, the profile's {@code thread.chamfer_angle}, 45 degrees by default), as
 * the Haas M23 pull-out does; rr = 00 is the straight pull-out; the value stays in force for later
 * G76s; G92 is not chamfered by it. On the fanuc machine (metric), under control fanuc-a and
 * fanuc-b alike.
 */
class FanucThreadRunOutTest {
    /** Lines 1-4: metric, feed per revolution, G97 800 r/min forward, at X30 Z5 (outside an M24 thread). */
    private static final String START = "G21 G99\nT0707\nG97 S800 M03\nG00 X30. Z5.\n";

    /** Each thread pass's chamfer as "Z length along the pass, X out on the diameter" ("square" without one). */
    private static List<String> chamfers(Run r) {
        List<String> out = new ArrayList<>();
        for (CheckedBlock b : r.blocks) {
            for (Motion m : b.motions()) {
                if (m instanceof Motion.Thread t) {
                    out.add(!t.chamfered() ? "square" : String.format(Locale.ROOT, "Z%.4f X%.4f",
                            (t.to().z() - t.chamferStart().z()) / b.frame().perZ(),
                            (t.to().x() - t.chamferStart().x()) / b.frame().perX()));
                }
            }
        }
        return out;
    }

    private static List<String> times(int n, String s) {
        List<String> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            out.add(s);
        }
        return out;
    }

    private static final String THREAD = "G76 X22.16 Z-25. P920 Q350 F1.5\n";

    @Test
    void rr10EndsEveryPassOfTheG76WithAOneLeadChamferAt45Degrees() {
        for (MachineProfile p : new MachineProfile[] {Run.profile("fanuc"), Run.profileWithControl("fanuc", "fanuc-b")}) {
            String start = p.control().name().equals("fanuc-b") ? START.replace("G99", "G95") : START;
            Run r = Run.of(p, start + "G76 P011060 Q50 R0\n" + THREAD + "G00 X40.\nM30\n", Checker.ERROR_CAP);
            assertEquals("", r.errors(), p.control().name());
            List<String> c = chamfers(r);
            // toward the chuck over the last 1.5 mm, 1.5 mm out (3 mm on the diameter): every pass, the finishing ones too
            assertEquals(times(c.size(), "Z-1.5000 X3.0000"), c, p.control().name());
            assertEquals(true, c.size() > 3, p.control().name());
        }
    }

    @Test
    void rrIsInTenthsOfALeadAndStaysInForce() {
        // rr = 05: half a lead, 0.75 mm; the second G76 has no first block and keeps it
        Run r = Run.of("fanuc", START + "G76 P010560 Q50 R0\n" + THREAD + THREAD + "M30\n");
        assertEquals("", r.errors());
        List<String> c = chamfers(r);
        assertEquals(times(c.size(), "Z-0.7500 X1.5000"), c);
    }

    @Test
    void rr00AndNoFirstBlockPullStraightOut() {
        Run none = Run.of("fanuc", START + THREAD + "M30\n");
        assertEquals("", none.errors());
        assertEquals(times(chamfers(none).size(), "square"), chamfers(none));
        Run zero = Run.of("fanuc", START + "G76 P010060 Q50 R0\n" + THREAD + "M30\n");
        assertEquals("", zero.errors());
        assertEquals(times(chamfers(zero).size(), "square"), chamfers(zero));
    }

    @Test
    void g92IsNotChamferedByTheG76rr() {
        // a Fanuc G92 chamfers only on the machine's chamfer signal (CDZ), which no program word sets
        Run r = Run.of("fanuc", START + "G76 P011060 Q50 R0\nG92 X23. Z-25. F1.5\nX22.5\nG00 X40.\nM30\n");
        assertEquals("", r.errors());
        assertEquals(List.of("square", "square"), chamfers(r));
    }

    @Test
    void theChamferAngleIsTheMachinesParameter5131() {
        // thread.chamfer_angle = 30: 1.5 x tan 30 = 0.8660 out (radius), 1.7321 on the diameter
        Run r = Run.of(fanucWith("thread.chamfer_angle = 30"), START + "G76 P011060 Q50 R0\n" + THREAD + "M30\n",
                Checker.ERROR_CAP);
        assertEquals("", r.errors());
        assertEquals(times(chamfers(r).size(), "Z-1.5000 X1.7321"), chamfers(r));
    }

    @Test
    void aChamferLongerThanThePassIsE240() {
        // rr = 99: 9.9 leads, 14.85 mm, on a 7 mm pass (Z5. to Z-2.)
        assertEquals("6:1:E240, 6:1:E199",
                Run.of("fanuc", START + "G76 P019960 Q50 R0\nG76 X22.16 Z-2. P920 Q350 F1.5\nM30\n").errors());
        // at the manual's own example (rr = 10) it fits
        assertEquals("", Run.of("fanuc", START + "G76 P011060 Q50 R0\nG76 X22.16 Z-2. P920 Q350 F1.5\nM30\n").errors());
    }

    /** The fanuc profile with {@code line} added. */
    private static MachineProfile fanucWith(String line) {
        try {
            String text = java.nio.file.Files.readString(java.nio.file.Path.of("tables/machines/fanuc.machine"));
            return gcnc.machine.ProfileLoader.read(gcnc.machine.ProfileFile.parse("fanuc-variant.machine",
                    text + "\n" + line + "\n"), Run.TABLES, gcnc.tables.TableSource.builtIn(), null);
        } catch (java.io.IOException | gcnc.tables.TableException e) {
            throw new AssertionError(e);
        }
    }
}
