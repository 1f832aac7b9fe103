package gcnc;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.File;
import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * The resident checker (gcnc daemon, issue 23) prints the same bytes on standard output and standard
 * error, exits with the same status and writes the same files as a cold run: the samples, the
 * pipeline fuzz test's random programs and mutated real-style programs, error cases (a missing file,
 * usage errors, a misspelt machine, Spanish, standard input, -o to standard output). The client is
 * called directly, so that a run the daemon did not serve (status 75, "run cold") fails the test
 * instead of passing as a cold run. A wrong token is refused; another jar, another folder and a
 * busy daemon are answered "cold", and through the launcher the user still gets a cold run's output.
 */
class ResidentCheckerTest {
    private static final Path JAR = Path.of("build/libs/gcnc.jar").toAbsolutePath();
    private static final int COLD = 75;
    private static Path state;
    /** Where the runs write, relative to the working directory as a user's names are. */
    private static final Path WORK = Path.of("build/tmp/resident");

    record Run(int status, byte[] out, byte[] err) {
        String text() {
            return "status " + status + "\n--- stdout\n" + new String(out, StandardCharsets.UTF_8) + "--- stderr\n"
                    + new String(err, StandardCharsets.UTF_8);
        }
    }

    /** The C client (scripts/gcnc-client.c), compiled as install.sh compiles it: every run goes through both clients. */
    private static final Path C_CLIENT = WORK.resolve("gcnc-client");

    @BeforeAll
    static void start() throws Exception {
        state = Files.createTempDirectory("gcnc-daemon-state");
        Files.createDirectories(WORK);
        Process cc = new ProcessBuilder("cc", "-O2", "-o", C_CLIENT.toString(), "scripts/gcnc-client.c").inheritIO().start();
        assertEquals(0, cc.waitFor(), "cc scripts/gcnc-client.c (setup.sh installs gcc)");
        Run r = run(List.of("java", "-jar", JAR.toString(), "daemon", "start"), null, Map.of(), null);
        assertEquals(0, r.status(), r.text());
    }

    @AfterAll
    static void stop() throws Exception {
        Run r = run(List.of("java", "-jar", JAR.toString(), "daemon", "stop"), null, Map.of(), null);
        assertEquals(0, r.status(), r.text());
        assertEquals(3, run(List.of("java", "-jar", JAR.toString(), "daemon", "status"), null, Map.of(), null).status());
    }

    private static Run run(List<String> command, byte[] stdin, Map<String, String> env, Path dir) throws Exception {
        return started(command, stdin, env, dir).call();
    }

    /** A process started, and what waits for it and reads what it printed. */
    private static java.util.concurrent.Callable<Run> started(List<String> command, byte[] stdin, Map<String, String> env,
            Path dir) throws Exception {
        Path tmp = Files.createTempDirectory("gcnc-resident-run");
        Path in = tmp.resolve("stdin");
        Files.write(in, stdin == null ? new byte[0] : stdin);
        ProcessBuilder pb = new ProcessBuilder(command).redirectInput(in.toFile())
                .redirectOutput(tmp.resolve("stdout").toFile()).redirectError(tmp.resolve("stderr").toFile());
        if (dir != null) {
            pb.directory(dir.toFile());
        }
        pb.environment().remove("GCNC_JAR");
        pb.environment().remove("GCNC_JAVA_OPTS");
        pb.environment().put("GCNC_DAEMON_DIR", state.toString());
        pb.environment().put("LANG", "C.UTF-8");
        pb.environment().remove("LC_ALL");
        pb.environment().putAll(env);
        Process p = pb.start();
        return () -> {
            assertTrue(p.waitFor(300, TimeUnit.SECONDS), command.toString());
            return new Run(p.exitValue(), Files.readAllBytes(tmp.resolve("stdout")), Files.readAllBytes(tmp.resolve("stderr")));
        };
    }

    private static Run cold(List<String> args, byte[] stdin, Map<String, String> env) throws Exception {
        return coldStarted(args, stdin, env).call();
    }

    private static java.util.concurrent.Callable<Run> coldStarted(List<String> args, byte[] stdin, Map<String, String> env)
            throws Exception {
        Map<String, String> off = new HashMap<>(env);
        off.put("GCNC_DAEMON", "off");
        List<String> c = new ArrayList<>(List.of("sh", "scripts/gcnc"));
        c.addAll(args);
        return started(c, stdin, off, null);
    }

