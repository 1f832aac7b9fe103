package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Issue 35 item 4: SIGTERM ends any command at once, with nothing at an output's name and no
 * part-written file. Each command reads a long program from a named pipe in a JVM of its own; a
 * write to the pipe returns only once the command has read what was before it (the pipe holds
 * 64 KiB), so after 600 KB written the command is busy in the middle of the program when the signal
 * comes: no polling, no sleep. {@link DrawingMemoryTest} signals a drawing while it simulates,
 * {@code AtomicPairTest} a compile waiting on its input.
 */
class SigtermTest {
    private Path dir;

    @BeforeEach
    void dir() throws IOException {
        dir = Files.createTempDirectory("gcnc-sigterm");
    }

    @AfterEach
    void remove() throws IOException {
        try (java.util.stream.Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }

    /** Runs {@code gcnc ARGS PROGRAM-ON-A-PIPE}, signals it after 600 KB of program, and returns what is left in dir. */
    private List<String> signalled(String... args) throws Exception {
        Path fifo = TestFiles.mkfifo(dir.resolve("long.nc"));
        Path log = dir.resolve("said.txt");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx64m", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "gcnc.cli.Main"));
        command.addAll(List.of(args));
        command.add(fifo.toString());
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        // were gcnc to end without opening the pipe, opening our end would wait for ever: then open
        // and close a reader's end (read-write, which on Linux never waits) to free it
        // (only while our end is not open: afterwards the callback, running late, would create a
        // plain file at the pipe's name after the test had removed the folder's files)
        java.util.concurrent.atomic.AtomicBoolean opened = new java.util.concurrent.atomic.AtomicBoolean();
        p.onExit().thenRun(() -> {
            if (opened.get()) {
                return;
            }
            try (java.io.RandomAccessFile unblock = new java.io.RandomAccessFile(fifo.toFile(), "rw")) {
                // nothing to read
            } catch (IOException gone) {
                // the pipe is removed already
            }
        });
        long signalled = 0;
        boolean ended = false;
        OutputStream program = null;
        try {
            program = Files.newOutputStream(fifo); // opens once gcnc opens its end
            opened.set(true);
            program.write("O2000\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1200 M03\nG00 X52. Z2.\n"
                    .getBytes(StandardCharsets.US_ASCII));
            long written = 0;
            double d = 50;
            while (written < 600_000) {
                byte[] pass = String.format(Locale.ROOT, "G00 X%.3f Z2.\nG01 Z-40.5 F120.\nG02 X%.3f Z-41.5 R1.\n"
                        + "G01 X%.3f\nG00 Z2.\n", d, d + 2, d + 4).getBytes(StandardCharsets.US_ASCII);
                program.write(pass);
                written += pass.length;
                d = d > 21 ? d - 0.001 : 50;
            }
            signalled = System.nanoTime();
            p.destroy(); // SIGTERM
            // the pipe stays open until gcnc has gone: closed now, gcnc would read the end of its
            // program and could finish the check (E052) before the signal's exit
            ended = p.waitFor(10, TimeUnit.SECONDS);
        } catch (IOException brokenPipe) {
            // gcnc went before the signal: the exit status below says how
        } finally {
            if (program != null) {
                try {
                    program.close();
                } catch (IOException brokenPipe) {
                    // gcnc has gone
                }
            }
        }
        try {
            // measured well under a second; a generous guard on a loaded machine
            assertTrue(ended || p.waitFor(10, TimeUnit.SECONDS), String.join(" ", args) + ": SIGTERM did not end the run");
            long tookMs = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - signalled);
            assertTrue(signalled != 0, String.join(" ", args) + " ended before the signal: " + Files.readString(log));
            assertEquals(143, p.exitValue(), String.join(" ", args) + " ended by the signal (128 + 15) after " + tookMs
                    + " ms: " + Files.readString(log));
        } finally {
            p.destroyForcibly();
        }
        List<String> left = new ArrayList<>();
        try (java.util.stream.Stream<Path> s = Files.list(dir)) {
            s.map(f -> f.getFileName().toString()).filter(n -> !n.equals("long.nc") && !n.equals("said.txt")).forEach(left::add);
        }
        return left;
    }

    @Test
    void aSigtermEndsACheck() throws Exception {
        assertEquals(List.of(), signalled("check"));
    }

    @Test
    void aSigtermEndsACompileAndLeavesNoOutput() throws Exception {
        assertEquals(List.of(), signalled("compile", "-o", dir.resolve("long.dmc").toString()), "no .dmc, .map or .part");
    }

    @Test
    void aSigtermEndsADrawingAndLeavesNoOutput() throws Exception {
        assertEquals(List.of(), signalled("simulate", "--svg", dir.resolve("long.svg").toString()), "no .svg or .part");
    }
}
