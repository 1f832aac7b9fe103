package gcnc.cli;

import static gcnc.cli.CliTest.gcnc;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The two forms of compile's output as a user meets them (docs/galil.md, "Two forms"): the program
 * form when the program fits the controller's memory, the stream form when it does not or when it
 * is asked for, the located refusal of a program form that cannot fit, and the stream form replayed
 * from its two files to the same verdict as the program form.
 */
class StreamFormTest {
    private static final Path THREAD = Path.of("src/test/resources/stream/thread-shaft.nc");
    private static final Path GOLDEN = Path.of("src/test/resources/golden/stream");
    /** A CAM-style finishing program of 6,400 chords: more lines than the DMC-4040's 2,000, even packed. */
    private static Path longProgram;

    @BeforeAll
    static void write() throws IOException {
        StringBuilder p = new StringBuilder("%\nO4410 (CAM CHORDS - 6400 BLOCKS)\nG21 G18 G40 G99\nG28 U0. W0.\nT0101\n"
                + "G97 S1200 M03\nG00 X52. Z2. M08\n");
        for (int pass = 0; pass < 16; pass++) {
            double d = 50 - pass * 0.5;
            p.append(String.format("G00 X%.3f Z1.%nG01 Z0. F0.2%n", d));
            for (int k = 1; k <= 400; k++) {
                p.append(String.format("X%.3f Z%.3f%n", d - 2 + Math.sin(k / 40.0), -k * 0.05));
            }
            p.append(String.format("G00 X%.3f%nZ1.%n", d + 2));
        }
        p.append("G00 X60. Z5. M09\nG28 U0. W0. M05\nM30\n%\n");
        longProgram = Files.writeString(Files.createTempDirectory("gcnc-stream").resolve("chords.nc"), p.toString());
    }

    private static Path dir() throws IOException {
        return Files.createTempDirectory("gcnc-form");
    }

    @Test
    void theThreadProgramsStreamFormIsItsGoldenFiles() throws IOException {
        Path out = dir().resolve("thread-shaft.dmc");
        CliTest.Run r = gcnc("compile", THREAD.toString(), "--machine", "haas", "--stock", "20mm,100mm,60mm", "--form", "stream",
                "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        for (String ext : List.of("dmc", "stream")) {
            Path actual = out.resolveSibling("thread-shaft." + ext);
            Path golden = GOLDEN.resolve("thread-shaft.haas." + ext);
            if (Boolean.getBoolean("gcnc.updateGolden")) {
                Files.createDirectories(GOLDEN);
                Files.copy(actual, golden, java.nio.file.StandardCopyOption.REPLACE_EXISTING);
            }
            assertEquals(Files.readString(golden, StandardCharsets.UTF_8), Files.readString(actual, StandardCharsets.UTF_8),
                    "thread-shaft." + ext);
        }
    }

    @Test
    void theStreamHoldsOnlyWhatAHostCanSendAndTheThreadsAreResidentRoutines() throws IOException {
        Path out = dir().resolve("t.dmc");
        assertEquals(0, gcnc("compile", THREAD.toString(), "--machine", "haas", "--stock", "20mm,100mm,60mm", "--form", "stream",
                "-o", out.toString()).status());
        List<String> stream = Files.readAllLines(out.resolveSibling("t.stream"));
        List<String> resident = Files.readAllLines(out).stream().flatMap(l -> gcnc.dmc.DmcReader.statements(l).stream()).toList();
        for (String l : stream) {
            gcnc.dmc.Command c = gcnc.dmc.DmcReader.read(l, (code, args) -> { throw new AssertionError(l); });
            assertFalse(gcnc.dmc.StreamRole.of(c) == gcnc.dmc.StreamRole.EMBED, l + " is not valid from the command line");
        }
        long calls = stream.stream().filter(l -> l.startsWith("JS #B")).count();
        long routines = resident.stream().filter(l -> l.matches("#B[0-9]+")).count();
        assertTrue(calls > 0, "the G76 passes are routines of the resident program");
        assertEquals(calls, routines, "one routine per moved block, each called once");
        assertTrue(resident.stream().anyMatch(l -> l.startsWith("MF ") || l.startsWith("MR ")), "the encoder waits are resident");
        assertEquals(List.of("#GCNC", "gready=0"), resident.subList(0, 2));
        assertTrue(resident.contains("gready=1"));
    }

