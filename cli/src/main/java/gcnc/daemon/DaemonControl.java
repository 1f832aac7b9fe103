package gcnc.daemon;

import java.io.BufferedInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.File;
import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * {@code gcnc daemon start|stop|status} as the command line runs them: find the server through its
 * state file, ask it, start one. Every answer is one line for the user.
 */
public final class DaemonControl {
    /** What an action ends with: the line to print and the exit status. */
    public record Outcome(String line, int status) {
    }

    /** Exit status of {@code status} when no daemon runs (as LSB init scripts say "not running"). */
    public static final int NOT_RUNNING = 3;
    private static final int WAIT_FOR_START_MS = 120_000;

    private final Path folder;

    public DaemonControl(Map<String, String> env) {
        this.folder = StateFile.folder(env);
    }

    /** The daemon's own description of itself, or empty when none answers with the state file's token. */
    Optional<String> ping() {
        Optional<StateFile> s = StateFile.read(folder);
        if (s.isEmpty()) {
            return Optional.empty();
        }
        try (Socket c = connect(s.get())) {
            DataOutputStream out = new DataOutputStream(c.getOutputStream());
            Frames.write(out, 'T', s.get().token());
            Frames.write(out, 'P', "");
            out.flush();
            Frames.Frame f = Frames.read(new DataInputStream(new BufferedInputStream(c.getInputStream())));
            return f.type() == 'P' ? Optional.of(f.text()) : Optional.empty();
        } catch (IOException e) {
            return Optional.empty();
        }
    }

    private static Socket connect(StateFile s) throws IOException {
        Socket c = new Socket();
        c.connect(new InetSocketAddress(InetAddress.getLoopbackAddress(), s.port()), 2000);
        c.setSoTimeout(10_000);
        return c;
    }

    public Outcome status() {
        Optional<String> running = ping();
        return running.map(r -> new Outcome("gcnc daemon: " + r, 0))
                .orElseGet(() -> new Outcome("gcnc daemon: not running (state in " + folder + ")", NOT_RUNNING));
    }

    public Outcome stop() {
        Optional<StateFile> s = StateFile.read(folder);
        if (s.isEmpty() || ping().isEmpty()) {
            s.ifPresent(st -> st.remove(folder)); // a state file nothing answers for
            return new Outcome("gcnc daemon: not running", 0);
        }
        try (Socket c = connect(s.get())) {
            DataOutputStream out = new DataOutputStream(c.getOutputStream());
            Frames.write(out, 'T', s.get().token());
            Frames.write(out, 'Q', "");
            out.flush();
            Frames.read(new DataInputStream(c.getInputStream()));
        } catch (IOException e) {
            // it stopped while answering
        }
        waitFor(s.get().pid());
        return new Outcome("gcnc daemon: stopped (pid " + s.get().pid() + ")", 0);
    }

    private static void waitFor(long pid) {
        Optional<ProcessHandle> p = ProcessHandle.of(pid);
        for (int i = 0; i < 100 && p.isPresent() && p.get().isAlive(); i++) {
            sleep(50);
        }
    }

    /**
     * Starts a server in {@code dir} running {@code jar} with {@code java}; one already serving that
     * folder with that jar is left running, any other stopped first.
     */
    public Outcome start(String java, Path jar, Path dir) {
        String realJar;
        try {
            realJar = jar.toRealPath().toString();
        } catch (IOException e) {
            return new Outcome("gcnc daemon: cannot read " + jar + ": " + e.getMessage(), 2);
        }
        Optional<StateFile> old = StateFile.read(folder);
        String replaced = "";
        if (old.isPresent() && ping().isPresent()) {
            Optional<String> st = ping();
            if (old.get().dir().equals(dir.toString()) && old.get().jar().equals(realJar)
                    && st.isPresent() && !st.get().contains("REPLACED")) {
                return new Outcome("gcnc daemon: already " + st.get(), 0);
            }
            stop();
            replaced = " (the one serving " + old.get().dir() + " stopped)";
        }
        List<String> command = new ArrayList<>();
        if (Files.isExecutable(Path.of("/usr/bin/setsid"))) {
            command.add("/usr/bin/setsid"); // its own session: closing the terminal does not stop it
        }
        // the launcher's heap (scripts/gcnc): small, growing only when a request needs it;
        // GCNC_DAEMON_JAVA_OPTS replaces these options (as GCNC_JAVA_OPTS does for a cold run)
        String opts = System.getenv("GCNC_DAEMON_JAVA_OPTS");
        command.add(java);
        command.addAll(opts == null || opts.isBlank() ? List.of("-XX:+UseSerialGC", "-Xmn48m", "-Xms64m", "-Xmx512m")
                : List.of(opts.strip().split("\\s+")));
        command.addAll(List.of("-cp", realJar, DaemonServer.class.getName(), folder.toString()));
        Path log = folder.resolve("daemon.log");
        Process p;
        try {
            Files.createDirectories(folder);
            p = new ProcessBuilder(command).directory(dir.toFile()).redirectInput(new File("/dev/null"))
                    .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        } catch (IOException e) {
            return new Outcome("gcnc daemon: cannot start " + java + ": " + e.getMessage(), 2);
        }
        for (int waited = 0; waited < WAIT_FOR_START_MS; waited += 100) {
            Optional<StateFile> s = StateFile.read(folder);
            if (s.isPresent() && (old.isEmpty() || !s.get().token().equals(old.get().token())) && ping().isPresent()) {
                return new Outcome("gcnc daemon: started, pid " + s.get().pid() + ", serving " + dir + replaced, 0);
            }
            if (!p.isAlive() && !Files.isExecutable(Path.of("/usr/bin/setsid"))) {
                break;
            }
            sleep(100);
        }
        return new Outcome("gcnc daemon: did not start (see " + log + ")", 2);
    }

    private static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
