package gcnc.cli;

import static gcnc.cli.CliTest.gcnc;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.cli.CliTest.Run;
import gcnc.output.AtomicOutput;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * A map that belongs to its DMC, side files never written through a link nobody named, and
 * standard output that carries the DMC alone (issue 18, docs/dmc-format.md and command-line.md).
 */
class SideFilesTest {
    private Path dir;
    private Path turn;
    private Path rapid;

    @BeforeEach
    void copyPrograms() throws Exception {
        dir = Files.createTempDirectory("gcnc-side");
        turn = Files.copy(Path.of("src/test/resources/gcnc/cli/turn.nc"), dir.resolve("turn.nc"));
        rapid = Files.copy(Path.of("src/test/resources/gcnc/cli/rapid-in.nc"), dir.resolve("rapid-in.nc"));
    }

    private Run compile(Path program, String... more) {
        List<String> args = new java.util.ArrayList<>(List.of("compile", program.toString(), "--machine", "haas"));
        args.addAll(List.of(more));
        return gcnc(args.toArray(String[]::new));
    }

    @Test
    void theMapRecordsTheShaOfItsDmcAndOfItsProgram() throws Exception {
        assertEquals(0, compile(turn).status());
        List<String> map = Files.readAllLines(dir.resolve("turn.dmc.map"));
        assertEquals("# source turn.nc", map.get(0));
        assertEquals("# source sha256 " + AtomicOutput.sha256(turn), map.get(1));
        assertEquals("# dmc sha256 " + AtomicOutput.sha256(dir.resolve("turn.dmc")), map.get(map.size() - 1));
    }

    @Test
    void aCompileWithoutAMapRemovesTheMapAnEarlierCompileLeft() throws Exception {
        assertEquals(0, compile(turn).status());
        assertTrue(Files.exists(dir.resolve("turn.dmc.map")));
        assertEquals(0, compile(turn, "--source-map").status());
        assertFalse(Files.exists(dir.resolve("turn.dmc.map")), "a stale map would blame the wrong lines");
        assertTrue(Files.readString(dir.resolve("turn.dmc")).contains("NO L7"));
    }

    @Test
    void aFailedCompileKeepsTheEarlierPair() throws Exception {
        assertEquals(0, compile(turn, "-o", dir.resolve("part.dmc").toString()).status());
        String dmc = Files.readString(dir.resolve("part.dmc"));
        String map = Files.readString(dir.resolve("part.dmc.map"));
        assertEquals(1, compile(rapid, "--source-map", "-o", dir.resolve("part.dmc").toString()).status());
        assertEquals(dmc, Files.readString(dir.resolve("part.dmc")));
        assertEquals(map, Files.readString(dir.resolve("part.dmc.map")));
    }

    @Test
    void aReplayWarnsAtTheDmcAndIgnoresTheMapOfAnotherDmc() throws Exception {
        assertEquals(0, compile(turn).status());
        assertEquals(0, compile(rapid, "--no-simulate").status());
        // the turning program's map beside the other DMC: its lines would blame turn.nc's lines
        Files.copy(dir.resolve("turn.dmc.map"), dir.resolve("rapid-in.dmc.map"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Path dmc = dir.resolve("rapid-in.dmc");
        Run r = gcnc("simulate", dmc.toString(), "--machine", "haas");
        assertEquals(1, r.status(), r.err());
        assertTrue(r.err().contains(dmc + ":1:1: warning[E331]: the source map " + dir.resolve("rapid-in.dmc.map")
                + " was not written with this DMC"), r.err());
        // the finding stays in the DMC, at its own line, and says so instead of "at ?"
        assertTrue(r.err().lines().anyMatch(l -> l.startsWith(dmc + ":") && l.contains("error[E305]")
                && l.contains("enters the blank at DMC line ")), r.err());
    }

    @Test
    void aReplayWithItsOwnMapBlamesTheProgramLineAndNamesTheDmcLine() throws Exception {
        assertEquals(0, compile(rapid, "--no-simulate").status());
        Run r = gcnc("simulate", dir.resolve("rapid-in.dmc").toString(), "--machine", "haas");
        assertEquals(1, r.status(), r.err());
        assertFalse(r.err().contains("E331"), r.err());
        assertFalse(r.err().contains(" at ?"), r.err());
        assertTrue(r.err().matches("(?s).*" + java.util.regex.Pattern.quote(dir.resolve("rapid-in.nc") + ":7:1: error[E305]: rapid move enters the blank at DMC line ")
                + "\\d+ \\(machine.*"), r.err());
    }

    @Test
    void theMapIsNeverWrittenThroughALinkNobodyNamed() throws Exception {
        Path victim = Files.writeString(dir.resolve("victim.txt"), "keep me\n");
        Files.createSymbolicLink(dir.resolve("turn.dmc.map"), victim.getFileName());
        Run r = compile(turn);
        assertEquals(2, r.status());
        assertTrue(r.err().contains("turn.dmc.map:1:1: error[E510]: " + dir.resolve("turn.dmc.map") + " is a symbolic link"),
                r.err());
        assertEquals("keep me\n", Files.readString(victim));
        assertFalse(Files.exists(dir.resolve("turn.dmc")), "nothing is written when the pair cannot be");
        // a compile that writes no map removes the planted link itself, never the file it leads to
        assertEquals(0, compile(turn, "--source-map").status());
        assertFalse(Files.exists(dir.resolve("turn.dmc.map"), java.nio.file.LinkOption.NOFOLLOW_LINKS));
        assertEquals("keep me\n", Files.readString(victim));
    }

    /**
     * {@code -o -} and {@code -o /dev/stdout} put the DMC alone on standard output, the same bytes as
     * {@code -o FILE}. The second runs in a JVM of its own, whose standard output the test reads: in
     * this JVM /dev/stdout is the test run's console.
     */
    @Test
    void devStdoutCarriesTheDmcAloneAsDashDoes() throws Exception {
        if (!Files.exists(Path.of("/proc/self/fd/1"))) {
            return; // no /proc: standard output cannot be recognised under another name
        }
        assertEquals(0, compile(turn).status());
        String dmc = Files.readString(dir.resolve("turn.dmc"));
        java.io.ByteArrayOutputStream stdout = new java.io.ByteArrayOutputStream();
        Run dash = gcnc(stdout, "compile", turn.toString(), "--machine", "haas", "-o", "-");
        assertEquals(0, dash.status(), dash.err());
        assertEquals(dmc, stdout.toString(java.nio.charset.StandardCharsets.ISO_8859_1));
        assertFalse(dash.out().contains("simulation:"), dash.out());
        assertTrue(dash.err().contains("simulation:"), dash.err());

        Path out = dir.resolve("stdout");
        Path err = dir.resolve("stderr");
        Process dev = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), "gcnc.cli.Main", "compile", turn.toString(), "--machine", "haas",
                "-o", "/dev/stdout").redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        assertTrue(dev.waitFor(120, java.util.concurrent.TimeUnit.SECONDS), "the compile ended");
        String said = Files.readString(err);
        assertEquals(0, dev.exitValue(), said);
        assertEquals(dmc, Files.readString(out), "the DMC alone");
        assertTrue(said.contains("-> /dev/stdout") && said.contains("simulation:"), said);
        assertFalse(Files.exists(Path.of("/dev/stdout.map")));
    }
}
