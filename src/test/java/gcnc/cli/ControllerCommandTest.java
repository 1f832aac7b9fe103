package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** {@code gcnc controller --virtual}: its usage errors (exit 2) and a real launch on a free port. */
class ControllerCommandTest {
    @Test
    void usageErrorsExitTwoAndSayWhatToGive() {
        CliTest.Run noLink = CliTest.gcnc("controller", "--virtual");
        assertEquals(2, noLink.status(), noLink.err());
        assertTrue(noLink.err().contains("--tcp") && noLink.err().contains("--pty"), noLink.err());
        CliTest.Run fault = CliTest.gcnc("controller", "--virtual", "--tcp", "0", "--fault", "stall=0");
        assertEquals(2, fault.status());
        assertTrue(fault.err().contains("'stall=0' is not a fault: give garbage-after=BYTES"), fault.err());
        CliTest.Run model = CliTest.gcnc("controller", "--virtual", "--tcp", "0", "--model", "DMC9999");
        assertEquals(2, model.status());
        assertTrue(model.err().contains("'DMC9999' is not a Galil model gcnc knows (tables/galil_models.csv): DMC-4010,"),
                model.err());
        CliTest.Run pty = CliTest.gcnc("controller", "--virtual", "--pty", "/nonexistent/galil");
        assertEquals(2, pty.status());
        assertTrue(pty.err().contains("socat -d -d pty,raw,echo=0,link=/nonexistent/galil"), pty.err());
        CliTest.Run spindle = CliTest.gcnc("controller", "--virtual", "--tcp", "0", "--spindle", "410");
        assertEquals(2, spindle.status());
        assertTrue(spindle.err().contains("--spindle 410: give the drive's r/min per volt and the encoder's counts per revolution"),
                spindle.err());
        CliTest.Run spanish = CliTest.gcnc("controller", "--virtual", "--tcp", "0", "--speed", "0", "--lang", "es");
        assertEquals(2, spanish.status());
        assertTrue(spanish.err().contains("indique un número mayor que 0"), spanish.err());
    }

    @Test
    void aTakenPortIsExitTwo() throws IOException {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            CliTest.Run r = CliTest.gcnc("controller", "--virtual", "--tcp", String.valueOf(taken.getLocalPort()));
            assertEquals(2, r.status());
            assertTrue(r.err().contains("cannot start the virtual controller on 127.0.0.1:" + taken.getLocalPort()), r.err());
        }
    }

    @Test
    void itServesOnTheLoopbackUntilStopped() throws Exception {
        Process p = new ProcessBuilder("java", "-jar", "build/libs/gcnc.jar", "controller", "--virtual", "--tcp", "0",
                "--model", "dmc-4030").redirectErrorStream(true).start();
        try {
            BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
            String first = out.readLine();
            Matcher m = Pattern.compile("a virtual DMC4030 Rev 1.2d on 127.0.0.1:(\\d+),").matcher(String.valueOf(first));
            assertTrue(m.find(), first);
            try (Socket s = new Socket(InetAddress.getLoopbackAddress(), Integer.parseInt(m.group(1)))) {
                s.setSoTimeout(5000);
                s.getOutputStream().write("\u0012\u0016\r".getBytes(StandardCharsets.ISO_8859_1));
                InputStream in = s.getInputStream();
                StringBuilder reply = new StringBuilder();
                int c;
                while ((c = in.read()) >= 0 && c != ':') {
                    reply.append((char) c);
                }
                assertEquals("DMC4030 Rev 1.2d\r\n", reply.toString());
            }
        } finally {
            p.destroy();
            assertTrue(p.waitFor(10, TimeUnit.SECONDS));
        }
        assertTrue(p.exitValue() == 0 || p.exitValue() == 143, "stopped by SIGTERM, its hook closing the controller: " + p.exitValue());
    }
}
