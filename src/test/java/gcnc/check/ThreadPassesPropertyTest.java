package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.check.cycle.ThreadPasses;
import gcnc.galil.Dialect;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.ProgramFrame;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Random G76 threads, Fanuc two-block and Haas one-block, outside and in a bore, with random
 * lead, height, first depth, minimum depth, allowance and finishing passes: the depths of the
 * thread passes the checker makes (read back from the passes' X, not from the planner) grow pass
 * after pass (strictly while roughing; the finishing passes stay at the height), the last reaches
 * the thread height exactly, and no pass cuts deeper than the height. And random G92 and G76 under
 * Haas M23, whose passes end with a chamfered pull-out, simulate clean. Seeds print on failure.
 */
class ThreadPassesPropertyTest {
    private static final int PROGRAMS = 80;
    /** Six-decimal words and the radius/diameter round trip, mm. */
    private static final double EXACT = 1e-6;

    @Test
    void g76PassesDeepenToTheHeightAndNeverPastIt() {
        for (int seed = 1; seed <= PROGRAMS; seed++) {
            Random r = new Random(seed * 104729L);
            boolean haas = r.nextBoolean();
            boolean outside = r.nextInt(4) != 0;
            double lead = 0.5 + r.nextInt(8) * 0.25;
            double height = round(lead * (0.3 + 0.35 * r.nextDouble()), 3);
            double first = round(height * (0.1 + 0.5 * r.nextDouble()), 3);
            double minimum = haas ? 0 : r.nextInt(3) * 0.05;
            double allowance = haas ? 0 : round(r.nextInt(3) * 0.02 * Math.min(1, height), 3);
            int finishes = haas ? 0 : 1 + r.nextInt(3);
            double major = 20 + r.nextInt(20);
            double root = outside ? major - 2 * height : major + 2 * height;
            double start = outside ? major + 4 : root - 4;
            String call;
            if (haas) {
                call = String.format(Locale.ROOT, "G76 X%.4f Z-20. K%.4f D%.4f F%.4f\n", root, height, first, lead);
            } else {
                call = String.format(Locale.ROOT, "G76 P%02d0060 Q%d R%.3f\nG76 X%.4f Z-20. P%d Q%d F%.4f\n", finishes,
                        Math.round(minimum * 1000), allowance, root, Math.round(height * 1000),
                        Math.round(first * 1000), lead);
            }
            String program = String.format(Locale.ROOT, "G21 G99\nT0707\nG97 S300 M03\nG00 X%.4f Z5." + (haas ? " M24" : "") + "\n", start) + call
                    + "M30\n";
            String why = "seed " + seed + "\n" + program;
            Run run = Run.of(haas ? "haas" : "fanuc", program);
            assertEquals("", run.errors(), why);
            // outside, X is the root and the depth runs down from the major diameter; in a bore X is the
            // root and the depth runs up from the minor diameter (here "major", the bore)
            List<Double> depths = new ArrayList<>();
            for (CheckedBlock b : run.blocks) {
                for (Motion m : b.motions()) {
                    if (m instanceof Motion.Thread t) {
                        ProgramFrame f = b.frame();
                        double x = (t.to().x() - f.origin().x()) / f.perX(); // a diameter
                        depths.add(outside ? (major - x) / 2 : (x - major) / 2);
                    }
                }
            }
            assertTrue(!depths.isEmpty(), why);
            int roughing = depths.size() - finishes;
            for (int i = 0; i < depths.size(); i++) {
                double d = depths.get(i);
                assertTrue(d > 0 && d <= height + EXACT, why + "pass " + (i + 1) + " cuts " + d + " (height " + height + ")");
                if (i > 0 && i < roughing) {
                    assertTrue(d > depths.get(i - 1), why + "pass " + (i + 1) + " at " + d + " is not deeper than the one before");
                } else if (i > 0) {
                    assertEquals(height, d, EXACT, why + "finishing pass " + (i + 1));
                }
            }
            assertEquals(height, depths.get(depths.size() - 1), EXACT, why);
        }
    }

    /**
     * Random G92 passes and Haas one-block G76s on the haas machine under M23 (on at power-up), with
     * a random chamfer in the profile (0.5 to 2 leads, 30 to 60 degrees), outside a bar of the
     * thread's major diameter: every pass ends with its chamfer (one straight geared part along the
     * pass's line, then Z going on for leads x lead while X moves out tan(angle) times as far), and
     * the whole program compiles and simulates without a finding (no E305 rapid into the stock,
     * E315 holder, E317 lead, E308 path...), by the compile's simulation and by a replay of its DMC
     * alone.
     */
    @Test
    void chamferedG92AndG76PassesUnderM23SimulateClean() throws Exception {
        for (int seed = 1; seed <= CHAMFERED_PROGRAMS; seed++) {
            Random r = new Random(seed * 7919L);
            double leads = 0.5 + r.nextInt(7) * 0.25;
            int angle = 30 + 5 * r.nextInt(7);
            double lead = 0.75 + r.nextInt(8) * 0.25;
            double height = round(lead * (0.45 + 0.15 * r.nextDouble()), 3);
            double major = 16 + r.nextInt(20);
            double root = major - 2 * height;
            double end = -(10 + r.nextInt(20));
            double start = major + 1 + r.nextInt(4);
            StringBuilder program = new StringBuilder(String.format(Locale.ROOT,
                    "(80.00 %.2f)\nG21 G99\nT303\nG97 S%d M03\nG00 X%.4f Z5. M08\n", major, 300 + 100 * r.nextInt(6),
                    start));
            if (r.nextBoolean()) {
                program.append(String.format(Locale.ROOT, "G76 X%.4f Z%.1f K%.4f D%.4f F%.4f\n", root, end, height,
                        round(height * (0.15 + 0.3 * r.nextDouble()), 3), lead));
            } else {
                int passes = 2 + r.nextInt(4);
                for (int i = 1; i <= passes; i++) {
                    double x = major - 2 * height * Math.sqrt((double) i / passes);
                    program.append(i == 1 ? String.format(Locale.ROOT, "G92 X%.4f Z%.1f F%.4f\n", x, end, lead)
                            : String.format(Locale.ROOT, "X%.4f\n", x));
                }
            }
            program.append("G00 X100. Z100. M09\nM30\n");
            gcnc.machine.MachineProfile haas = ThreadErrorsTest.haasWith("thread.chamfer_leads = 1.0",
                    "thread.chamfer_leads = " + leads, "thread.chamfer_angle = 45", "thread.chamfer_angle = " + angle);
            String why = "seed " + seed + " (" + leads + " leads at " + angle + " degrees)\n" + program;
            Run run = Run.of(haas, program.toString(), Checker.ERROR_CAP);
            assertEquals("", run.errors(), why);
            int chamfered = 0;
            for (CheckedBlock b : run.blocks) {
                for (Motion m : b.motions()) {
                    if (m instanceof Motion.Thread t) {
                        ProgramFrame f = b.frame();
                        assertTrue(t.chamfered(), why);
                        assertEquals(leads * lead, (t.chamferStart().z() - t.to().z()) / f.perZ(), EXACT, why);
                        assertEquals(2 * leads * lead * Math.tan(Math.toRadians(angle)),
                                (t.to().x() - t.chamferStart().x()) / f.perX(), EXACT, why);
                        assertEquals(t.from().x(), t.chamferStart().x(), 1e-6, why); // no taper: along the pass's X
                        chamfered++;
                    }
                }
            }
            assertTrue(chamfered >= 2, why);
            StringBuilder dmc = new StringBuilder();
            gcnc.Compiler.Result compiled = gcnc.Compiler.compile(new java.io.StringReader(program.toString()),
                    new gcnc.Compiler.Settings(Run.TABLES, haas, Dialect.Kind.GALIL,
                            java.util.Optional.of(gcnc.sim.SimOptions.defaults()), false),
                    l -> dmc.append(l.text()).append('\n'));
            assertTrue(compiled.ok(), why + compiled.diagnostics().sorted());
            assertEquals(0, compiled.simulation().orElseThrow().findings(), why + compiled.diagnostics().sorted());
            gcnc.diag.Diagnostics replayed = new gcnc.diag.Diagnostics();
            gcnc.sim.DmcReplay.replay(new java.io.BufferedReader(new java.io.StringReader(dmc.toString())), haas,
                    gcnc.sim.SimOptions.defaults(), replayed);
            assertEquals("[]", replayed.sorted().toString(), why);
        }
    }

    private static final int CHAMFERED_PROGRAMS = 40;

    @Test
    void thePlannerAloneKeepsTheSameRules() {
        Random r = new Random(7);
        for (int i = 0; i < 2000; i++) {
            double height = 0.05 + r.nextDouble() * 3;
            double first = height * (0.01 + r.nextDouble());
            double minimum = r.nextBoolean() ? 0 : r.nextDouble() * height / 5;
            int finishes = r.nextInt(4);
            double allowance = finishes == 0 ? 0 : r.nextDouble() * height * 0.5;
            ThreadPasses.Infeed infeed = r.nextBoolean() ? ThreadPasses.Infeed.CONSTANT_AREA
                    : ThreadPasses.Infeed.CONSTANT_DEPTH;
            double[] d = ThreadPasses.depths(height, first, minimum, allowance, finishes, infeed, 100_000);
            String why = height + " " + first + " " + minimum + " " + allowance + " " + finishes + " " + infeed;
            assertNotNull(d, why);
            assertEquals(Double.valueOf(height), Double.valueOf(d[d.length - 1]), why);
            for (int k = 0; k < d.length; k++) {
                assertTrue(d[k] > 0 && d[k] <= height, why);
                if (k > 0 && k < d.length - finishes) {
                    assertTrue(d[k] > d[k - 1], why + " pass " + k);
                    assertTrue(d[k] - d[k - 1] >= Math.min(minimum, height - allowance - d[k - 1]) - 1e-12, why);
                }
            }
            assertTrue(d.length >= finishes + 1, why);
            assertTrue(ThreadPasses.depths(height, first, minimum, allowance, finishes, infeed, d.length - 1) == null, why);
        }
    }

    private static double round(double v, int decimals) {
        double p = Math.pow(10, decimals);
        return Math.max(1 / p, Math.round(v * p) / p);
    }
}
