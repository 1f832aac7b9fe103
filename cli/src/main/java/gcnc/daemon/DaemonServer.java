package gcnc.daemon;

import gcnc.cli.Main;
import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.ByteArrayInputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Semaphore;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The resident checker (issue 23): a warm JVM on the loopback interface that runs {@code check},
 * {@code compile} and {@code simulate} for a client with the client's arguments, standard input,
 * environment and terminal, through the same {@link Main#execute} as a cold run, and sends back
 * the bytes of standard output and standard error and the exit status. A request it cannot run
 * exactly as a cold JVM would is answered "cold" before anything is read or written, and the
 * client then starts a JVM of its own ({@link Requests#coldReason} says which requests those are).
 *
 * <p>One run at a time: a request that comes while one runs is answered "busy", i.e. cold (a
 * second JVM on a 2-core machine is as fast as waiting). Every connection first sends the token of
 * the state file ({@link StateFile}); any other is refused and closed.
 *
 * <p>Started by {@code gcnc daemon start} as {@code java -cp gcnc.jar gcnc.daemon.DaemonServer STATE-DIR},
 * in the folder it serves.
 */
public final class DaemonServer {
    /** How long a client may take to send its request (not its standard input). */
    private static final int HEADER_TIMEOUT_MS = 10_000;
    /**
     * Output held back before any byte is sent: until then a run that fails inside gcnc (a bug's
     * exception, memory) is handed to a cold JVM, which prints exactly what it prints.
     */
    static final int HOLD = 1 << 20;

    private final Path stateDir;
    private final JarIdentity jar;
    private final String dir;
    private final String token;
    private final Semaphore running = new Semaphore(1);
    private final AtomicLong served = new AtomicLong();
    private final long started = System.currentTimeMillis();
    private ServerSocket socket;
    private StateFile state;

    DaemonServer(Path stateDir, JarIdentity jar, String dir, String token) {
        this.stateDir = stateDir;
        this.jar = jar;
        this.dir = dir;
        this.token = token;
    }

    public static void main(String[] args) throws Exception {
        Path stateDir = Path.of(args[0]);
        byte[] secret = new byte[32];
        new SecureRandom().nextBytes(secret);
        DaemonServer s = new DaemonServer(stateDir, JarIdentity.ofRunningJar(), Path.of("").toAbsolutePath().toString(),
                HexFormat.of().formatHex(secret));
        s.serve();
    }

    void serve() throws IOException {
        socket = new ServerSocket(0, 16, InetAddress.getLoopbackAddress());
        Warmup.run(); // before the state file exists: no client waits on a cold JIT
        state = new StateFile(ProcessHandle.current().pid(), socket.getLocalPort(), token, jar.path(), dir);
        state.write(stateDir);
        while (!socket.isClosed()) {
            Socket c;
            try {
                c = socket.accept();
            } catch (IOException e) {
                break; // closed by a stop request
            }
            Thread t = new Thread(() -> handle(c), "gcnc-daemon-client");
            t.setDaemon(true);
            t.start();
        }
    }

    private void handle(Socket c) {
        try (c) {
            c.setSoTimeout(HEADER_TIMEOUT_MS);
            c.setTcpNoDelay(true);
            DataInputStream in = new DataInputStream(new BufferedInputStream(c.getInputStream(), 1 << 16));
            DataOutputStream out = new DataOutputStream(new BufferedOutputStream(c.getOutputStream(), 1 << 16));
            Frames.Frame first = Frames.read(in);
            if (first.type() != 'T' || !MessageDigest.isEqual(first.data(), token.getBytes(java.nio.charset.StandardCharsets.UTF_8))) {
                Frames.write(out, 'N', "refused: wrong token");
                out.flush();
                return;
            }
            Frames.Frame what = Frames.read(in);
            switch (what.type()) {
                case 'P' -> {
                    Frames.write(out, 'P', status());
                    out.flush();
                }
                case 'Q' -> {
                    Frames.write(out, 'X', "0");
                    out.flush();
                    stop();
                }
                case 'R' -> run(Requests.read(in), in, out, c);
                default -> {
                    Frames.write(out, 'K', "unknown request");
                    out.flush();
                }
            }
        } catch (IOException | RuntimeException e) {
            // the client went away or spoke another protocol: nothing to answer
        }
    }

    private String status() {
        long minutes = (System.currentTimeMillis() - started) / 60_000;
        return "running, pid " + ProcessHandle.current().pid() + ", port " + socket.getLocalPort() + ", serving " + dir
                + ", jar " + jar.path() + (jar.changed() ? " (REPLACED since the daemon started: clients run cold;"
                + " restart it with gcnc daemon start)" : "") + ", up " + minutes + " min, " + served.get() + " runs served";
    }

    private void stop() {
        state.remove(stateDir);
        try {
            socket.close();
        } catch (IOException e) {
            // closing anyway
        }
        System.exit(0);
    }

    private void run(Requests.Request r, DataInputStream in, DataOutputStream out, Socket c) throws IOException {
        String cold = Requests.coldReason(r, jar, dir);
        if (cold == null && !running.tryAcquire()) {
            cold = "busy";
        }
        if (cold != null) {
            Frames.write(out, 'K', cold);
            out.flush();
            return;
        }
        boolean[] held = {true};
        Runnable release = () -> {
            if (held[0]) {
                held[0] = false;
                running.release();
            }
        };
        try {
            Frames.write(out, 'Y', "");
            out.flush();
            c.setSoTimeout(0); // standard input may come slowly, from a pipe
            Outputs outputs = new Outputs(out);
            InputStream stdin = r.stdin() ? new StdinFrames(in) : new ByteArrayInputStream(new byte[0]);
            int status;
            Throwable[] failed = new Throwable[1];
            try {
                status = Main.execute(r.argv().toArray(new String[0]), new Main.Invocation(stdin, outputs.stdout(),
                        outputs.stderr(), r.env(), r.console(), r::isStandardOutput), (e, cl, parsed) -> {
                            failed[0] = e; // a cold JVM prints it with its own stack trace: let one
                            return 2;
                        });
                if (failed[0] != null) {
                    throw failed[0];
                }
            } catch (Throwable e) {
                if (!outputs.sent() && !r.stdin()) {
                    // nothing sent yet: the run goes cold, with the user's own heap, verdict and stack trace
                    outputs.discard();
                    Frames.write(out, 'K', "failed inside gcnc: " + e);
                    out.flush();
                    return;
                }
                // part of the output is out: out of memory ends as a cold run ends (Main.main), E506 and
                // status 2 (the run's objects are unreachable by now, and the daemon serves on); anything
                // else says the daemon failed
                outputs.flushAll();
                Frames.write(out, '2', e instanceof OutOfMemoryError ? Main.outOfMemoryLine(r.argv().toArray(new String[0]), r.env())
                        : "gcnc: the resident checker failed during this run (" + e + "); run it again with GCNC_DAEMON=off\n");
                status = 2;
            }
            outputs.flushAll();
            served.incrementAndGet();
            // free before the client hears the end: a client that runs again at once is served, not told "busy"
            release.run();
            Frames.write(out, 'X', Integer.toString(status));
            out.flush();
        } finally {
            release.run();
        }
    }

    /**
     * Standard output and error of one run as frames: held back (up to {@link #HOLD} bytes in all)
     * until the run ends or grows past that, so that a run failing inside gcnc can still go cold.
     */
    static final class Outputs {
        private final DataOutputStream out;
        private final List<Object[]> held = new ArrayList<>();
        private int heldBytes;
        private boolean streaming;

        Outputs(DataOutputStream out) {
            this.out = out;
        }

        OutputStream stdout() {
            return stream('1');
        }

        OutputStream stderr() {
            return stream('2');
        }

        boolean sent() {
            return streaming;
        }

        void discard() {
            held.clear();
        }

        private OutputStream stream(char type) {
            return new OutputStream() {
                @Override
                public void write(int b) throws IOException {
                    write(new byte[] {(byte) b}, 0, 1);
                }

                @Override
                public void write(byte[] b, int off, int len) throws IOException {
                    synchronized (Outputs.this) {
                        for (int at = off; at < off + len; at += 1 << 16) {
                            int n = Math.min(1 << 16, off + len - at);
                            if (streaming) {
                                Frames.write(out, type, b, at, n);
                            } else {
                                held.add(new Object[] {type, java.util.Arrays.copyOfRange(b, at, at + n)});
                                heldBytes += n;
                                if (heldBytes > HOLD) {
                                    flushAll();
                                }
                            }
                        }
                    }
                }

                @Override
                public void flush() throws IOException {
                    synchronized (Outputs.this) {
                        if (streaming) {
                            out.flush();
                        }
                    }
                }
            };
        }

        /** Sends what is held and streams from then on. */
        synchronized void flushAll() throws IOException {
            for (Object[] h : held) {
                byte[] b = (byte[]) h[1];
                Frames.write(out, (Character) h[0], b, 0, b.length);
            }
            held.clear();
            streaming = true;
            out.flush();
        }
    }

    /** The client's standard input, as it sends it in frames ({@code i} chunks, then {@code z}). */
    static final class StdinFrames extends InputStream {
        private final DataInputStream in;
        private byte[] chunk = new byte[0];
        private int at;
        private boolean ended;

        StdinFrames(DataInputStream in) {
            this.in = in;
        }

        @Override
        public int read() throws IOException {
            byte[] one = new byte[1];
            return read(one, 0, 1) < 0 ? -1 : one[0] & 0xFF;
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            while (at == chunk.length) {
                if (ended) {
                    return -1;
                }
                Frames.Frame f = Frames.read(in);
                if (f.type() == 'z') {
                    ended = true;
                } else {
                    chunk = f.data();
                    at = 0;
                }
            }
            int n = Math.min(len, chunk.length - at);
            System.arraycopy(chunk, at, b, off, n);
            at += n;
            return n;
        }
    }

    /** Used by {@link Requests}: the environment of a request as a map. */
    static Map<String, String> env(List<String> entries) {
        Map<String, String> m = new HashMap<>();
        for (String e : entries) {
            int eq = e.indexOf('=');
            if (eq > 0) {
                m.put(e.substring(0, eq), e.substring(eq + 1));
            }
        }
        return m;
    }
}
