package gcnc.controller;

import com.fazecast.jSerialComm.SerialPort;
import java.io.Closeable;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * A virtual controller and a host link to it, over loopback TCP or over a real pseudo-terminal pair made
 * by socat (the host end opened with jSerialComm, as gcnc run opens a serial port). Closing it closes
 * the link, the controller and socat.
 */
final class Links implements Closeable {
    enum Kind { TCP, PTY }

    final VirtualController controller;
    final HostLink host;
    /** The pty pair of a PTY link; null over TCP. */
    private final gcnc.PtyPair pty;

    private Links(VirtualController controller, HostLink host, gcnc.PtyPair pty) {
        this.controller = controller;
        this.host = host;
        this.pty = pty;
    }

    /** Is socat here (setup.sh installs it)? The pty tests need it. */
    static boolean socat() {
        return gcnc.PtyPair.available();
    }

    static Links open(Kind kind, Model model, double speed, List<InjectedFault> faults, Path trace) throws IOException {
        VirtualController.Options o = new VirtualController.Options(model, speed, faults, trace);
        if (kind == Kind.TCP) {
            VirtualController vc = VirtualController.tcp(0, o);
            Socket s = new Socket(InetAddress.getLoopbackAddress(), vc.port());
            s.setSoTimeout(5000);
            return new Links(vc, new HostLink(s.getInputStream(), s.getOutputStream(), s), null);
        }
        gcnc.PtyPair pty;
        try {
            pty = gcnc.PtyPair.open(Files.createTempDirectory("gcnc-pty"), "");
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while socat made the pty pair", e);
        }
        Path controllerEnd = pty.controller;
        Path hostEnd = pty.host;
        VirtualController vc = VirtualController.pty(controllerEnd, o);
        // a factory unit echoes on its serial port until EO 0 (ControllerLinkTest tests that); these tests
        // are about the replies, so they start where a host's EO 0 leaves the port
        vc.controller().echo = false;
        SerialPort port = SerialPort.getCommPort(hostEnd.toString());
        port.setBaudRate(115200);
        if (!port.openPort()) {
            close(pty);
            vc.close();
            throw new IOException("jSerialComm cannot open " + hostEnd + ": error " + port.getLastErrorCode());
        }
        port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, 5000, 0);
        HostLink host = new HostLink(port.getInputStream(), port.getOutputStream(), port::closePort);
        return new Links(vc, host, pty);
    }

    private static void close(gcnc.PtyPair pty) {
        try {
            pty.close();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    static void sleep(long ms) {
        try {
            Thread.sleep(ms);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    @Override
    public void close() {
        try {
            host.close();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } finally {
            controller.close();
            if (pty != null) {
                close(pty);
            }
        }
    }
}
