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
    private final Process socat;
    private final Path dir;

    private Links(VirtualController controller, HostLink host, Process socat, Path dir) {
        this.controller = controller;
        this.host = host;
        this.socat = socat;
        this.dir = dir;
    }

    /** Is socat here (setup.sh installs it)? The pty tests need it. */
    static boolean socat() {
        for (String d : System.getenv().getOrDefault("PATH", "/usr/bin").split(":")) {
            if (Files.isExecutable(Path.of(d, "socat"))) {
                return true;
            }
        }
        return false;
    }

    static Links open(Kind kind, Model model, double speed, List<Fault> faults, Path trace) throws IOException {
        VirtualController.Options o = new VirtualController.Options(model, speed, faults, trace);
        if (kind == Kind.TCP) {
            VirtualController vc = VirtualController.tcp(0, o);
            Socket s = new Socket(InetAddress.getLoopbackAddress(), vc.port());
            s.setSoTimeout(5000);
            return new Links(vc, new HostLink(s.getInputStream(), s.getOutputStream(), s), null, null);
        }
        Path dir = Files.createTempDirectory("gcnc-pty");
        Path controllerEnd = dir.resolve("galil");
        Path hostEnd = dir.resolve("host");
        Process socat = new ProcessBuilder("socat", "-d", "-d", "pty,raw,echo=0,link=" + controllerEnd,
                "pty,raw,echo=0,link=" + hostEnd).redirectErrorStream(true).redirectOutput(dir.resolve("socat.log").toFile())
                .start();
        long until = System.nanoTime() + 5_000_000_000L;
        while (!(Files.exists(controllerEnd) && Files.exists(hostEnd)) && System.nanoTime() < until) {
            sleep(10);
        }
        VirtualController vc = VirtualController.pty(controllerEnd, o);
        SerialPort port = SerialPort.getCommPort(hostEnd.toString());
        port.setBaudRate(115200);
        if (!port.openPort()) {
            socat.destroy();
            vc.close();
            throw new IOException("jSerialComm cannot open " + hostEnd + ": error " + port.getLastErrorCode());
        }
        port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, 5000, 0);
        HostLink host = new HostLink(port.getInputStream(), port.getOutputStream(), port::closePort);
        return new Links(vc, host, socat, dir);
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
            if (socat != null) {
                socat.destroy();
                try {
                    socat.waitFor();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }
    }
}
