package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.controller.VirtualController;
import gcnc.tables.GalilConformance;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Set;
import java.util.TreeMap;
import org.junit.jupiter.api.Test;

/**
 * Everything {@code gcnc run} sends has a row in tables/galil_conformance.csv (issue 30): full runs against
 * the virtual controller through a link that records every byte the sender writes (the download's program
 * lines too), in both forms, with a feed override, and stopped by a refused command (the stop path: ST,
 * TC1, _ED, _SC). The test names what has no row.
 */
class SenderConformanceTest {
    /** A TCP relay to the controller that keeps what the host sends; one connection, as gcnc run opens. */
    private static final class Recorder implements AutoCloseable {
        final ServerSocket server;
        final ByteArrayOutputStream sent = new ByteArrayOutputStream();
        private final Thread relay;

        Recorder(int controllerPort) throws IOException {
            server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress());
            relay = new Thread(() -> {
                try (Socket host = server.accept(); Socket galil = new Socket(InetAddress.getLoopbackAddress(), controllerPort)) {
                    Thread back = pump(galil.getInputStream(), host.getOutputStream(), null);
                    pump(host.getInputStream(), galil.getOutputStream(), sent).join();
                    galil.shutdownOutput();
                    back.join(5000);
                } catch (IOException | InterruptedException e) {
                    // the run's own assertions report a broken link
                }
            });
            relay.setDaemon(true);
            relay.start();
        }

        private static Thread pump(InputStream in, OutputStream out, ByteArrayOutputStream copy) {
            Thread t = new Thread(() -> {
                byte[] buf = new byte[4096];
                try {
                    for (int n = in.read(buf); n >= 0; n = in.read(buf)) {
                        if (copy != null) {
                            synchronized (copy) {
                                copy.write(buf, 0, n);
                            }
                        }
                        out.write(buf, 0, n);
                        out.flush();
                    }
                } catch (IOException e) {
                    // the peer closed
                }
            });
            t.setDaemon(true);
            t.start();
            return t;
        }

        String address() {
            return "127.0.0.1:" + server.getLocalPort();
        }

        /** What the host sent, once the run has closed its link. */
        String sent() throws InterruptedException {
            relay.join(10_000);
            synchronized (sent) {
                return sent.toString(StandardCharsets.ISO_8859_1);
            }
        }

        @Override
        public void close() throws IOException {
            server.close();
        }
    }

    /** The names of what a run sent with no row, each with the command it was in. */
    private static void missing(String sent, TreeMap<String, String> into) throws IOException {
        Set<String> names = GalilConformance.names(GalilConformance.rows());
        for (String piece : sent.split("[\r\n]")) {
            String command = piece.replaceFirst("^\\\\+", ""); // the download's terminator before the marker query
            for (String n : GalilConformance.namesOfLine(command)) {
                if (!names.contains(n)) {
                    into.putIfAbsent(n, gcnc.send.GalilClient.printable(command));
                }
            }
        }
    }

    private static String run(VirtualController vc, String keys, String... options) throws Exception {
        Path p = RunOnControllerTest.part(RunOnControllerTest.PART);
        try (Recorder r = new Recorder(vc.port())) {
            java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of("run", p.toString(), "--machine", "haas",
                    "--tcp", r.address()));
            args.addAll(java.util.List.of(options));
            RunOnControllerTest.Run run = RunOnControllerTest.gcnc(keys, args.toArray(new String[0]));
            String sent = r.sent();
            assertTrue(sent.contains("XQ #") || sent.contains("BGS"), "the run reached its motion: " + run.all());
            return sent;
        }
    }

    @Test
    void everyCommandARunSendsHasARow() throws Exception {
        TreeMap<String, String> missing = new TreeMap<>();
        try (VirtualController vc = RunOnControllerTest.fast(RunOnControllerTest.model("DMC-4040"))) {
            RunOnControllerTest.homed(vc);
            String program = run(vc, "+\n", "--poll", "20");
            assertTrue(program.startsWith("\u0012\u0016\r"), "the revision query first");
            assertTrue(program.contains("\rDL\r#GCNC"), "the program form downloads");
            missing(program, missing);
        }
        try (VirtualController vc = RunOnControllerTest.fast(RunOnControllerTest.model("DMC-4040"))) {
            RunOnControllerTest.homed(vc);
            String stream = run(vc, "", "--poll", "20", "--form", "stream");
            assertTrue(stream.contains("\rVP "), "the stream form sends its segments");
            missing(stream, missing);
        }
        try (VirtualController vc = RunOnControllerTest.controller(RunOnControllerTest.model("DMC-4040"), "reject=45")) {
            RunOnControllerTest.homed(vc);
            String stopped = run(vc, "", "--poll", "50");
            assertTrue(stopped.contains("\rST\r"), "a refused command stops the machine");
            missing(stopped, missing);
        }
        assertEquals(new TreeMap<String, String>(), missing, "sent by gcnc run without a row in galil_conformance.csv");
    }
}
