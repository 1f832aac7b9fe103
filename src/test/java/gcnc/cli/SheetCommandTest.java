package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** {@code gcnc sheet FILE}: the setup sheet from the command line (issue 34; the golden is ProgramTermsGoldenTest's). */
class SheetCommandTest {
    private static final String PIN = "O1201 (PIN)\nG21 G18 G40 G99\nG28 U0. W0.\nT101\nG50 S2500\nG96 S180 M03\n"
            + "G54 G00 X44. Z2. M08\nG01 Z0. F0.2\nX-1.6 F0.15\nG00 Z2.\nX41.\nG01 Z-25. F0.25\nX41.\nG00 Z2.\nM09\n"
            + "G28 U0. W0.\nM05\nM30\n";

    @Test
    void theSheetGoesBesideTheProgramWithTheSpindleSpeedItReached() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-sheet");
        Path nc = Files.writeString(dir.resolve("o1201.nc"), PIN);
        CliTest.Run r = CliTest.gcnc("sheet", nc.toString(), "--machine", "haas", "--stock", "40,200,150");
        assertEquals(0, r.status(), r.err());
        String html = Files.readString(dir.resolve("o1201.html"), StandardCharsets.UTF_8);
        assertTrue(html.contains("<tr><th>Program</th><td>O1201</td></tr>"), html);
        // G96 S180 at asks for more than the G50 S2500 clamp: the spindle runs at the clamp
        assertTrue(html.contains("<tr><th>Maximum spindle speed</th><td>2500 rpm</td></tr>"), html);
        assertTrue(html.contains("<h2>Drawing</h2>\n<svg "), html);
        assertTrue(r.out().startsWith("setup sheet: " + dir.resolve("o1201.html") + " (O1201, cycle about"), r.out());
    }

    @Test
    void neverOverTheProgram() throws Exception {
        Path nc = Files.writeString(Files.createTempDirectory("gcnc-sheet").resolve("o1201.nc"), PIN);
        CliTest.Run r = CliTest.gcnc("sheet", nc.toString(), "--machine", "haas", "-o", nc.toString());
        assertEquals(2, r.status(), r.out());
        assertTrue(r.err().contains("error[E501]"), r.err());
        assertEquals(PIN, Files.readString(nc));
    }

    @Test
    void aLinkPlantedAtTheSheetsDefaultNameIsRefused() throws Exception {
        // the name gcnc chose (FILE.html): a link there was planted by nobody the user named (issue 35)
        Path dir = Files.createTempDirectory("gcnc-sheet");
        Path nc = Files.writeString(dir.resolve("o1201.nc"), PIN);
        Path victim = Files.writeString(dir.resolve("victim.txt"), "keep me");
        Files.createSymbolicLink(dir.resolve("o1201.html"), victim);
        CliTest.Run r = CliTest.gcnc("sheet", nc.toString(), "--machine", "haas", "--stock", "40,200,150");
        assertEquals(2, r.status(), r.out());
        assertTrue(r.err().contains("error[E510]"), r.err());
        assertEquals("keep me", Files.readString(victim));
    }

    @Test
    void aProgramThatStopsTheSimulationWritesNoSheet() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-sheet");
        // a feed before the spindle turns: a check error, nothing simulated
        Path nc = Files.writeString(dir.resolve("bad.nc"), "G21 G18 G99\nT101\nG00 X44. Z2.\nG01 X40. F0.2\nM30\n");
        CliTest.Run r = CliTest.gcnc("sheet", nc.toString(), "--machine", "haas");
        assertEquals(1, r.status(), r.out());
        assertTrue(r.out().contains("no sheet was written"), r.out());
        assertFalse(Files.exists(dir.resolve("bad.html")));
    }
}
