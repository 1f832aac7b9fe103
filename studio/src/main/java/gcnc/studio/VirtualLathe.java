package gcnc.studio;

import gcnc.controller.Model;
import gcnc.controller.VirtualController;
import gcnc.machine.MachineProfile;
import gcnc.machine.Plane;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.List;

/**
 * The virtual Galil behind the Run screen's "virtual controller" (gcnc.controller, the one
 * {@code gcnc controller --virtual} serves): started inside the studio on a free loopback port at the
 * first run that asks for it, of the model the machine profile names, and kept until the studio
 * stops, so that a run stopped half way can be resumed on it. The run reaches it over TCP like any
 * Galil: nothing of the run knows it is virtual.
 */
final class VirtualLathe implements AutoCloseable {
    private final double speed;
    private VirtualController controller;
    private String model;

    /** {@code speed}: how many times faster than real time it runs the motion (gcnc studio --virtual-speed). */
    VirtualLathe(double speed) {
        this.speed = speed;
    }

    /** Its address, {@code 127.0.0.1:PORT}; started (or restarted as another model) for {@code profile}. */
    synchronized String address(MachineProfile profile) throws IOException {
        String want = profile.galilModel().name();
        if (controller != null && !want.equals(model)) {
            controller.close(); // Configure saved a profile of another Galil model
            controller = null;
        }
        if (controller == null) {
            Model m = Model.named(want).orElse(Model.standard());
            controller = VirtualController.tcp(0, new VirtualController.Options(m, speed, List.of(), null));
            model = want;
        }
        return "127.0.0.1:" + controller.port();
    }

    /**
     * Defines the axes at the profile's home ({@code DP}), as a machine's homing routine leaves them:
     * a run starts where the simulator verified it from (docs/run.md, "Home"). Sent over the command
     * port, as an operator's terminal would.
     */
    synchronized void home(MachineProfile profile) throws IOException {
        String address = address(profile);
        Plane plane = Plane.of(profile);
        double[] g = plane.galil(profile.home().x(), profile.home().z());
        // DP's fields are the channels in order: the plane's two may have others between them (DP a,,b)
        String[] fields = new String[plane.second() + 1];
        java.util.Arrays.fill(fields, "");
        fields[plane.first()] = Long.toString(Math.round(g[0]));
        fields[plane.second()] = Long.toString(Math.round(g[1]));
        String reply = tell(address, "DP " + String.join(",", fields));
        if (!reply.endsWith(":")) {
            throw new IOException("the virtual controller refused DP (" + reply.strip() + ")");
        }
    }

    /** One command on a connection of its own; the reply up to its {@code :} or {@code ?}. */
    private static String tell(String address, String command) throws IOException {
        int port = Integer.parseInt(address.substring(address.indexOf(':') + 1));
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            s.setSoTimeout(3000);
            s.getOutputStream().write((command + "\r").getBytes(StandardCharsets.ISO_8859_1));
            StringBuilder b = new StringBuilder();
            InputStream in = s.getInputStream();
            for (int c = in.read(); c >= 0; c = in.read()) {
                b.append((char) c);
                if (c == ':' || c == '?') {
                    break;
                }
            }
            return b.toString();
        }
    }

    @Override
    public synchronized void close() {
        if (controller != null) {
            controller.close();
            controller = null;
        }
    }
}
