package gcnc.output;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The DMC and its source map are replaced together or not at all, and no temporary file outlives a run. */
class AtomicPairTest {
    private final Path dir;
    private final Path dmc;
    private final Path map;

    AtomicPairTest() throws IOException {
        dir = Files.createTempDirectory("gcnc-pair");
        dmc = dir.resolve("part.dmc");
        map = dir.resolve("part.dmc.map");
    }

    private List<String> leftovers() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.startsWith(".")).toList();
        }
    }

    @Test
    void bothAreReplacedTogether() throws IOException {
        Files.writeString(dmc, "old dmc\n");
        Files.writeString(map, "old map\n");
        try (AtomicOutput d = new AtomicOutput(dmc); AtomicOutput m = new AtomicOutput(map)) {
            d.line("new dmc");
            m.line("new map");
            AtomicOutput.commitAll(d, m);
        }
        assertEquals("new dmc\n", Files.readString(dmc));
        assertEquals("new map\n", Files.readString(map));
        assertEquals(List.of(), leftovers());
    }

    /** A full disk while writing the map: the old pair stays as it was (once the new .dmc was kept beside the old .map). */
    @Test
    void aFullDiskOnTheSecondFileLeavesTheOldPair() throws IOException {
        Files.writeString(dmc, "old dmc\n");
        Files.writeString(map, "old map\n");
        AtomicOutput.Opener full = temp -> new java.io.FilterOutputStream(Files.newOutputStream(temp)) {
            @Override
            public void write(byte[] b, int off, int len) throws IOException {
                throw new IOException("No space left on device");
            }
        };
        try (AtomicOutput d = new AtomicOutput(dmc); AtomicOutput m = new AtomicOutput(map, full)) {
            d.line("new dmc");
            m.line("new map");
            IOException e = assertThrows(IOException.class, () -> AtomicOutput.commitAll(d, m));
            assertEquals("No space left on device", e.getMessage());
        }
        assertEquals("old dmc\n", Files.readString(dmc));
        assertEquals("old map\n", Files.readString(map));
        assertEquals(List.of(), leftovers());
    }

    /** The second rename fails (its target turned into a non-empty folder meanwhile): the first is undone. */
    @Test
    void whenTheSecondRenameFailsTheFirstIsRestored() throws IOException {
        Files.writeString(dmc, "old dmc\n");
        try (AtomicOutput d = new AtomicOutput(dmc); AtomicOutput m = new AtomicOutput(map)) {
            d.line("new dmc");
            m.line("new map");
            Files.createDirectory(map);
            Files.writeString(map.resolve("occupant"), "x");
            assertThrows(IOException.class, () -> AtomicOutput.commitAll(d, m));
        }
        assertEquals("old dmc\n", Files.readString(dmc), "the new .dmc must not stay beside an old or missing map");
        assertEquals(List.of(), leftovers());
    }

    @Test
    void whenTheSecondRenameFailsANewFirstFileIsRemoved() throws IOException {
        try (AtomicOutput d = new AtomicOutput(dmc); AtomicOutput m = new AtomicOutput(map)) {
            d.line("new dmc");
            Files.createDirectory(map);
            Files.writeString(map.resolve("occupant"), "x");
            assertThrows(IOException.class, () -> AtomicOutput.commitAll(d, m));
        }
        assertFalse(Files.exists(dmc));
        assertEquals(List.of(), leftovers());
    }

    @Test
    void aSymbolicLinkStaysALinkAndItsFileGetsTheOutput() throws IOException {
        Path real = dir.resolve("real.dmc");
        Files.writeString(real, "old\n");
        Path link = Files.createSymbolicLink(dir.resolve("link.dmc"), real.getFileName());
        try (AtomicOutput o = new AtomicOutput(link)) {
            o.line("new");
            o.commit();
        }
        assertTrue(Files.isSymbolicLink(link));
        assertEquals("new\n", Files.readString(real));
    }

    /**
     * A file made read-only to keep it is not replaced behind its owner's back (a rename needs only the
     * folder's permission). Root, whom the modes do not stop, may write it, and gcnc replaces it as a
     * write would; so as root the compile runs without the capability that overrides them
     * (CAP_DAC_OVERRIDE, dropped by util-linux's setpriv), as a shop's own user would run it.
     */
    @Test
    void aReadOnlyFileIsNotReplaced() throws Exception {
        Files.writeString(dmc, "kept\n");
        Files.setPosixFilePermissions(dmc, java.nio.file.attribute.PosixFilePermissions.fromString("r--r--r--"));
        if (Files.isWritable(dmc)) {
            Path setpriv = Path.of("/usr/bin/setpriv");
            org.junit.jupiter.api.Assumptions.assumeTrue(Files.isExecutable(setpriv),
                    "run as root, and needs /usr/bin/setpriv (util-linux) to drop root's override of file modes; absent here");
            Path log = Files.createTempFile("gcnc-readonly", ".log");
            Process gcnc = new ProcessBuilder(setpriv.toString(), "--inh-caps=-dac_override", "--bounding-set=-dac_override",
                    Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp", System.getProperty("java.class.path"),
                    "gcnc.cli.Main", "compile", "samples/turning.nc", "-o", dmc.toString())
                    .redirectErrorStream(true).redirectOutput(log.toFile()).start();
            assertTrue(gcnc.waitFor(120, TimeUnit.SECONDS), "the compile ended");
            String out = Files.readString(log);
            assertEquals(2, gcnc.exitValue(), out);
            assertTrue(out.contains("error[E500]: cannot write: permission denied"), out);
            Files.delete(log);
        } else {
            assertThrows(java.nio.file.AccessDeniedException.class, () -> new AtomicOutput(dmc).close());
        }
        assertEquals("kept\n", Files.readString(dmc));
        assertEquals(List.of(), leftovers());
    }

    @Test
    void aReplacedFileKeepsItsPermissions() throws IOException {
        Files.writeString(dmc, "old\n");
        Files.setPosixFilePermissions(dmc, java.nio.file.attribute.PosixFilePermissions.fromString("rw-rw----"));
        try (AtomicOutput o = new AtomicOutput(dmc)) {
            o.line("new");
            o.commit();
        }
        assertEquals("rw-rw----", java.nio.file.attribute.PosixFilePermissions.toString(Files.getPosixFilePermissions(dmc)));
    }

    /**
     * SIGTERM or Ctrl-C (SIGINT) in the middle of a compile (here: while it waits for the rest of its
     * program on a named pipe, with its .part files open) leaves no temporary file behind.
     */
    @Test
    void aKilledCompileLeavesNoTemporaryFiles() throws Exception {
        for (String signal : new String[] {"TERM", "INT"}) {
            killedWith(signal);
        }
    }

    private void killedWith(String signal) throws Exception {
        Path fifo = gcnc.TestFiles.mkfifo(dir.resolve(signal + ".fifo"));
        Path log = Files.createTempFile("gcnc-killed", ".log");
        String javaCommand = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process gcnc = new ProcessBuilder(javaCommand, "-cp", System.getProperty("java.class.path"), "gcnc.cli.Main",
                "compile", fifo.toString(), "-o", dmc.toString())
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        try (OutputStream program = Files.newOutputStream(fifo)) {
            program.write("O1\nG21 G90\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
            program.flush();
            long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (leftovers().stream().noneMatch(n -> n.endsWith(".part")) && System.nanoTime() < until) {
                Thread.sleep(20);
            }
            assertTrue(leftovers().stream().anyMatch(n -> n.endsWith(".part")), "the compile never opened its output: "
                    + Files.readString(log));
            Process kill = new ProcessBuilder("kill", "-s", signal, Long.toString(gcnc.pid())).inheritIO().start();
            assertEquals(0, kill.waitFor());
            assertTrue(gcnc.waitFor(60, TimeUnit.SECONDS));
        } catch (IOException brokenPipe) {
            // The program's end was never written; the pipe breaks when gcnc goes.
        } finally {
            gcnc.destroyForcibly();
        }
        assertEquals(List.of(), leftovers(), "SIG" + signal + " left temporary files; gcnc said: " + Files.readString(log));
        assertFalse(Files.exists(dmc));
        Files.delete(fifo);
    }
}