    @Test
    void theStreamFormReplaysToWhatTheProgramFormReplaysTo() throws IOException {
        for (String[] c : List.of(new String[] {THREAD.toString(), "haas", "20mm,100mm,60mm"},
                new String[] {"docs/examples/bushing.nc", "haas", "38.1mm,200mm,150mm"},
                new String[] {"samples/bishop.nc", "thesis-2004", null})) {
            Path d = dir();
            String[] stock = c[2] == null ? new String[0] : new String[] {"--stock", c[2]};
            Path program = d.resolve("p.dmc");
            Path resident = d.resolve("s.dmc");
            assertEquals(0, gcnc(concat(new String[] {"compile", c[0], "--machine", c[1], "--form", "program", "-o",
                    program.toString()}, stock)).status(), c[0]);
            assertEquals(0, gcnc(concat(new String[] {"compile", c[0], "--machine", c[1], "--form", "stream", "-o",
                    resident.toString()}, stock)).status(), c[0]);
            CliTest.Run p = gcnc(concat(new String[] {"simulate", program.toString(), "--machine", c[1]}, stock));
            CliTest.Run s = gcnc(concat(new String[] {"simulate", d.resolve("s.stream").toString(), "--machine", c[1]}, stock));
            assertEquals(0, s.status(), s.err());
            assertTrue(p.out().contains("simulation: "), p.out() + p.err());
            assertEquals(summary(p.out()), summary(s.out()), c[0]);
        }
    }

    private static String summary(String err) {
        return err.lines().filter(l -> l.startsWith("simulation: ")).findFirst().orElse(err);
    }

    private static String[] concat(String[] a, String[] b) {
        String[] out = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    @Test
    void aProgramThatFitsIsOneProgramAndOneThatDoesNotIsStreamed() throws IOException {
        Path d = dir();
        CliTest.Run small = gcnc("compile", "samples/bishop.nc", "--machine", "thesis-2004", "-o", d.resolve("b.dmc").toString());
        assertEquals(0, small.status(), small.err());
        assertFalse(Files.exists(d.resolve("b.stream")), "the bishop fits a 2,000-line controller");
        assertTrue(Files.readAllLines(d.resolve("b.dmc")).size() <= 2000);

        CliTest.Run big = gcnc("compile", longProgram.toString(), "--machine", "haas", "-o", d.resolve("c.dmc").toString());
        assertEquals(0, big.status(), big.err());
        assertTrue((big.out() + big.err()).contains("resident program) and "), big.out() + big.err());
        int resident = Files.readAllLines(d.resolve("c.dmc")).size();
        assertTrue(resident < 100, "the resident program is small: " + resident);
        assertTrue(Files.readAllLines(d.resolve("c.stream")).size() > 2000);
        assertTrue(Files.readString(d.resolve("c.dmc.map")).contains("# stream c.stream\n# stream sha256 "));
    }

    @Test
    void theProgramFormAskedForAndTooLongIsALocatedErrorNamingTheStreamForm() throws IOException {
        Path d = dir();
        CliTest.Run r = gcnc("compile", longProgram.toString(), "--machine", "haas", "--form", "program", "-o",
                d.resolve("c.dmc").toString());
        assertEquals(1, r.status());
        assertTrue(r.err().contains("chords.nc:1:1: error[E238]: the program form is "), r.err());
        assertTrue(r.err().contains("lines the DMC-4040's program memory holds"), r.err());
        assertTrue(r.err().contains("the stream form fits: a resident program of "), r.err());
        try (var files = Files.list(d)) {
            assertEquals(List.of(), files.toList(), "nothing written");
        }
    }

    @Test
    void aProgramFormCompileRemovesTheStreamAnEarlierCompileLeft() throws IOException {
        Path d = dir();
        Path out = d.resolve("t.dmc");
        assertEquals(0, gcnc("compile", THREAD.toString(), "--machine", "haas", "--stock", "20mm,100mm,60mm", "--form", "stream", "-o",
                out.toString()).status());
        assertTrue(Files.exists(d.resolve("t.stream")));
        assertEquals(0, gcnc("compile", THREAD.toString(), "--machine", "haas", "--stock", "20mm,100mm,60mm", "-o", out.toString()).status());
        assertFalse(Files.exists(d.resolve("t.stream")), "a sender must not pair the new program with the old stream");
        assertFalse(Files.exists(d.resolve("t.stream.map")));
    }

    @Test
    void aStreamFromAnotherCompileIsToldApart() throws IOException {
        Path d = dir();
        Path out = d.resolve("t.dmc");
        assertEquals(0, gcnc("compile", THREAD.toString(), "--machine", "haas", "--stock", "20mm,100mm,60mm", "--form", "stream", "-o",
                out.toString()).status());
        Files.writeString(d.resolve("t.stream"), Files.readString(d.resolve("t.stream")).replace("WT 2000", "WT 2002"));
        CliTest.Run r = gcnc("simulate", d.resolve("t.stream").toString(), "--machine", "haas", "--stock", "20mm,100mm,60mm");
        assertTrue(r.err().contains("warning[E245]: "), r.err());
    }

    @Test
    void usageThatCannotWorkIsRefusedBeforeAnythingIsWritten() throws IOException {
        assertEquals(2, gcnc("compile", THREAD.toString(), "--machine", "haas", "--form", "stream", "-o", "-").status());
        assertEquals(2, gcnc("compile", THREAD.toString(), "--machine", "haas", "--form", "tape", "-o",
                dir().resolve("x.dmc").toString()).status());
        assertEquals(2, gcnc("compile", "samples/bishop.nc", "--machine", "thesis-2004", "--dialect", "thesis", "--form", "stream",
                "-o", dir().resolve("x.dmc").toString()).status());
    }
}
