package gcnc.studio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** {@code gcnc studio}'s refusals before it serves (it serves until stopped, so the serving is StudioServerTest's). */
class StudioCommandTest {
    record Run(int status, String out, String err) {
    }

    static Run gcnc(String... args) {
        CommandLine cl = gcnc.cli.Main.commandLine(args);
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        return new Run(cl.execute(args), out.toString(), err.toString());
    }

    @Test
    void aFolderThatIsNotThereIsStatus2() {
        Run r = gcnc("studio", "--lang", "en", "no/such/folder");
        assertEquals(2, r.status());
        assertEquals("gcnc: no/such/folder is not a folder: gcnc studio serves the programs in a folder\n", r.err());
        Run es = gcnc("studio", "--lang", "es", "samples/bishop.nc");
        assertEquals(2, es.status());
        assertEquals("gcnc: samples/bishop.nc no es una carpeta: gcnc studio sirve los programas de una carpeta\n", es.err());
    }

    @Test
    void aPortTakenIsStatus2AndSaysWhich() throws Exception {
        try (ServerSocket taken = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            Run r = gcnc("studio", "--lang", "en", "samples", "--port", String.valueOf(taken.getLocalPort()));
            assertEquals(2, r.status());
            assertTrue(r.err().startsWith("gcnc: cannot start the studio on port " + taken.getLocalPort() + ": "), r.err());
        }
    }

    @Test
    void aBrokenProfileIsReportedAsCheckReportsItAndStatus2() throws Exception {
        Path machine = Files.createTempFile("broken", ".machine");
        Files.writeString(machine, Files.readString(Path.of("tables/machines/generic.machine")).replace("x.sign = 1", "x.sign = up"));
        Run r = gcnc("studio", "--lang", "en", "samples", "--machine", machine.toString());
        assertEquals(2, r.status());
        assertTrue(r.err().contains(machine.toString() + ":"), r.err());
        assertEquals("", r.out());
    }

    @Test
    void aVirtualSpeedThatIsNotAboveZeroIsStatus2() {
        for (String speed : new String[] {"0", "-1", "20000"}) {
            Run r = gcnc("studio", "--lang", "en", "samples", "--virtual-speed", speed);
            assertEquals(2, r.status(), speed);
            assertTrue(r.err().startsWith("gcnc: --virtual-speed " + Double.parseDouble(speed) + ": give a number above 0"), r.err());
            assertEquals("", r.out());
        }
    }

    @Test
    void theHelpNamesEveryOption() {
        Run r = gcnc("studio", "--help");
        assertEquals(0, r.status());
        for (String option : new String[] {"DIR", "--port", "--open", "--virtual-speed", "--machine", "--control", "--tables", "--lang"}) {
            assertTrue(r.out().contains(option), option + " in\n" + r.out());
        }
    }
}
