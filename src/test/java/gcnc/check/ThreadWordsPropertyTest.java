package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.galil.Dialect;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The thread words the Fusion posts write, as properties over random threads (docs/threading.md):
 * a Fanuc two-block G76 with a random chamfer rr ends every pass with rr/10 leads at 45 degrees;
 * a Haas G76 with a random infeed P1-P4 and tool angle never passes the programmed end; two starts
 * (Q0 and Q180000) on G92 or the Haas G76 give every pass its start angle. Each program compiles
 * and simulates without a finding over a bar of the thread's major diameter. Seeds print on failure.
 */
class ThreadWordsPropertyTest {
    private static final int PROGRAMS = 25;

    private static double round(double v, int places) {
        double f = Math.pow(10, places);
        return Math.round(v * f) / f;
    }

    /** Compiles and simulates {@code program} on {@code p}: no error, no simulator finding. */
    private static void simulatesClean(MachineProfile p, String program, String why) {
        gcnc.Compiler.Result compiled;
        try {
            compiled = gcnc.Compiler.compile(new java.io.StringReader(program),
                    new gcnc.Compiler.Settings(Run.TABLES, p, Dialect.Kind.GALIL, java.util.Optional.of(gcnc.sim.SimOptions.defaults()),
                            false), l -> { });
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
        assertTrue(compiled.ok(), why + compiled.diagnostics().sorted());
        assertEquals(0, compiled.simulation().orElseThrow().findings(), why + compiled.diagnostics().sorted());
    }

    @Test
    void fanucG76rrChamfersEveryPassAndSimulatesClean() {
        for (int seed = 1; seed <= PROGRAMS; seed++) {
            Random r = new Random(seed * 104729L);
            int rr = 1 + r.nextInt(20);
            double lead = 0.75 + r.nextInt(8) * 0.25;
            double height = round(lead * (0.45 + 0.15 * r.nextDouble()), 3);
            double major = 16 + r.nextInt(20);
            double end = -(15 + r.nextInt(20));
            String program = String.format(Locale.ROOT, "(80.00 %.2f)\nG21 G99\nT0707\nG97 S%d M03\nG00 X%.4f Z5. M08\n"
                            + "G76 P%02d%02d60 Q50 R0\nG76 X%.4f Z%.1f P%d Q%d F%.4f\nG00 X100. Z100. M09\nM30\n",
                    major, 300 + 100 * r.nextInt(6), major + 1 + r.nextInt(4), 1 + r.nextInt(2), rr, major - 2 * height,
                    end, Math.round(height * 1000), Math.round(height * (150 + r.nextInt(300))), lead);
            String why = "seed " + seed + " (rr " + rr + ")\n" + program;
            Run run = Run.of("fanuc", program);
            assertEquals("", run.errors(), why);
            int passes = 0;
            for (CheckedBlock b : run.blocks) {
                for (Motion m : b.motions()) {
                    if (m instanceof Motion.Thread t) {
                        assertTrue(t.chamfered(), why);
                        double along = (t.chamferStart().z() - t.to().z()) / b.frame().perZ();
                        assertEquals(rr / 10.0 * lead, along, 1e-6, why);
                        assertEquals(2 * along, (t.to().x() - t.chamferStart().x()) / b.frame().perX(), 1e-6, why);
                        passes++;
                    }
                }
            }
            assertTrue(passes >= 2, why);
            simulatesClean(Run.profile("fanuc"), program, why);
        }
    }

    @Test
    void haasInfeedsAndStartAnglesStayInsideTheThreadAndSimulateClean() {
        MachineProfile haas = ThreadErrorsTest.haasWith("thread.chamfer_leads = 1.0", "thread.chamfer_leads = 0");
        for (int seed = 1; seed <= PROGRAMS; seed++) {
            Random r = new Random(seed * 7717L);
            int infeed = 1 + r.nextInt(4);
            int angle = new int[] {29, 55, 60}[r.nextInt(3)];
            double lead = 0.75 + r.nextInt(8) * 0.25;
            double height = round(lead * (0.45 + 0.15 * r.nextDouble()), 3);
            double major = 16 + r.nextInt(20);
            double end = -(15 + r.nextInt(20));
            boolean g92 = r.nextBoolean();
            double first = round(height * (0.2 + 0.3 * r.nextDouble()), 3);
            StringBuilder program = new StringBuilder(String.format(Locale.ROOT,
                    "(80.00 %.2f)\nG21 G99\nT303\nG97 S%d M03\nG00 X%.4f Z5. M08\n", major, 300 + 100 * r.nextInt(6),
                    major + 1 + r.nextInt(4)));
            for (String q : new String[] {"Q0", "Q180000"}) {
                if (g92) {
                    for (int i = 1; i <= 3; i++) {
                        double x = major - 2 * height * Math.sqrt(i / 3.0);
                        program.append(i == 1 ? String.format(Locale.ROOT, "G92 X%.4f Z%.1f %s F%.4f\n", x, end, q, lead)
                                : String.format(Locale.ROOT, "X%.4f\n", x));
                    }
                } else {
                    program.append(String.format(Locale.ROOT, "G76 X%.4f Z%.1f K%.4f D%.4f A%d. P%d %s F%.4f\n",
                            major - 2 * height, end, height, first, angle,
                            infeed, q, lead));
                }
            }
            program.append("G00 X100. Z100. M09\nM30\n");
            String why = "seed " + seed + " (" + (g92 ? "G92" : "G76 P" + infeed + " A" + angle) + ")\n" + program;
            Run run = Run.of(haas, program.toString(), Checker.ERROR_CAP);
            assertEquals("", run.errors(), why);
            int one = 0;
            int two = 0;
            for (CheckedBlock b : run.blocks) {
                for (Motion m : b.motions()) {
                    if (m instanceof Motion.Thread t) {
                        double z = (t.to().z() - b.frame().origin().z()) / b.frame().perZ();
                        assertTrue(z >= end - 1e-6, why + " a pass ends at Z" + z);
                        if (t.startAngle() == 0) {
                            one++;
                        } else {
                            assertEquals(180.0, t.startAngle(), 1e-9, why);
                            two++;
                        }
                    }
                }
            }
            assertTrue(one >= 2 && one == two, why + one + " / " + two);
            simulatesClean(haas, program.toString(), why);
        }
    }
}
