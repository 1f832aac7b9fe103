package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Issue 30, "threads in one groove": eight passes of one thread on the virtual Galil, whose MF/MR
 * trips are seen 0 to 2 servo samples late at a seeded random phase (COMALL MF: "The accuracy of
 * the MF command is the number of counts that occur in 2*TM"). With gcnc's phase correction after
 * GR (the slave's lag behind the helix from the sync point, read in one expression and added by IP,
 * COMALL IP "superimposed on top of the existing gearing motion") every pass runs on the same helix
 * within 2 counts; the program gcnc wrote before (GR straight after the MF) starts each pass
 * wherever its trip fell.
 */
class VirtualThreadPhaseTest {
    /** 600 r/min at 410 r/min a volt on a 4,096-count encoder: 40,960 counts/s, 41 a sample. */
    static final double VOLTS = 600 / 410.0;
    static final double RATIO = -0.3604;

    static final List<String> CORRECTED = List.of("#PASS", "GA C,C", "gsp=(@INT[_TPC/4096]+1)*4096", "MF ,,gsp",
            "GR -0.3604,0.0000", "gpu=(_TPC-gsp)*_GRX-(_RPX-0)", "IP gpu", "MR -8000", "GR 0,0", "PA 0,0",
            "BG XY", "AM XY", "EN");
    static final List<String> UNCORRECTED = List.of("#PASS", "GA C,C", "gsp=(@INT[_TPC/4096]+1)*4096", "MF ,,gsp",
            "GR -0.3604,0.0000", "MR -8000", "GR 0,0", "PA 0,0", "BG XY", "AM XY", "EN");

    /** Where Z (X here) stands against the helix from each pass's sync point, counts, once past 6,000 counts of the pass. */
    private static List<Double> phases(List<String> program, long seed) throws GalilException {
        VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), null, VirtualGalil.SPINDLE_RATE, seed);
        c.command("SH XYC");
        c.command("VM XY");
        c.command(String.format(java.util.Locale.ROOT, "OF ,,%.4f", VOLTS));
        c.download(String.join("\r", program), false);
        List<Double> phases = new ArrayList<>();
        for (int pass = 0; pass < 8; pass++) {
            c.advance(0.0037 * (pass + 1)); // the spindle somewhere else in its revolution each time
            c.command("XQ #PASS");
            c.advance(0.001);
            double gsp = c.variable("gsp");
            double phase = Double.NaN;
            while (c.operand("XQ0") >= 0) {
                c.advance(0.001);
                double z = c.motion.position[0];
                if (Double.isNaN(phase) && z < -6000) {
                    phase = z - c.operand("GRX") * (c.motion.position[2] - gsp);
                }
                assertTrue(c.time() < 60, "the pass ends");
            }
            assertEquals(0, c.operand("TPX"), "back at the start");
            phases.add(phase);
        }
        return phases;
    }

    private static double spread(List<Double> phases) {
        return phases.stream().mapToDouble(Double::doubleValue).max().orElseThrow()
                - phases.stream().mapToDouble(Double::doubleValue).min().orElseThrow();
    }

    @Test
    void eightCorrectedPassesStartWithinTwoCountsOfEachOther() throws GalilException {
        for (long seed : new long[] {VirtualGalil.TRIP_SEED, 1, 2, 3}) {
            List<Double> phases = phases(CORRECTED, seed);
            assertTrue(spread(phases) <= 2, "seed " + seed + ": " + phases);
            assertTrue(Math.abs(phases.get(0)) <= 2, "on the helix from the whole revolution: " + phases);
        }
    }

    @Test
    void withoutTheCorrectionThePassesStartWhereverTheTripFell() throws GalilException {
        List<Double> phases = phases(UNCORRECTED, VirtualGalil.TRIP_SEED);
        // up to 2 samples of 41 encoder counts × 0.3604 late, at random: far more than 2 counts apart
        assertTrue(spread(phases) > 5, phases.toString());
    }
}
