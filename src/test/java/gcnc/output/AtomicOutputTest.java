package gcnc.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The output file holds exactly the lines written, across buffer ends and in any script, or nothing. */
class AtomicOutputTest {
    private final Path dir;

    AtomicOutputTest() throws java.io.IOException {
        dir = Files.createTempDirectory("gcnc-out");
        dir.toFile().deleteOnExit();
    }

    @Test
    void linesOfEveryLengthAndScriptComeOutExactly() throws Exception {
        Random rnd = new Random(3);
        String[] pieces = {"VP 1000,-2000", "NO L12", "NO año 2004", "é", "ñ (Spanish)", "€", "x".repeat(70_000), "", "CR 2100,87,8.2"};
        StringBuilder expected = new StringBuilder();
        Path target = dir.resolve("out.dmc");
        try (AtomicOutput out = new AtomicOutput(target)) {
            for (int i = 0; i < 1_000; i++) {
                String line = pieces[rnd.nextInt(pieces.length)] + (rnd.nextBoolean() ? pieces[rnd.nextInt(3)] : "");
                out.line(line);
                expected.append(line).append('\n');
            }
            out.commit();
        }
        assertEquals(expected.toString(), Files.readString(target, StandardCharsets.UTF_8));
        Files.delete(target);
    }

    @Test
    void withoutCommitNothingIsLeft() throws Exception {
        Path target = dir.resolve("out.dmc");
        try (AtomicOutput out = new AtomicOutput(target)) {
            for (int i = 0; i < 100_000; i++) {
                out.line("VP 1000,-2000");
            }
        }
        assertFalse(Files.exists(target));
        try (var files = Files.list(dir)) {
            assertEquals(0, files.count(), "no temporary file left behind");
        }
    }

    /** A full disk: lines after the failure are dropped quietly, commit reports it, nothing is left. */
    @Test
    void aFullDiskFailsTheCommitNotTheLinesAndLeavesNothing() throws Exception {
        Path target = dir.resolve("full.dmc");
        Files.writeString(target, "the previous output\n");
        AtomicOutput.Opener fullAfter100k = temp -> new java.io.FilterOutputStream(Files.newOutputStream(temp)) {
            private long written;

            @Override
            public void write(byte[] b, int off, int len) throws java.io.IOException {
                if (written + len > 100_000) {
                    throw new java.io.IOException("No space left on device");
                }
                written += len;
                out.write(b, off, len);
            }
        };
        try (AtomicOutput out = new AtomicOutput(target, fullAfter100k)) {
            for (int i = 0; i < 100_000; i++) {
                out.line("VP 1000,-2000");
            }
            java.io.IOException e = assertThrows(java.io.IOException.class, out::commit);
            assertEquals("No space left on device", e.getMessage());
        }
        assertEquals("the previous output\n", Files.readString(target), "the old output stays whole");
        Files.delete(target);
        try (var files = Files.list(dir)) {
            assertEquals(0, files.count(), "no temporary file left behind");
        }
    }

    /** A map entry's two numbers are written as a String of them would be, whatever their sign and size. */
    @Test
    void twoNumbersAreWrittenAsTheirText() throws Exception {
        Path target = Files.createTempDirectory("gcnc-atomic").resolve("part.dmc.map");
        long[][] pairs = {{1, 0}, {0, 7}, {10, 200}, {-5, 3}, {Long.MAX_VALUE, Long.MIN_VALUE}, {123456789, -1}};
        StringBuilder expected = new StringBuilder();
        try (AtomicOutput out = new AtomicOutput(target)) {
            for (long[] p : pairs) {
                out.line(p[0], p[1]);
                expected.append(p[0]).append(' ').append(p[1]).append('\n');
            }
            out.commit();
        }
        assertEquals(expected.toString(), Files.readString(target));
    }
}
