package gcnc.controller;

import java.io.Closeable;
import java.io.FileInputStream;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.Writer;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * {@code gcnc controller --virtual}: a {@link VirtualGalil} behind a transport, with a clock that runs it in
 * real time times {@code speed}. TCP binds 127.0.0.1 only and takes any number of connections (Galil's
 * Ethernet handles); the pty transport opens one end of a pty pair (socat's) and, when the far side goes
 * away, waits for the path to come back and opens it again. A disconnect fault closes a TCP connection
 * (the host sees it closed and may connect again); on the pty, where a closed end is invisible to the
 * host behind socat, it makes the controller go silent for good, as a serial line whose cable is pulled.
 * Faults and trace as in {@link Options}.
 */
public final class VirtualController implements Closeable {
    /**
     * What the command line gives: model, how much faster than real time, faults, trace file (or null).
     * A speed of 0 (not offered on the command line) starts no clock: a test turns it with
     * {@code controller().advance(seconds)} and the run, times and buffer states too, is then a function
     * of the commands alone.
     */
    public record Options(Model model, double speed, List<InjectedFault> faults, Path trace, double spindleRate) {
        /** With the haas profile's spindle drive and encoder ({@link VirtualGalil#SPINDLE_RATE}). */
        public Options(Model model, double speed, List<InjectedFault> faults, Path trace) {
            this(model, speed, faults, trace, VirtualGalil.SPINDLE_RATE);
        }

        /** The spindle encoder's counts a second per volt of OF: r/min per volt × counts per revolution / 60. */
        public static double spindleRate(double rpmPerVolt, int countsPerRev) {
            return rpmPerVolt * countsPerRev / 60.0;
        }
    }

    private final VirtualGalil controller;
    private final Faults faults;
    private final double speed;
    private final Thread clock;
    private volatile boolean closed;
    private ServerSocket server;
    private volatile Closeable ptyLink;

    private VirtualController(Options o) throws IOException {
        Writer trace = o.trace() == null ? null : Files.newBufferedWriter(o.trace(), StandardCharsets.UTF_8);
        this.controller = new VirtualGalil(o.model(), o.faults(), trace, o.spindleRate());
        this.faults = new Faults(o.faults());
        this.speed = o.speed();
        this.clock = new Thread(this::tick, "gcnc-controller-clock");
        clock.setDaemon(true);
    }

    /** Listens on 127.0.0.1:{@code port} (0: a free port, see {@link #port}). */
    public static VirtualController tcp(int port, Options o) throws IOException {
        VirtualController v = new VirtualController(o);
        v.server = new ServerSocket(port, 8, InetAddress.getLoopbackAddress());
        Thread accept = new Thread(v::accept, "gcnc-controller-accept");
        accept.setDaemon(true);
        accept.start();
        v.startClock();
        return v;
    }

    /** Serves the pty at {@code path} (a socat {@code link=}); IOException when it cannot be opened now. */
    public static VirtualController pty(Path path, Options o) throws IOException {
        VirtualController v = new VirtualController(o);
        if (!Files.exists(path)) {
            throw new java.nio.file.NoSuchFileException(path.toString());
        }
        Thread serve = new Thread(() -> v.servePty(path), "gcnc-controller-pty");
        serve.setDaemon(true);
        serve.start();
        v.startClock();
        return v;
    }

    private void startClock() {
        if (speed > 0) {
            clock.start();
        }
    }

    public int port() {
        return server == null ? -1 : server.getLocalPort();
    }

    public VirtualGalil controller() {
        return controller;
    }

    private void accept() {
        while (!closed) {
            try {
                Socket s = server.accept();
                s.setTcpNoDelay(true);
                char handle = controller.openHandle();
                if (handle == 0) {
                    s.close(); // all eight Ethernet handles are taken (COMALL TH lists IHA-IHH)
                    continue;
                }
                Connection c = new Connection(controller, s.getInputStream(), s.getOutputStream(), faults, s, handle);
                Thread t = new Thread(c::serve, "gcnc-controller-tcp");
                t.setDaemon(true);
                t.start();
            } catch (IOException e) {
                if (closed) {
                    return;
                }
            }
        }
    }

    private void servePty(Path path) {
        while (!closed) {
            if (!Files.exists(path)) {
                pause(50);
                continue;
            }
            try (FileInputStream in = new FileInputStream(path.toFile());
                 FileOutputStream out = new FileOutputStream(path.toFile())) {
                Closeable link = () -> {
                    in.close();
                    out.close();
                };
                ptyLink = link;
                if (new Connection(controller, in, out, faults, link, 'S').serve()) {
                    // a serial line whose cable is pulled: the host hears nothing more, ever; the motion goes on
                    return;
                }
            } catch (IOException e) {
                // the pty went away between the check and the open
            }
            ptyLink = null;
            // after a disconnect the far end needs a moment to see it before the path is opened again
            pause(500);
        }
    }

    private static void pause(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The clock: every millisecond of real time runs {@code speed} milliseconds of controller time. */
    private void tick() {
        long last = System.nanoTime();
        while (!closed) {
            pause(1);
            long now = System.nanoTime();
            // a long pause of this JVM (a collection) runs at most 50 ms of real time at once
            double dt = Math.min(0.05, (now - last) / 1e9) * speed;
            last = now;
            // in slices of 10 ms of controller time, so that at a high --speed a command from the host
            // waits for one slice, not for the whole tick
            while (dt > 1e-12 && !closed) {
                double slice = Math.min(dt, 0.01);
                controller.letCommandsIn();
                controller.advance(slice);
                dt -= slice;
            }
        }
    }

    @Override
    public void close() {
        closed = true;
        try {
            if (server != null) {
                server.close();
            }
            Closeable p = ptyLink;
            if (p != null) {
                p.close();
            }
        } catch (IOException e) {
            // closing anyway
        }
        try {
            if (clock.isAlive()) {
                clock.join(1000);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        controller.close();
    }
}
