package gcnc.plan;

import static gcnc.plan.ContouringTest.compile;
import static gcnc.plan.ContouringTest.profile;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Locale;
import org.junit.jupiter.api.Test;

/**
 * The planner's windows do not show in the path (issue 33 item 3): it hands on {@link Contouring#WINDOW}
 * pieces at a time, each join planned to a speed the pieces still held can stop from, so the speed at a
 * join is what the junction and the acceleration allow, as anywhere else in the sequence. The same
 * contour with the windows falling elsewhere (its lead-in cut into more collinear pieces: the same path,
 * the joins moved along it) runs in the same time, and the replay checks every corner (E332, E333).
 */
class WindowJoinTest {
    /** A 1,500-chord contour with sharp corners among the chords; its lead-in in {@code leadIn} collinear pieces. */
    static String contour(int leadIn) {
        StringBuilder b = new StringBuilder("G21 G18 G40 G99\nT0101\nG97 S1200 M03\nG00 X48. Z1.\nG01 F0.2\n");
        for (int k = 1; k <= leadIn; k++) {
            b.append(String.format(Locale.ROOT, "Z%.4f%n", 1 - k / (double) leadIn));
        }
        for (int k = 1; k <= 1500; k++) {
            // a wave with a step every 200 chords: a corner the junction slows
            double x = 46 + Math.sin(k / 40.0) + (k / 200) * 0.05;
            b.append(String.format(Locale.ROOT, "X%.3f Z%.3f%n", x, -k * 0.05));
        }
        return b.append("G00 X60.\nZ5.\nM05\nM30\n").toString();
    }

    /** The written chords (VP with their speeds) of the feed sequence: its last 1,500 segments. */
    static java.util.List<String> chords(ContouringTest.Out o) {
        java.util.List<String> vps = new java.util.ArrayList<>();
        for (gcnc.dmc.Instruction i : o.instructions()) {
            if (i.command() instanceof gcnc.dmc.Command.VectorSpeed && vps.size() > 1500) {
                break; // (the feed sequence read: the retract's follows)
            }
            if (i.command() instanceof gcnc.dmc.Command.VectorSpeed) {
                vps.clear();
            } else if (i.command() instanceof gcnc.dmc.Command.VectorPosition) {
                vps.add(i.text());
            }
        }
        assertTrue(vps.size() > 1500, vps.size() + " segments");
        return vps.subList(vps.size() - 1500, vps.size());
    }

    @Test
    void aLongContoursCycleTimeDoesNotDependOnWhereTheWindowsFall() throws Exception {
        var haas = profile("haas");
        ContouringTest.Out one = compile(contour(1), haas);
        double t = one.result().simulation().orElseThrow().cycleSeconds();
        assertEquals(java.util.List.of("rapid-feed", "rapid-feed", "output"), one.stops());
        for (int leadIn : new int[] {2, 37, Contouring.WINDOW / 2, Contouring.WINDOW - 1}) {
            ContouringTest.Out o = compile(contour(leadIn), haas);
            var sim = o.result().simulation().orElseThrow();
            assertEquals(0, sim.findings(), "the replay's corner checks (E332, E333) at every join");
            assertEquals(one.stops(), o.stops());
            // the joins move by leadIn - 1 pieces; a collinear joint costs nothing, a join nothing either
            assertEquals(t, sim.cycleSeconds(), 0.002, "lead-in in " + leadIn + " pieces");
            // every chord is written with the same speeds wherever the joins fall
            java.util.List<String> a = chords(one);
            java.util.List<String> b = chords(o);
            for (int k = 0; k < a.size(); k++) {
                assertEquals(a.get(k), b.get(k), "chord " + (k + 1) + ", lead-in in " + leadIn + " pieces");
            }
        }
        // and the blended path is faster than stopping at every chord
        assertTrue(t < one.result().simulation().orElseThrow().exactStopSeconds() * 0.95);
    }
}