    private static Run client(List<String> args, byte[] stdin, Map<String, String> env, Path jar, Path dir)
            throws Exception {
        List<String> c = new ArrayList<>(List.of("python3", Path.of("scripts/gcnc-client.py").toAbsolutePath().toString(),
                jar.toString()));
        c.addAll(args);
        return run(c, stdin, env, dir);
    }

    private static Run clientC(List<String> args, Map<String, String> env, Path jar, Path dir) throws Exception {
        List<String> c = new ArrayList<>(List.of(C_CLIENT.toAbsolutePath().toString(), jar.toAbsolutePath().toString()));
        c.addAll(args);
        return run(c, null, env, dir);
    }

    /** The files a run may write, read and removed so that the next run writes them afresh. */
    private static List<byte[]> take(List<Path> files) throws IOException {
        List<byte[]> out = new ArrayList<>();
        for (Path f : files) {
            out.add(Files.exists(f) ? Files.readAllBytes(f) : null);
            Files.deleteIfExists(f);
        }
        return out;
    }

    /** The same bytes, status and files, cold and through the daemon. */
    private static void same(List<String> args, byte[] stdin, Map<String, String> env, Path... written) throws Exception {
        Run cold;
        List<byte[]> coldFiles;
        Run warm;
        if (written.length == 0) {
            // a run that writes no file: the cold JVM starts while the daemon serves the same command
            // line (a cold JVM never asks the daemon, GCNC_DAEMON=off), the two side by side on two cores
            java.util.concurrent.Callable<Run> coldRun = coldStarted(args, stdin, env);
            warm = client(args, stdin, env, JAR, null);
            cold = coldRun.call();
            coldFiles = List.of();
        } else {
            cold = cold(args, stdin, env);
            coldFiles = take(List.of(written));
            warm = client(args, stdin, env, JAR, null);
        }
        List<byte[]> warmFiles = take(List.of(written));
        sameAs(cold, coldFiles, warm, warmFiles, args, written, "Python client");
        List<String> c = new ArrayList<>(List.of(C_CLIENT.toAbsolutePath().toString(), JAR.toString()));
        c.addAll(args);
        Run warmC = run(c, stdin, env, null);
        sameAs(cold, coldFiles, warmC, take(List.of(written)), args, written, "C client");
    }

    private static void sameAs(Run cold, List<byte[]> coldFiles, Run warm, List<byte[]> warmFiles, List<String> args,
                               Path[] written, String client) {
        String what = args + " (" + client + ")";
        assertNotEquals(COLD, warm.status(), what + " was not served by the daemon:\n" + warm.text());
        assertEquals(cold.text(), warm.text(), what);
        assertArrayEquals(cold.out(), warm.out(), what);
        assertArrayEquals(cold.err(), warm.err(), what);
        for (int i = 0; i < written.length; i++) {
            assertArrayEquals(coldFiles.get(i), warmFiles.get(i), written[i] + " after " + what);
        }
    }

    private static final Path DMC = WORK.resolve("out.dmc");
    private static final Path MAP = WORK.resolve("out.dmc.map");

    @Test
    void theSamplesPrintAndWriteTheSame() throws Exception {
        try (var files = Files.list(Path.of("samples"))) {
            for (Path p : files.filter(f -> f.toString().endsWith(".nc")).sorted().toList()) {
                String f = p.toString();
                same(List.of("check", f), null, Map.of());
                same(List.of("compile", f, "-o", DMC.toString()), null, Map.of(), DMC, MAP);
                same(List.of("check", f, "--format", "json", "--machine", "haas"), null, Map.of());
            }
        }
        Files.writeString(WORK.resolve("sim.dmc"), "");
        cold(List.of("compile", "samples/turning.nc", "-o", WORK.resolve("sim.dmc").toString()), null, Map.of());
        same(List.of("simulate", WORK.resolve("sim.dmc").toString()), null, Map.of());
        same(List.of("check", "samples"), null, Map.of());
    }

    /**
     * Random and mutated programs per run: 3 in the default run (each is three pairs of a cold JVM and
     * a resident run, about 0.6 s a pair: the most of this class's time); a campaign sets more with
     * {@code gradle junitPlatformTest -PresidentCount=50}.
     */
    private static final int PROGRAMS = Integer.getInteger("gcnc.resident.count", 3);

    @Test
    void randomAndMutatedProgramsPrintAndWriteTheSame() throws Exception {
        String real = Files.readString(Path.of("samples/turning.nc"));
        for (long seed = 1; seed <= PROGRAMS; seed++) {
            Path p = WORK.resolve("fuzz-" + seed + ".nc");
            Files.writeString(p, PipelineFuzzTest.program(new Random(seed)));
            same(List.of("check", p.toString()), null, Map.of());
            same(List.of("compile", p.toString(), "-o", DMC.toString()), null, Map.of(), DMC, MAP);
            Path m = WORK.resolve("mutated-" + seed + ".nc");
            Files.writeString(m, PipelineFuzzTest.mutated(real, new Random(seed)));
            same(List.of("check", m.toString(), "--caret", "always"), null, Map.of());
        }
    }

