package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The simulator's cost stays near-linear in the moves whatever they hit (issue 18): a stock made
 * ragged by thousands of rapids into the blank, each leaving its own notch, and a groove deepened
 * 0.0001 in at a time. Never timed: the polygon work is counted ({@link Stock#work}), and whole
 * runs go through the command line in a JVM of bounded heap.
 */
class SimCostTest {
    /** A 60 degree V tip, 0.8 mm wide and 2 mm tall, relative to its tip (mm). */
    private static final double[] TZ = {-0.4, 0.4, 0};
    private static final double[] TR = {2, 2, 0};

    /**
     * n rapids, each plunging 0.03 mm further along and 0.004 mm deeper than the last: every one
     * reaches into the blank (E305's test: the overlap, less half the depth, is not empty) and each
     * leaves its notch's corners in the stock. Returns the polygon work.
     */
    private static long plunges(int n) {
        Stock s = new Stock(0, 150, 25);
        double[][] in = Hull.smaller(TZ, TR);
        int deep = 0;
        for (int i = 0; i < n; i++) {
            double z = 5 + i * 0.03;
            double r = 24 - i * 0.004;
            Stock.Sweep sweep = new Stock.Sweep(Hull.sweep(TZ, TR, z, 30, z, r), Hull.sweep(in[0], in[1], z, 30, z, r));
            List<Stock.Sweep> biting = s.biting(List.of(sweep));
            if (!biting.isEmpty() && s.deepOverlap(biting) != null) {
                deep++;
            }
            s.cut(sweep.full());
        }
        assertEquals(n, deep, "every plunge reaches into material not yet cut");
        assertTrue(s.corners() > n, "the notches stay in the stock: it is ragged");
        assertTrue(s.envelopePieces() <= 8 * n + 8, "the envelope holds a few pieces per notch: " + s.envelopePieces());
        return s.work();
    }

    @Test
    void aRaggedStockCostsLinearlyInTheMoves() {
        long w1 = plunges(1000);
        long w2 = plunges(2000);
        long w4 = plunges(4000);
        // whole-polygon booleans would make each doubling cost four times as much
        assertTrue(w2 < 2.5 * w1, "1000 -> 2000 plunges: " + w1 + " -> " + w2);
        assertTrue(w4 < 2.5 * w2, "2000 -> 4000 plunges: " + w2 + " -> " + w4);
    }

    /**
     * The 11-line Haas G75 whose peck lost its point (I01 = 0.0001 in: 5000 pecks, 50,000 DMC
     * lines) compiles in a 64 MiB heap, with its two real findings and the warning at the I word.
     */
    @Test
    void aPeckWithoutItsPointIsWarnedAndReplayedInBoundedMemory() throws Exception {
        Path nc = Path.of("src/test/resources/gcnc/sim/cost/g75-peck-no-point.nc");
        Path out = Files.createTempDirectory("gcnc-cost").resolve("g75.dmc");
        Run r = gcnc("-Xmx64m", "compile", nc.toString(), "--machine", "haas", "-o", out.toString());
        assertEquals(1, r.status(), r.err());
        assertTrue(r.err().contains(":8:18: warning[E330]: G75: I01 makes 5000 pecks from one block (more than 1000)"),
                r.err());
        assertEquals(2, r.err().lines().filter(l -> l.contains("error[E305]")).count(), r.err());
        assertFalse(r.err().contains("Exception") || r.err().contains("Error:"), r.err());
        assertFalse(Files.exists(out));
    }

    /** 2000 rapids into the blank, each one E305, in a 64 MiB heap. */
    @Test
    void twoThousandRapidsIntoTheBlankRunInBoundedMemory() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-cost");
        Path nc = dir.resolve("rapids.nc");
        StringBuilder b = new StringBuilder("%\nO1002\nG21 G18 G40 G54 G80 G99\nT0303\nG97 S1000 M03\nG00 X60. Z2.\n");
        int n = 2000;
        for (int i = 0; i < n; i++) {
            b.append(String.format(java.util.Locale.ROOT, "G00 Z%.3f\nX%.3f\nX60.\n", -5.0 - i * 0.03, 50.0 - i * 0.004));
        }
        b.append("G00 Z5.\nM30\n%\n");
        Files.writeString(nc, b);
        Run r = gcnc("-Xmx64m", "compile", nc.toString(), "--machine", "haas", "-o", dir.resolve("r.dmc").toString());
        assertEquals(1, r.status(), r.err());
        assertEquals(n, r.err().lines().filter(l -> l.contains("error[E305]")).count());
        assertFalse(r.err().contains("Exception") || r.err().contains("Error:"), r.err());
    }

    record Run(int status, String err) {
    }

    /** gcnc in a JVM of its own, with the heap limit given first. */
    static Run gcnc(String heap, String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                heap, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "gcnc.cli.Main"));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectOutput(ProcessBuilder.Redirect.DISCARD)
                .redirectError(ProcessBuilder.Redirect.PIPE).start();
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(10, TimeUnit.MINUTES));
        return new Run(p.exitValue(), err);
    }
}
