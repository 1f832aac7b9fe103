package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** What the command line does with its outputs and inputs: it never loses or overwrites data. */
class OutputSafetyTest {
    record Run(int status, String out, String err, byte[] stdout) {
    }

    static Run gcnc(InputStream stdin, String... args) {
        ByteArrayOutputStream raw = new ByteArrayOutputStream();
        CommandLine cl = Main.commandLine(new Main.Streams(stdin, raw));
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int status = cl.execute(args);
        return new Run(status, out.toString(), err.toString(), raw.toByteArray());
    }

    static Run gcnc(String... args) {
        return gcnc(InputStream.nullInputStream(), args);
    }

    private final Path dir;
    private final Path program;
    private final String text;

    OutputSafetyTest() throws IOException {
        dir = Files.createTempDirectory("gcnc-safe");
        program = dir.resolve("part.nc");
        text = Files.readString(Path.of("samples/turning.nc"));
        Files.writeString(program, text);
    }

    private void assertProgramUntouched() throws IOException {
        assertEquals(text, Files.readString(program), "the G-code source was overwritten");
    }

    private void assertNoTemporaryFiles() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            assertFalse(s.anyMatch(f -> f.getFileName().toString().contains(".part")), "a temporary file was left behind");
        }
        assertEquals(java.util.Set.of(), gcnc.output.TempFiles.open(), "temporary files the shutdown hook still has to remove");
    }

    @Test
    void anOutputNamingTheInputIsRefusedUnderEveryName() throws IOException {
        Path symlink = Files.createSymbolicLink(dir.resolve("link.nc"), program.getFileName());
        Path hardLink = Files.createLink(dir.resolve("hard.nc"), program);
        String[] names = {program.toString(), dir.resolve("./part.nc").toString(), dir + "/../" + dir.getFileName() + "/part.nc",
                symlink.toString(), hardLink.toString()};
        for (String name : names) {
            Run r = gcnc("compile", program.toString(), "-o", name);
            assertEquals(2, r.status(), name + ": " + r.err());
            assertTrue(r.err().startsWith(name + ":1:1: error[E501]: the output is the program being read (" + program + ")"), r.err());
            assertProgramUntouched();
        }
        assertTrue(Files.isSymbolicLink(symlink));
        assertNoTemporaryFiles();
    }

    /** A program called x.dmc.map compiled to x.dmc would have its source overwritten by the side map. */
    @Test
    void theSideMapMayNotOverwriteTheInputEither() throws IOException {
        Path odd = dir.resolve("x.dmc.map");
        Files.writeString(odd, text);
        Run r = gcnc("compile", odd.toString(), "-o", dir.resolve("x.dmc").toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("error[E501]"), r.err());
        assertEquals(text, Files.readString(odd));
        assertFalse(Files.exists(dir.resolve("x.dmc")));
    }

    @Test
    void aDirectoryOrRootIsAClearErrorNotAnException() throws IOException {
        for (String name : new String[] {"/", dir.toString(), "."}) {
            Run r = gcnc("compile", program.toString(), "-o", name);
            assertEquals(2, r.status(), r.err());
            assertEquals(name + ":1:1: error[E502]: the output is a directory: name a file to write\n", r.err());
        }
        Run svg = gcnc("simulate", program.toString(), "--svg", dir.toString());
        assertEquals(2, svg.status(), svg.err());
        assertTrue(svg.err().contains(dir + ":1:1: error[E502]"), svg.err());
        assertNoTemporaryFiles();
    }

    @Test
    void theSvgMayNotOverwriteTheProgram() throws IOException {
        Run r = gcnc("simulate", program.toString(), "--svg", program.toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("error[E501]"), r.err());
        assertProgramUntouched();
    }

    /** As root, -o /dev/null once replaced the device with a regular file. */
    @Test
    void aDeviceIsWrittenThroughNeverReplaced() throws IOException {
        Path devNull = Path.of("/dev/null");
        Run r = gcnc("compile", program.toString(), "-o", devNull.toString());
        assertEquals(0, r.status(), r.err());
        assertFalse(Files.isRegularFile(devNull), "/dev/null became a regular file");
        assertFalse(Files.exists(Path.of("/dev/null.map")), "a side map beside a device");
    }

    @Test
    void aNamedPipeIsWrittenThroughAndAReaderGetsTheWholeProgram() throws Exception {
        Path expected = dir.resolve("expected.dmc");
        assertEquals(0, gcnc("compile", program.toString(), "-o", expected.toString()).status());
        Path fifo = mkfifo(dir.resolve("out.fifo"));
        CompletableFuture<byte[]> reader = CompletableFuture.supplyAsync(() -> {
            try (InputStream in = Files.newInputStream(fifo)) {
                return in.readAllBytes();
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        });
        Run r = gcnc("compile", program.toString(), "-o", fifo.toString());
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(Files.readAllBytes(expected), reader.get(30, TimeUnit.SECONDS));
        assertFalse(Files.isRegularFile(fifo), "the pipe was replaced by a file");
        assertFalse(Files.exists(dir.resolve("out.fifo.map")));
    }

    /** compile and simulate read the program once: a named pipe neither hangs nor loses the first line (false E052). */
    @Test
    void aProgramFromANamedPipeIsReadOnce() throws Exception {
        for (String command : new String[] {"check", "compile", "simulate"}) {
            Path fifo = mkfifo(dir.resolve(command + ".fifo"));
            CompletableFuture<Void> writer = CompletableFuture.runAsync(() -> {
                try (OutputStream o = Files.newOutputStream(fifo)) {
                    o.write(text.getBytes(StandardCharsets.UTF_8));
                } catch (IOException e) {
                    throw new java.io.UncheckedIOException(e);
                }
            });
            Run r = command.equals("compile")
                    ? gcnc(command, fifo.toString(), "-o", dir.resolve("fifo.dmc").toString())
                    : gcnc(command, fifo.toString());
            writer.get(30, TimeUnit.SECONDS);
            assertEquals(0, r.status(), command + ": " + r.err());
            assertEquals("", r.err(), command);
        }
    }

    @Test
    void standardInputAndStandardOutput() throws IOException {
        Path file = dir.resolve("file.dmc");
        assertEquals(0, gcnc("compile", program.toString(), "-o", file.toString()).status());
        Run r = gcnc(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), "compile", "-", "-o", "-");
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(Files.readAllBytes(file), r.stdout(), "-o - writes exactly the DMC program");
        assertEquals("", r.out(), "the summary must not mix with the program on standard output");
        assertTrue(r.err().startsWith("<stdin>: 13 blocks -> <stdout>"), r.err());
        Run check = gcnc(new ByteArrayInputStream("G21\nM93\nM30\n".getBytes(StandardCharsets.UTF_8)), "check", "-");
        assertEquals(1, check.status());
        assertTrue(check.err().startsWith("<stdin>:") && check.err().contains(": error[E012]"), check.err());
    }

    @Test
    void aProgramWithErrorsWritesNothingToStandardOutput() {
        Run r = gcnc(new ByteArrayInputStream("G21\nG01 X10. Z5.\nM30\n".getBytes(StandardCharsets.UTF_8)), "compile", "-", "-o", "-");
        assertEquals(1, r.status(), r.err());
        assertEquals(0, r.stdout().length);
    }

    @Test
    void standardInputNeedsANamedOutputAndStandardOutputCannotCarryTwoThings() {
        Run noOutput = gcnc(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), "compile", "-");
        assertEquals(2, noOutput.status());
        assertTrue(noOutput.err().contains("name the output with -o"), noOutput.err());
        assertFalse(Files.exists(Path.of("-.dmc")));
        Run both = gcnc("compile", program.toString(), "-o", "-", "--format", "json");
        assertEquals(2, both.status());
        assertTrue(both.err().contains("would both write standard output"), both.err());
        assertEquals("", both.out(), "no report document after a usage error");
    }

    @Test
    void aReadErrorNamesTheInputNotTheOutput() throws IOException {
        Path folder = Files.createDirectory(dir.resolve("folder.nc"));
        Path out = dir.resolve("out.dmc");
        Run r = gcnc("compile", folder.toString(), "-o", out.toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().startsWith(folder + ":1:1: error[E500]: cannot read:"), r.err());
        assertFalse(r.err().contains("out.dmc"), r.err());
        assertFalse(Files.exists(out));
        assertNoTemporaryFiles();
    }

    @Test
    void controlCharactersFromTheInputAreEscaped() throws IOException {
        Path evil = dir.resolve("a\u001b[2Jb\u202e.nc");
        Files.writeString(evil, "G21\nX\u001b]0;pwned\u0007 M30\n");
        Run r = gcnc("check", evil.toString());
        assertEquals(1, r.status(), r.err());
        for (char c : (r.err() + r.out()).toCharArray()) {
            assertFalse(Printable.unsafe(c) && c != '\n', "unescaped U+" + Integer.toHexString(c) + " in: " + r.err());
        }
        assertTrue(r.err().startsWith(dir + "/a\\x1B[2Jb\\u202E.nc:"), r.err());
    }

    @Test
    void aFileNameThatJavaCannotTakeIsAClearUsageError() {
        Run r = gcnc("check", "bad\u0000name.nc");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("'bad\\x00name.nc' cannot be a file name"), r.err());
        assertFalse(r.err().contains("Exception"), r.err());
    }

    static Path mkfifo(Path p) throws IOException, InterruptedException {
        return gcnc.TestFiles.mkfifo(p);
    }

    @Test
    void theDrawingCanGoToStandardOutputAndTheTraceThenToStandardError() {
        Run r = gcnc("simulate", program.toString(), "--svg", "-", "--trace");
        assertEquals(0, r.status(), r.err());
        String svg = new String(r.stdout(), StandardCharsets.UTF_8);
        assertTrue(svg.startsWith("<svg") || svg.startsWith("<?xml"), svg.substring(0, Math.min(80, svg.length())));
        assertTrue(svg.strip().endsWith("</svg>"));
        assertEquals("", r.out(), "nothing but the drawing on standard output");
        assertTrue(r.err().contains("drawing: <stdout>"), r.err());
        assertFalse(Files.exists(Path.of("-")));
    }

    @Test
    void theTraceNeverBreaksAJsonReport() throws IOException {
        Run r = gcnc("simulate", program.toString(), "--trace", "--format", "json");
        assertEquals(0, r.status(), r.err());
        assertEquals("gcnc-diagnostics", new com.fasterxml.jackson.databind.ObjectMapper().readTree(r.out()).get("format").asText());
        assertFalse(r.err().isEmpty(), "the trace went to standard error");
    }

    /** {@code -o /dev/stdout >> log}: the log is appended to, never replaced by the DMC. */
    @Test
    void devStdoutAppendsToWhatStandardOutputIs() throws Exception {
        Path log = dir.resolve("log");
        Files.writeString(log, "earlier entries\n");
        String javaCommand = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(javaCommand, "-cp", System.getProperty("java.class.path"), "gcnc.cli.Main",
                "compile", "--quiet", program.toString(), "-o", "/dev/stdout")
                .redirectOutput(ProcessBuilder.Redirect.appendTo(log.toFile()))
                .redirectError(dir.resolve("stderr").toFile()).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), Files.readString(dir.resolve("stderr")));
        Path expected = dir.resolve("expected.dmc");
        assertEquals(0, gcnc("compile", program.toString(), "-o", expected.toString()).status());
        assertEquals("earlier entries\n" + Files.readString(expected), Files.readString(log));
    }

    @Test
    void checkReadsStandardInputOnlyOnce() {
        Run r = gcnc(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), "check", "-", "-");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("standard input, which can be read once"), r.err());
    }
}