    @Test
    void errorsPrintTheSame() throws Exception {
        same(List.of("check", "no-such-program.nc"), null, Map.of());
        same(List.of("check", "--bogus", "samples/turning.nc"), null, Map.of());
        same(List.of("compile"), null, Map.of());
        same(List.of("check", "samples/turning.nc", "--machine", "hass"), null, Map.of());
        Path bad = WORK.resolve("bad.nc");
        Files.writeString(bad, "G21 G90\nG01 X10 Z-5\nG02 X20 Q3\n");
        same(List.of("check", bad.toString()), null, Map.of());
        same(List.of("check", bad.toString()), null, Map.of("LANG", "es_ES.UTF-8"));
        same(List.of("--lang", "es", "compile", bad.toString(), "-o", DMC.toString()), null, Map.of(), DMC, MAP);
        same(List.of("check", "-", "--machine", "thesis-2004"), Files.readAllBytes(Path.of("samples/bishop.nc")), Map.of());
        same(List.of("compile", "-", "-o", "-"), Files.readAllBytes(Path.of("samples/turning.nc")), Map.of());
        same(List.of("check", "-"), new byte[] {'G', '0', 0, (byte) 0xFF, '\n'}, Map.of());
    }

    @Test
    void theStateFileIsTheUsersAloneAndAWrongTokenIsRefused() throws Exception {
        Path file = state.resolve("daemon.state");
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
        int port = 0;
        for (String line : Files.readAllLines(file)) {
            if (line.startsWith("port=")) {
                port = Integer.parseInt(line.substring(5));
            }
        }
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            // one write: the daemon answers the token and closes before reading on, and a later write of
            // ours would then meet a reset socket (a broken pipe under load)
            DataOutputStream out = new DataOutputStream(new java.io.BufferedOutputStream(s.getOutputStream()));
            byte[] token = "0".repeat(64).getBytes(StandardCharsets.UTF_8);
            out.write('T');
            out.writeInt(token.length);
            out.write(token);
            out.write('P');
            out.writeInt(0);
            out.flush();
            DataInputStream in = new DataInputStream(s.getInputStream());
            assertEquals('N', in.read());
            byte[] why = new byte[in.readInt()];
            in.readFully(why);
            assertTrue(new String(why, StandardCharsets.UTF_8).startsWith("refused"));
            assertEquals(-1, in.read()); // and closed
        }
    }

    @Test
    void aStateFileLeftByADeadDaemonIsRemovedAndTheRunGoesCold() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-dead-daemon");
        Process gone = new ProcessBuilder("true").start();
        gone.waitFor();
        int port;
        try (java.net.ServerSocket free = new java.net.ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = free.getLocalPort(); // closed below: nothing answers there
        }
        String dead = "pid=" + gone.pid() + "\nport=" + port + "\ntoken=" + "0".repeat(64)
                + "\njar=" + JAR + "\ndir=" + Path.of("").toAbsolutePath() + "\n";
        Files.writeString(dir.resolve("daemon.state"), dead);
        Run r = client(List.of("check", "samples/turning.nc"), null, Map.of("GCNC_DAEMON_DIR", dir.toString()), JAR, null);
        assertEquals(COLD, r.status(), r.text());
        assertTrue(Files.notExists(dir.resolve("daemon.state")));
        Files.writeString(dir.resolve("daemon.state"), dead);
        Run c = clientC(List.of("check", "samples/turning.nc"), Map.of("GCNC_DAEMON_DIR", dir.toString()), JAR, null);
        assertEquals(COLD, c.status(), "C client: " + c.text());
        assertEquals(0, c.out().length + c.err().length, c.text());
        assertTrue(Files.notExists(dir.resolve("daemon.state")), "C client");
    }

    @Test
    void anotherJarAnotherFolderOrABusyDaemonRunCold() throws Exception {
        Path other = Files.createTempDirectory("gcnc-other-jar").resolve("gcnc.jar");
        Files.copy(JAR, other);
        List<String> args = List.of("check", Path.of("samples/turning.nc").toAbsolutePath().toString());
        Run stale = client(args, null, Map.of(), other, null);
        assertEquals(COLD, stale.status(), stale.text());
        assertEquals(0, stale.out().length + stale.err().length, stale.text());
        // through the launcher, the user gets the cold run's output
        Run launcher = run(List.of("sh", "scripts/gcnc", "check", "samples/turning.nc"), null,
                Map.of("GCNC_JAR", other.toString()), null);
        assertEquals(cold(List.of("check", "samples/turning.nc"), null, Map.of()).text(), launcher.text());

        Run elsewhere = client(args, null, Map.of(), JAR, other.getParent());
        assertEquals(COLD, elsewhere.status(), elsewhere.text());
        for (Run c : List.of(clientC(args, Map.of(), other, null), clientC(args, Map.of(), JAR, other.getParent()))) {
            assertEquals(COLD, c.status(), "C client: " + c.text());
            assertEquals(0, c.out().length + c.err().length, c.text());
        }

        // a run waiting for its standard input keeps the daemon busy: another client is told to go cold
        List<String> c = List.of("python3", "scripts/gcnc-client.py", JAR.toString(), "check", "-");
        ProcessBuilder pb = new ProcessBuilder(c).redirectError(ProcessBuilder.Redirect.DISCARD)
                .redirectOutput(ProcessBuilder.Redirect.DISCARD);
        pb.environment().put("GCNC_DAEMON_DIR", state.toString());
        Process waiting = pb.start();
        try {
            int status = 0;
            // polled: the waiting client's request reaches the daemon a moment after it starts
            for (int i = 0; i < 400 && status != COLD; i++) {
                Thread.sleep(50);
                status = client(args, null, Map.of(), JAR, null).status();
            }
            assertEquals(COLD, status, "a second run while the first waits for its input");
        } finally {
            waiting.getOutputStream().write("G21\nM30\n".getBytes(StandardCharsets.UTF_8));
            waiting.getOutputStream().close();
            assertTrue(waiting.waitFor(60, TimeUnit.SECONDS));
        }
    }

    /**
     * A run that fails inside gcnc before any output (an exception, out of memory) is answered {@code Y}
     * then {@code K} (Server.run: standard input may already flow after {@code Y}): both clients go cold
     * with nothing printed, and through the launcher the user gets the cold run's output (issue 35: they
     * printed "the resident checker stopped during this run" and exited 2). A daemon that answers so,
     * played here on a socket of the test's own, since gcnc has no input left that fails inside it.
     */
    @Test
    void aRunThatFailsInsideGcncBeforeAnyOutputGoesCold() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-failing-daemon");
        try (java.net.ServerSocket fake = new java.net.ServerSocket(0, 8, InetAddress.getLoopbackAddress())) {
            Thread daemon = new Thread(() -> {
                while (!fake.isClosed()) {
                    try (Socket c = fake.accept()) {
                        DataInputStream in = new DataInputStream(c.getInputStream());
                        for (int type = in.read(); type != 'G'; type = in.read()) {
                            if (type < 0) {
                                throw new java.io.EOFException();
                            }
                            in.readFully(new byte[in.readInt()]);
                        }
                        in.readInt();
                        DataOutputStream out = new DataOutputStream(c.getOutputStream());
                        out.write('Y');
                        out.writeInt(0);
                        byte[] why = "failed inside gcnc: java.lang.OutOfMemoryError: Java heap space".getBytes(StandardCharsets.UTF_8);
                        out.write('K');
                        out.writeInt(why.length);
                        out.write(why);
                        out.flush();
                    } catch (IOException e) {
                        // closed: the test is over, or a client went away
                    }
                }
            });
            daemon.setDaemon(true);
            daemon.start();
            Files.writeString(dir.resolve("daemon.state"), "pid=" + ProcessHandle.current().pid() + "\nport=" + fake.getLocalPort()
                    + "\ntoken=" + "0".repeat(64) + "\njar=" + JAR + "\ndir=" + Path.of("").toAbsolutePath() + "\n");
            Map<String, String> env = Map.of("GCNC_DAEMON_DIR", dir.toString());
            Run py = client(List.of("check", "samples/turning.nc"), null, env, JAR, null);
            assertEquals(COLD, py.status(), py.text());
            assertEquals(0, py.out().length + py.err().length, py.text());
            Run c = clientC(List.of("check", "samples/turning.nc"), env, JAR, null);
            assertEquals(COLD, c.status(), "C client: " + c.text());
            assertEquals(0, c.out().length + c.err().length, c.text());
            Run launcher = run(List.of("sh", "scripts/gcnc", "check", "samples/turning.nc"), null, env, null);
            assertEquals(cold(List.of("check", "samples/turning.nc"), null, Map.of()).text(), launcher.text());
        }
    }
}
