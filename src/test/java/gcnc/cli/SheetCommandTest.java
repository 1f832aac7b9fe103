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
        CliTest.Run r = CliTest.gcnc("sheet", nc.toString(), "--machine", "haas", "--stock", "40mm,200mm,150mm");
        assertEquals(0, r.status(), r.err());
        String html = Files.readString(dir.resolve("o1201.html"), StandardCharsets.UTF_8);
        assertTrue(html.contains("<tr><th>Program</th><td>O1201</td></tr>"), html);
        // G96 S180 at asks for more than the G50 S2500 clamp: the spindle runs at the clamp
        // beside it, the clamp as the program writes it
        assertTrue(html.contains("<tr><th>Maximum spindle speed</th><td>2500 rpm; the program's limit G50 S2500 (line 5)"
                + "</td></tr>"), html);
        assertTrue(html.contains("<h2>Drawing</h2>\n<svg "), html);
        assertTrue(r.out().startsWith("setup sheet: " + dir.resolve("o1201.html") + " (O1201, cycle about"), r.out());
    }

    /** Fanuc system B writes the clamp G92 S; below it, G96 asks for less: the speed reached and the limit differ. */
    @Test
    void theProgramsLimitIsBesideTheSpeedItReachedAsTheControlWritesIt() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-sheet");
        Path nc = Files.writeString(dir.resolve("b.nc"), "O1000\nG21 G99\nG92 S3500\nT0101\nG96 S200 M03\n"
                + "G00 X42. Z2.\nG01 X40. F0.2\nG01 Z-30.\nG00 X60. Z5.\nG92 S1800\nG97 S900\nG00 X70.\nM05\nM30\n");
        CliTest.Run r = CliTest.gcnc("sheet", nc.toString(), "--machine", "fanuc", "--control", "fanuc-b");
        assertEquals(0, r.status(), r.err());
        String html = Files.readString(dir.resolve("b.html"), StandardCharsets.UTF_8);
        // 200 m/min at X40: 1592 rpm, under the G92 S3500 clamp; a second clamp later is listed too
        assertTrue(html.contains("<tr><th>Maximum spindle speed</th><td>1592 rpm; the program's limit G92 S3500 (line 3),"
                + " G92 S1800 (line 10)</td></tr>"), html);
    }

    /**
     * {@code -o sheet.png}: one PNG that decodes, as wide as the drawing and as high as its text lines and
     * the drawing; its findings listed one by one, as many as the sheet's Findings row counts.
     */
    @Test
    void aPngSheetDecodesAtItsSizeAndListsEveryFindingItCounts() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-sheet");
        // two rapids into the 65 mm bar (E305 each): the simulation goes on, the sheet lists both
        Path nc = Files.writeString(dir.resolve("hit.nc"), "O1000\nG21 G99\nG50 S2500\nT0101\nG97 S1200 M03\n"
                + "G00 X70. Z2.\nG00 X60. Z-5.\nG00 X50. Z-10.\nG01 X40. F0.2\nG01 Z-30.\nG00 X80. Z5.\nM05\nM30\n");
        Path png = dir.resolve("hit.png");
        CliTest.Run r = CliTest.gcnc("sheet", nc.toString(), "--machine", "fanuc", "-o", png.toString());
        assertEquals(1, r.status(), r.err()); // the program has errors; the sheet says which
        assertTrue(r.out().contains("setup sheet: " + png + " (O1000") && r.out().contains("2 findings"), r.out());
        java.awt.image.BufferedImage image = javax.imageio.ImageIO.read(png.toFile());
        org.junit.jupiter.api.Assertions.assertNotNull(image, "a PNG ImageIO decodes");
        // the same sheet in the library: its lines and its drawing set the image's size
        gcnc.Session s = gcnc.Session.open(gcnc.Session.Options.defaults().withMachine("fanuc"));
        gcnc.Compiler.Result res;
        try (java.io.Reader in = Files.newBufferedReader(nc)) {
            res = s.compile(in, java.util.Optional.of(s.simulation().withPath()), false, l -> { });
        }
        gcnc.SetupSheet sheet = gcnc.SetupSheet.of("hit.nc", "O1000", s.profile(), res.simulation().orElseThrow(),
                res.diagnostics(), s.tables().messages().in(gcnc.tables.ErrorMessages.Lang.EN));
        java.util.List<gcnc.SheetImage.Line> lines = gcnc.SheetImage.lines(sheet);
        assertEquals(1000, image.getWidth());
        assertEquals(2 * gcnc.SheetImage.MARGIN + gcnc.SheetImage.LINE * lines.size()
                + gcnc.sim.PngDrawing.height(res.simulation().get()), image.getHeight());
        java.util.List<String> errors = lines.stream().filter(l -> l.kind() == gcnc.SheetImage.Kind.ERROR)
                .map(gcnc.SheetImage.Line::text).toList();
        assertEquals(2, errors.size(), lines.toString());
        assertTrue(errors.get(0).startsWith("7:1 error E305 rapid move enters the blank"), errors.toString());
        assertTrue(lines.stream().anyMatch(l -> l.text().equals("Findings: " + errors.size())), lines.toString());
        // the drawing was painted below the text: the feed moves' blue and the findings' magenta are there
        int top = 2 * gcnc.SheetImage.MARGIN + gcnc.SheetImage.LINE * lines.size();
        java.util.Set<Integer> colours = new java.util.HashSet<>();
        for (int y = top; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                colours.add(image.getRGB(x, y) & 0xffffff);
            }
        }
        assertTrue(colours.contains(0x1040c0), "feeds drawn");
        assertTrue(colours.contains(0xff00ff), "findings marked");
        // and nothing is left beside it
        try (var files = Files.list(dir)) {
            assertEquals(java.util.List.of("hit.nc", "hit.png"), files.map(p -> p.getFileName().toString()).sorted().toList());
        }
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
        CliTest.Run r = CliTest.gcnc("sheet", nc.toString(), "--machine", "haas", "--stock", "40mm,200mm,150mm");
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
