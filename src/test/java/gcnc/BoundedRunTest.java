package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Issue 18, "nothing crashes, nothing stalls": each reproduction (src/test/resources/limits) run by
 * the command line in a JVM of its own with a 64 MB heap, which the old code ran out of (a loop's
 * 1,249,222 identical errors, a profile or program that is /dev/zero). Each must end with its exit
 * status and its diagnostic, no stack trace, and a short report: the heap bounds the memory and the
 * report's size bounds what was printed. Nothing is asserted on time.
 */
class BoundedRunTest {
    private static final Path LIMITS = Path.of("src/test/resources/limits");
    /** The heap every run gets: far below what the old code needed for these inputs. */
    private static final String HEAP = "-Xmx64m";
    private static Path dir;

    @BeforeAll
    static void folder() throws IOException {
        dir = Files.createTempDirectory("gcnc-bounded");
    }

    @AfterAll
    static void removeFolder() throws IOException {
        try (java.util.stream.Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }

    /** What a run printed (stdout and stderr) and its exit status. */
    private record Run(int status, String output, long size) {
    }

    private static Run gcnc(String... args) throws Exception {
        return gcncIn(HEAP, args);
    }

    /** A run in a heap of {@code heap} (a -Xmx option). */
    private static Run gcncIn(String heap, String... args) throws Exception {
        Path out = Files.createTempFile(dir, "run", ".txt");
        List<String> command = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                heap, "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-cp", System.getProperty("java.class.path"), "gcnc.cli.Main"));
        command.addAll(List.of(args));
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(out.toFile()).start();
        // a guard so that a regression fails instead of hanging the build; not a measure of speed
        if (!p.waitFor(15, TimeUnit.MINUTES)) {
            p.destroyForcibly();
            throw new AssertionError("gcnc " + String.join(" ", args) + " did not end");
        }
        long size = Files.size(out);
        byte[] head = new byte[(int) Math.min(size, 1 << 16)];
        try (var in = Files.newInputStream(out)) {
            in.readNBytes(head, 0, head.length);
        }
        String text = new String(head, StandardCharsets.UTF_8);
        if (size > head.length) {
            // and the last 4 KB, where the summary is
            try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(out.toFile(), "r")) {
                byte[] tail = new byte[4096];
                f.seek(size - tail.length);
                f.readFully(tail);
                text += "\n[...]\n" + new String(tail, StandardCharsets.UTF_8);
            }
        }
        return new Run(p.exitValue(), text, size);
    }

    /** The run ended with {@code status}, printed {@code expected}, no stack trace, and a short report. */
    private static void ends(Run r, int status, String expected) {
        assertFalse(r.output().contains("Exception") || r.output().contains("OutOfMemoryError")
                || r.output().contains("\tat "), r.output());
        assertTrue(r.output().contains(expected), r.output());
        assertTrue(r.size() < 4096, "a report of " + r.size() + " bytes:\n" + r.output());
        assertEquals(status, r.status(), r.output());
    }

    private static String limits(String name) {
        return LIMITS.resolve(name).toString();
    }

    @Test
    void aLoopRepeatingOneErrorReportsItOnceInBoundedMemory() throws Exception {
        // 113 bytes: 2,000 x 2,000 passes of G01 X#24 with #24 vacant (1,249,222 errors, 2.9 GB, out of memory)
        Run r = gcnc("check", limits("loop-one-error.nc"), "--machine", "fanuc");
        ends(r, 1, "loop-one-error.nc:6:5: error[E146]: X#24 has no value");
        assertTrue(r.output().contains("loop-one-error.nc:6:5: note[E680]: the same in 1249220 passes of this block;"
                + " shown once"), r.output());
        assertEquals(1, r.output().split("E146", -1).length - 1, r.output());
    }

    @Test
    void aLoopOfManyCleanBlocksStreams() throws Exception {
        ends(gcnc("check", limits("loop-many-blocks.nc"), "--machine", "fanuc"), 0,
                "loop-many-blocks.nc: 400008 blocks, no errors");
        // translated, replayed and written (2,000,021 lines) in the same heap
        Path dmc = dir.resolve("loop-many-blocks.dmc");
        Run r = gcnc("compile", limits("loop-many-blocks.nc"), "--machine", "fanuc", "-o", dmc.toString());
        assertEquals(0, r.status(), r.output());
        assertTrue(r.output().contains("400002 segments, 0 findings"), r.output());
        // 2,000,021 lines do not fit the DMC-4040's 2,000: the stream form, a small resident program and the stream
        assertTrue(r.output().contains("resident program) and "), r.output());
        assertTrue(Files.size(dmc) < 10_000, "the resident program is small");
        assertTrue(Files.size(dir.resolve("loop-many-blocks.stream")) > 10_000_000, "the stream was written whole");
    }

    /** A program of {@code blocks} moves after {@code first} (a macro statement, or a call), then M30 and {@code after}. */
    private static Path held(String name, String first, int blocks, String after) throws IOException {
        StringBuilder p = new StringBuilder("O0185\nG21 G18 G40 G99\nT0101\nG97 S1000 M03\nG00 X52. Z2.\n" + first + "\n");
        for (int i = 0; i < blocks; i++) {
            p.append("G01 X").append(40 + i % 100 / 10.0).append(" Z-").append(i % 300 / 10.0).append(" F0.2\n");
        }
        return Files.writeString(dir.resolve(name), p.append("G00 X60.\nM30\n").append(after).toString());
    }

    @Test
    void whatTheFlowHoldsFitsTheHeap() throws Exception {
        // 150,000 blocks after a macro statement (held for GOTO and END) ran out of 64 MB; now the
        // limit is the heap's (one block per KiB: 65,536) and the rest is E137, not a crash
        Path macro = held("held-macro.nc", "#1 = 1", 150_000, "");
        Run r = gcnc("check", macro.toString(), "--machine", "fanuc");
        ends(r, 1, "error[E137]: too long to follow: gcnc holds at most");
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("holds at most (\\d+) blocks").matcher(r.output());
        assertTrue(m.find(), r.output());
        assertTrue(Integer.parseInt(m.group(1)) <= 65_536, "the limit of a 64 MB heap: " + m.group(1));
        // the same after a call: the rest of the file is read for the programs after M30
        Path call = held("held-call.nc", "M98 P1000", 150_000, "O1000\nG00 X60.\nM99\n");
        ends(gcnc("check", call.toString(), "--machine", "fanuc"), 1, "error[E137]");
    }

    @Test
    void numbersNoMacroHoldsAndDeepSignsAreLocatedErrors() throws Exception {
        ends(gcnc("check", limits("four-hundred-nines.nc"), "--machine", "fanuc"), 1,
                "four-hundred-nines.nc:5:7: error[E683]: 999999999999999999999999999999... comes to >1.8E+308");
        ends(gcnc("check", limits("ten-thousand-signs.nc"), "--machine", "fanuc"), 0, "6 blocks, no errors");
        ends(gcnc("check", limits("alarm-number.nc"), "--machine", "fanuc"), 1,
                "alarm-number.nc:3:1: error[E682]: #3000 = 1E+21: an alarm number is a whole number from 0 to 200");
    }

    @Test
    void aProfileWhoseTravelOverflowsIsRefusedAtItsLine() throws Exception {
        String profile = limits("travel-overflow.machine");
        ends(gcnc("machines", "validate", profile), 2, profile + ":23:12: error[E401]: x.travel = 1e306");
        ends(gcnc("check", limits("alarm-number.nc"), "--machine", profile), 2, profile + ":23:12: error[E401]");
    }

    @Test
    void aProfileOrTableThatIsDevZeroIsRefusedAtAStatedSize() throws Exception {
        Path profile = Files.createSymbolicLink(dir.resolve("zero.machine"), Path.of("/dev/zero"));
        ends(gcnc("machines", "validate", profile.toString()), 2,
                profile + ":1:1: error[E404]: larger than 8388608 bytes: not a table or control or profile");
        // a control's table under --tables DIR
        Path tables = dir.resolve("tables");
        TestFiles.copyTree(Path.of("tables"), tables);
        Path gCodes = tables.resolve("controls/fanuc-a/g_codes.csv");
        Files.delete(gCodes);
        Files.createSymbolicLink(gCodes, Path.of("/dev/zero"));
        ends(gcnc("check", limits("alarm-number.nc"), "--tables", tables.toString(), "--machine", "fanuc"), 2,
                gCodes + ":1:1: error[E404]");
    }

    @Test
    void aProgramThatNeverEndsIsRefusedAtTheLineLimit() throws Exception {
        // a flood of NULs without a newline: cut at the line limit, read up to the text limit, in 64 MB
        Run r = gcnc("check", "/dev/zero", "--machine", "fanuc");
        ends(r, 1, "/dev/zero:1:65537: error[E503]: line longer than 65536 characters: the rest of it is not read");
        assertTrue(r.output().contains("error[E504]: the text is longer than 1073741824 characters"), r.output());
    }

    // Issue 23's memory bounds, each in a heap far below what keeping everything would take: the
    // exit status and the diagnostic, never the time.

    /** The first 10,000 errors are kept and printed, E116 says so, the rest only counted. */
    @Test
    void aHundredThousandLexicalErrorsAreCappedInBoundedMemory() throws Exception {
        StringBuilder p = new StringBuilder("G21 G18 G40 G99\n");
        for (int i = 0; i < 100_000; i++) {
            p.append("G01 X1. $ Z-1.\n");
        }
        Path program = Files.writeString(dir.resolve("many-errors.nc"), p.append("M30\n"));
        Run r = gcncIn("-Xmx16m", "check", program.toString(), "--machine", "fanuc");
        assertFalse(r.output().contains("Exception") || r.output().contains("\tat "), r.output());
        assertTrue(r.output().startsWith(program + ":2:9: error[E003]: lexical error: illegal character '$'"), r.output());
        assertTrue(r.output().contains(program + ":10001:1: error[E116]: stopped after 10000 errors"), r.output());
        assertTrue(r.output().contains(program + ": 100002 blocks, 100001 errors"), r.output());
        // 10,000 lines of about 110 bytes (the temporary folder's name included): the report is bounded
        // by the cap, not by the program
        assertTrue(r.size() < 2_000_000, "a report of " + r.size() + " bytes");
        assertEquals(1, r.status(), r.output());
    }

    /** A line of a million characters (a transfer that lost its line ends) is cut; the next line is read. */
    @Test
    void aLineLongerThanTheLimitIsCutAndTheNextLineIsRead() throws Exception {
        Path program = Files.writeString(dir.resolve("long-line.nc"),
                "G21 G18 G40 G99\n" + "X1. ".repeat(250_000) + "\nG01 X10. Z-5. $\nM30\n");
        Run r = gcncIn("-Xmx16m", "check", program.toString(), "--machine", "fanuc");
        ends(r, 1, program + ":2:65537: error[E503]: line longer than 65536 characters: the rest of it is not read");
        assertTrue(r.output().contains(program + ":3:15: error[E003]: lexical error: illegal character '$'"), r.output());
        assertTrue(r.output().contains(program + ": 4 blocks, 3 errors"), r.output());
    }

    /** NUL bytes inside lines and a line of them (a padded transfer): located errors, bounded memory. */
    @Test
    void nulBytesAreLocatedErrorsInBoundedMemory() throws Exception {
        java.io.ByteArrayOutputStream p = new java.io.ByteArrayOutputStream();
        p.writeBytes("G21 G18 G40 G99\nT0101\nG97 S1000 M03\n".getBytes(StandardCharsets.US_ASCII));
        for (int i = 0; i < 100_000; i++) {
            p.writeBytes("G01 X40.\0\0\0 Z-1. F0.2\n".getBytes(StandardCharsets.US_ASCII));
        }
        p.writeBytes(new byte[100_000]);
        p.writeBytes("\nM30\n".getBytes(StandardCharsets.US_ASCII));
        Path program = Files.write(dir.resolve("nul.nc"), p.toByteArray());
        Run r = gcncIn("-Xmx16m", "check", program.toString(), "--machine", "fanuc");
        assertFalse(r.output().contains("Exception") || r.output().contains("\tat "), r.output());
        assertTrue(r.output().startsWith(program + ":4:9: error[E003]: lexical error: illegal character 'U+0000'"),
                r.output());
        assertTrue(r.output().contains("error[E116]: stopped after 10000 errors"), r.output());
        assertTrue(r.output().contains(program + ": 100005 blocks, 100003 errors"), r.output());
        assertTrue(r.size() < 2_000_000, "a report of " + r.size() + " bytes");
        assertEquals(1, r.status(), r.output());
    }

    /**
     * A heap too small even for the 10,000 errors kept (4 MB): the run ends with E506 on one line and
     * status 2 (what the run could not do), never the JVM's stack trace or status 1 ("the program has errors").
     */
    @Test
    void runningOutOfMemoryIsOneLineAndStatusTwo() throws Exception {
        StringBuilder p = new StringBuilder("G21 G18 G40 G99\n");
        for (int i = 0; i < 50_000; i++) {
            p.append("G01 X1. $ Z-1.\n");
        }
        Path program = Files.writeString(dir.resolve("out-of-memory.nc"), p.append("M30\n"));
        Run r = gcncIn("-Xmx4m", "check", program.toString(), "--machine", "fanuc");
        assertFalse(r.output().contains("Exception") || r.output().contains("OutOfMemoryError")
                || r.output().contains("\tat "), r.output());
        assertTrue(r.output().contains("gcnc: error[E506]: out of memory: the Java heap of "), r.output());
        assertEquals(1, r.output().split("E506", -1).length - 1, r.output());
        assertEquals(2, r.status(), r.output());
    }
}
