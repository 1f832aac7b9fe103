package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Files;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The virtual controller's ports as COMALL describes them (issue 30): the serial port echoes until
 * {@code EO 0} ("This command is defaulted to EO1"), Ethernet never echoes and refuses EO; unsolicited
 * messages go to the CF port only ("The CF command sets the default communication port for routing
 * unsolicited messages"), the serial port at power-up; commands "Not Valid in terminal" are refused from
 * the host with TC 2 (tables/galil_terminal.csv).
 */
class ProtocolPortsTest {
    private static VirtualController.Options options(String... faults) {
        List<InjectedFault> f = new java.util.ArrayList<>();
        for (String s : faults) {
            f.add(InjectedFault.parse(s));
        }
        return new VirtualController.Options(Model.standard(), 20, f, null);
    }

    @Test
    void aFactoryUnitEchoesOnItsSerialPortUntilEo0() throws Exception {
        assumeTrue(Links.socat(), "socat (setup.sh installs it)");
        try (gcnc.PtyPair pty = gcnc.PtyPair.open(Files.createTempDirectory("gcnc-pty"), "");
             VirtualController vc = VirtualController.pty(pty.controller, options());
             var io = java.nio.channels.FileChannel.open(pty.host, java.nio.file.StandardOpenOption.READ,
                     java.nio.file.StandardOpenOption.WRITE)) {
            assertEquals("MG 7\r 7.0000\r\n:", exchange(io, "MG 7"), "every byte echoed, then the reply");
            assertEquals("EO 0\r:", exchange(io, "EO 0"), "EO 0 is echoed itself, then echo is off");
            assertEquals(" 7.0000\r\n:", exchange(io, "MG 7"));
            assertEquals(":", exchange(io, "EO 1"));
            assertEquals("MG 7\r 7.0000\r\n:", exchange(io, "MG 7"), "EO 1: the echo is back");
        }
    }

    /** Writes a command and reads until the reply's colon (a colon after the echo). */
    private static String exchange(java.nio.channels.FileChannel io, String command) throws Exception {
        io.write(java.nio.ByteBuffer.wrap((command + "\r").getBytes(java.nio.charset.StandardCharsets.ISO_8859_1)));
        StringBuilder b = new StringBuilder();
        java.nio.ByteBuffer one = java.nio.ByteBuffer.allocate(64);
        long until = System.currentTimeMillis() + 3000;
        while (System.currentTimeMillis() < until && !(b.toString().endsWith(":") && b.length() > 0
                && (b.length() == 1 || b.charAt(b.length() - 2) == '\r' || b.charAt(b.length() - 2) == '\n'))) {
            one.clear();
            int n = io.read(one);
            for (int i = 0; i < n; i++) {
                b.append((char) one.get(i));
            }
        }
        return b.toString();
    }

    @Test
    void ethernetNeverEchoesAndRefusesEo() throws Exception {
        try (VirtualController vc = VirtualController.tcp(0, options());
             Socket s = new Socket(InetAddress.getLoopbackAddress(), vc.port())) {
            s.setSoTimeout(3000);
            HostLink h = new HostLink(s.getInputStream(), s.getOutputStream(), s);
            assertEquals(" 7.0000\r\n:", h.send("MG 7"));
            assertEquals("?", h.send("EO 0"), "accepted over the serial port only");
            assertEquals(" 7.0000\r\n:", h.send("MG 7"));
        }
    }

    @Test
    void anEchoEthernetFaultEchoesOverTcp() throws Exception {
        try (VirtualController vc = VirtualController.tcp(0, options("echo-ethernet=1"));
             Socket s = new Socket(InetAddress.getLoopbackAddress(), vc.port())) {
            s.setSoTimeout(3000);
            HostLink h = new HostLink(s.getInputStream(), s.getOutputStream(), s);
            assertEquals("MG 7\r 7.0000\r\n:", h.send("MG 7"));
        }
    }

    @Test
    void unsolicitedMessagesGoToTheCfPortOnly() throws Exception {
        try (VirtualController vc = VirtualController.tcp(0, options());
             Socket a = new Socket(InetAddress.getLoopbackAddress(), vc.port());
             Socket b = new Socket(InetAddress.getLoopbackAddress(), vc.port())) {
            a.setSoTimeout(3000);
            b.setSoTimeout(3000);
            HostLink ha = new HostLink(a.getInputStream(), a.getOutputStream(), a);
            HostLink hb = new HostLink(b.getInputStream(), b.getOutputStream(), b);
            assertEquals(" 83.0000\r\n:", ha.send("MG _CF"), "S, the main serial port, at power-up (COMALL CF)");
            assertEquals("IHA\r\n:", ha.send("WH"));
            assertEquals("IHB\r\n:", hb.send("WH"));
            assertEquals("::", ha.download("#hello\r\nMG \"HELLO\"\r\nEN\r\n"));
            assertEquals(":", ha.send("XQ #hello,1"));
            assertTrue(ha.awaitThreadEnd(1, 3));
            assertTrue(!new String(ha.raw.toByteArray(), java.nio.charset.StandardCharsets.ISO_8859_1).contains("HELLO"),
                    "CF S: not on an Ethernet handle");
            assertEquals(":", hb.send("CF I"));
            assertEquals(" 66.0000\r\n:", ha.send("MG _CF"), "B, the handle CF I came in on");
            assertEquals(":", ha.send("CW 1"));
            assertEquals(":", ha.send("XQ #hello,1"));
            assertTrue(ha.awaitThreadEnd(1, 3));
            assertEquals(" 1.0000\r\n:", hb.send("MG 1"));
            assertEquals("HELLO\r\n", hb.unsolicited.toString(), "on B only");
            assertEquals("", ha.unsolicited.toString());
        }
    }

    @Test
    void commandsNotValidInTheTerminalAreRefusedWithTc2() throws GalilException {
        VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), null);
        for (String cmd : List.of("EN", "WT 10", "AM", "AV 100", "MF ,,100", "JP #a", "JS #a", "ZS", "RE", "MC",
                "AI 1", "#LABEL", "IF (1)", "ENDIF", "ELSE")) {
            GalilException e = assertThrows(GalilException.class, () -> c.command(cmd), cmd);
            assertEquals(Tc.ONLY_IN_PROGRAM, e.tc, cmd + ": COMALL \"Not Valid in terminal\"");
            assertEquals("2 Command only valid from program\r\n", c.command("TC1"), cmd);
        }
        assertEquals("", c.command("ENX=1"), "an assignment is no command: EN is not its head");
        assertEquals(" 1.0000\r\n", c.command("MG ENX"));
    }

    @Test
    void aProgramLineThatIsNotValidInAProgramIsTc3() throws Exception {
        VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), null);
        c.download("#a\r\nRS\r\nEN\r\n", false);
        c.command("XQ #a,0");
        c.advance(0.01);
        assertEquals(Tc.NOT_IN_PROGRAM, c.lastError, "COMALL RS: Not Valid in program");
    }
}
