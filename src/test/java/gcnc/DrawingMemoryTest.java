package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.Writer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Issue 35 item 4: {@code simulate --svg} in bounded memory. A long roughing program (its passes
 * a thousandth of a millimetre apart, so that no two are the same polyline) is drawn by the
 * command line in a JVM of its own with a 64 MiB heap: the drawing holds at most 2^18 path
 * points (gcnc.sim.PathRecorder.MOST_POINTS), so the SVG has at most that many points in at most
 * half as many polylines, where before it had a polyline per block (300,000 of them here, and
 * 1,000,249 for a million blocks). {@code gradle junitPlatformTest -PdrawingBlocks=5000000}
 * draws a program of that many blocks instead. And a SIGTERM during a drawing ends the run at
 * once and leaves no file at the drawing's name.
 */
class DrawingMemoryTest {
    /** The drawing's budget of path points (PathRecorder.MOST_POINTS). */
    private static final int MOST_POINTS = 1 << 18;
    private static Path dir;
    private static Path program;
    private static int blocks;

    @BeforeAll
    static void write() throws IOException {
        dir = Files.createTempDirectory("gcnc-drawing");
        blocks = Integer.getInteger("gcnc.drawing.blocks", 300_000);
        program = dir.resolve("long.nc");
        try (Writer w = Files.newBufferedWriter(program)) {
            w.write("O2000\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1200 M03\nG00 X52. Z2.\n");
            int written = 7;
            double d = 50;
            while (written + 5 + 3 <= blocks) {
                // one roughing pass (as bench/gen_program.py writes them), each 0.001 mm below the last
                w.write(String.format(Locale.ROOT, "G00 X%.3f Z2.\nG01 Z-40.5 F120.\nG02 X%.3f Z-41.5 R1.\n"
                        + "G01 X%.3f\nG00 Z2.\n", d, d + 2, d + 4));
                written += 5;
                d = d > 21 ? d - 0.001 : 50;
            }
            w.write("G00 X60. Z5.\nM05\nM30\n");
        }
    }

    @AfterAll
    static void remove() throws IOException {
        try (java.util.stream.Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }

    private static ProcessBuilder gcnc(Path out, String... args) {
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx64m", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "gcnc.cli.Main"));
        command.addAll(List.of(args));
        return new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(out.toFile());
    }

    @Test
    void aLongProgramIsDrawnInBoundedMemoryAndSize() throws Exception {
        Path svg = dir.resolve("long.svg");
        Path out = dir.resolve("draw.txt");
        Process p = gcnc(out, "simulate", program.toString(), "--svg", svg.toString()).start();
        // a guard so that a regression fails instead of hanging the build; not a measure of speed
        assertTrue(p.waitFor(15, TimeUnit.MINUTES), "the drawing did not end");
        String said = Files.readString(out);
        assertFalse(said.contains("OutOfMemoryError") || said.contains("\tat "), said);
        assertEquals(0, p.exitValue(), said);
        assertTrue(said.contains("drawing: " + svg), said);
        String text = Files.readString(svg);
        assertTrue(text.contains("; path drawn to "), "the drawing says its path was compacted");
        int polylines = text.split("<polyline ", -1).length - 1;
        int points = 0;
        for (String part : text.split("points=\"")) {
            if (part.startsWith("<svg")) {
                continue;
            }
            String pts = part.substring(0, part.indexOf('"')).trim();
            points += pts.isEmpty() ? 0 : pts.split(" ").length;
        }
        // every pass's rapid and feed were a polyline each: 2 per pass, 5 blocks a pass
        assertTrue(polylines <= MOST_POINTS / 2, polylines + " polylines");
        // the path's points, and the few of the part, the blank, chuck and tool outlines
        assertTrue(points <= MOST_POINTS + 10_000, points + " points");
        assertTrue(polylines > 2, "the path is drawn: " + polylines);
        // a point is at most 15 bytes ("123.45,678.90 "), a polyline's element about 100
        assertTrue(text.length() < MOST_POINTS * 15L + MOST_POINTS / 2 * 100L + 1_000_000, text.length() + " bytes");
    }

    @Test
    void aSigtermEndsADrawingAndLeavesNoFile() throws Exception {
        Path svg = dir.resolve("stopped.svg");
        List<String> command = new ArrayList<>(gcnc(dir.resolve("unused.txt"), "simulate", program.toString(),
                "--svg", svg.toString(), "--trace").command());
        // with --trace it says where it is as it goes, on a pipe read here: the signal comes once it
        // has said 100,000 bytes of it, that is once it is simulating (a blocking read, no polling)
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        java.util.concurrent.CountDownLatch simulating = new java.util.concurrent.CountDownLatch(1);
        Thread reader = new Thread(() -> {
            byte[] buffer = new byte[8192];
            long said = 0;
            try (java.io.InputStream in = p.getInputStream()) {
                for (int n; (n = in.read(buffer)) >= 0; ) {
                    said += n;
                    if (said >= 100_000) {
                        simulating.countDown();
                    }
                }
            } catch (IOException ended) {
                // the pipe closes with the process
            }
        }, "drawing-trace-reader");
        reader.setDaemon(true);
        reader.start();
        try {
            assertTrue(simulating.await(5, TimeUnit.MINUTES) && p.isAlive(), "still simulating when the signal comes");
            long signalled = System.nanoTime();
            p.destroy(); // SIGTERM
            // measured at 0.1 s; a generous guard on a loaded machine, where it was 15 s with the heap full
            assertTrue(p.waitFor(10, TimeUnit.SECONDS), "SIGTERM did not end the run");
            long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - signalled);
            assertEquals(143, p.exitValue(), "ended by the signal (128 + 15), after " + tookMs + " ms");
        } finally {
            p.destroyForcibly();
        }
        assertFalse(Files.exists(svg), "no drawing at its name");
        try (java.util.stream.Stream<Path> s = Files.list(dir)) {
            List<Path> left = s.filter(f -> f.getFileName().toString().contains("stopped.svg")).toList();
            assertEquals(List.of(), left, "no part-written file left");
        }
    }
}
