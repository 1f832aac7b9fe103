package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.gcnc;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.TestCut;
import gcnc.machine.MachineProfile;
import gcnc.machine.ToolWear;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Wear offsets and the test cut (issue 34 item 5, docs/profiles.md "Wear offsets"): a wear moves
 * the emitted DMC by exactly the wear, in a metric Fanuc program and an inch Haas one; {@code gcnc
 * offsets wear} computes programmed - measured, re-verifies, saves one line atomically and refuses
 * a typo, a wear that makes a collision, an offset the program does not use, and a shipped profile
 * with nowhere to save; the offsets file's own faults are located.
 */
public class WearOffsetsTest {
    /** A metric Fanuc part: T0101 turns X40. from Z2. to Z-30., faces out to X50. */
    public static final String METRIC = String.join("\n",
            "O1002 (WEAR TEST PART)",
            "G21 G99",
            "G50 S2500",
            "T0101",
            "G97 S1200 M03",
            "G00 X42. Z2.",
            "G01 X40. F0.2",
            "G01 Z-30.",
            "G02 X46. Z-33. R3.",
            "G01 X50.",
            "G00 X60. Z5.",
            "M05",
            "M30", "");

    /** An inch Haas part: T0101 turns X1.5 from Z0.1 to Z-1. */
    public static final String INCH = String.join("\n",
            "O2001 (INCH TEST PART)",
            "G20 G99",
            "G50 S2500",
            "T0101",
            "G97 S1200 M03",
            "G00 X1.6 Z0.1",
            "G01 X1.5 F0.008",
            "G01 Z-1.",
            "G01 X1.8",
            "G00 X2.5 Z0.5",
            "M05",
            "M30", "");

    /** A rapid along the fanuc profile's 65 mm blank 0.2 mm (on the radius) above it. */
    public static final String CLOSE = String.join("\n",
            "O1003 (RAPID CLOSE TO THE BAR)",
            "G21 G99",
            "G50 S2500",
            "T0101",
            "G97 S1200 M03",
            "G00 X65.4 Z2.",
            "G00 Z-20.",
            "G00 X70.",
            "G00 X80. Z5.",
            "M05",
            "M30", "");

    static Path folder() throws Exception {
        return Files.createTempDirectory("gcnc-wear");
    }

    static Path write(Path dir, String name, String text) throws Exception {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p;
    }

    /** The numbers of every VP of a DMC file, in order (Galil X = lathe Z, Galil Y = lathe X on both profiles). */
    static List<long[]> vps(Path dmc) throws Exception {
        List<long[]> out = new ArrayList<>();
        Matcher m = Pattern.compile("VP (-?\\d+),(-?\\d+)").matcher(Files.readString(dmc));
        while (m.find()) {
            out.add(new long[] {Long.parseLong(m.group(1)), Long.parseLong(m.group(2))});
        }
        return out;
    }

    /** The VPs of {@code with} minus those of {@code without}, each "dZ,dX" in counts. */
    static List<String> moved(Path without, Path with) throws Exception {
        List<long[]> a = vps(without);
        List<long[]> b = vps(with);
        assertEquals(a.size(), b.size());
        List<String> d = new ArrayList<>();
        for (int i = 0; i < a.size(); i++) {
            d.add((b.get(i)[0] - a.get(i)[0]) + "," + (b.get(i)[1] - a.get(i)[1]));
        }
        return d;
    }

    @Test
    void aMetricTestCutChangesTheEmittedCountsByExactlyTheWearAndIsSavedAndReadAgain() throws Exception {
        Path dir = folder();
        Path part = write(dir, "part.nc", METRIC);
        Path offsets = dir.resolve("shop.offsets");
        // the OD came out 39.96 where the program cuts 40.: +0.04 on the diameter, 0.02 mm on the radius
        RunOnControllerTest.Run r = gcnc("", "offsets", "wear", "T0101", "--measured", "X39.96", "--programmed", "X40.",
                part.toString(), "--machine", "fanuc", "--offsets", offsets.toString());
        assertEquals(0, r.status(), r.all());
        assertTrue(r.out().contains("T01 X wear 0.000 -> +0.040 (+0.040 = programmed X40. - measured X39.96;"
                + " on the diameter, mm)"), r.out());
        assertTrue(r.out().contains("re-verified"), r.out());
        assertEquals("wear.1 = 0.04, 0\n", Files.readString(offsets));
        // the face came out at Z-30.05 where the program cuts Z-30.: +0.05 toward +Z, added to the X wear
        r = gcnc("", "offsets", "wear", "1", "--measured", "Z-30.05", "--programmed", "Z-30.", part.toString(),
                "--machine", "fanuc", "--offsets", offsets.toString());
        assertEquals(0, r.status(), r.all());
        assertEquals("wear.1 = 0.04, 0.05\n", Files.readString(offsets));
        // read again as every command reads it
        MachineProfile p = Session.open(Session.Options.defaults().withMachine("fanuc").withOffsets(offsets)).profile();
        assertEquals(0.04, p.wear().of(1).orElseThrow().x(), 1e-12);
        assertEquals(0.05, p.wear().of(1).orElseThrow().z(), 1e-12);
        // compile with and without: the approach moves by 0.05 mm x 500 = 25 counts in Z, 0.02 mm x 500 = 10 in X
        assertEquals(0, gcnc("", "compile", part.toString(), "--machine", "fanuc", "-o", dir.resolve("a.dmc").toString())
                .status());
        assertEquals(0, gcnc("", "compile", part.toString(), "--machine", "fanuc", "--offsets", offsets.toString(), "-o",
                dir.resolve("b.dmc").toString()).status());
        List<String> d = moved(dir.resolve("a.dmc"), dir.resolve("b.dmc"));
        assertEquals("25,10", d.get(0), d.toString());
        for (String step : d.subList(1, d.size())) {
            assertEquals("0,0", step, d.toString()); // the moves after it are relative: the whole path shifted
        }
    }

    @Test
    void anInchTestCutIsConvertedToTheOffsetsMillimetres() throws Exception {
        Path dir = folder();
        Path part = write(dir, "inch.nc", INCH);
        Path offsets = dir.resolve("st20.offsets");
        // 1.4980 in where the program cuts 1.5000: +0.002 in on the diameter = 0.0508 mm, 0.001 in on the radius
        RunOnControllerTest.Run r = gcnc("", "offsets", "wear", "T01", "--measured", "X1.4980", "--programmed", "X1.5000",
                part.toString(), "--machine", "haas", "--offsets", offsets.toString());
        assertEquals(0, r.status(), r.all());
        assertTrue(r.out().contains("+0.0508 = programmed X1.5000 - measured X1.4980; on the diameter, mm; +0.0020 in"),
                r.out());
        assertEquals("wear.1 = 0.0508, 0\n", Files.readString(offsets));
        gcnc("", "compile", part.toString(), "--machine", "haas", "-o", dir.resolve("a.dmc").toString());
        gcnc("", "compile", part.toString(), "--machine", "haas", "--offsets", offsets.toString(), "-o",
                dir.resolve("b.dmc").toString());
        // 0.001 in on the radius x 25000 counts/in = 25 counts, exactly
        assertEquals("0,25", moved(dir.resolve("a.dmc"), dir.resolve("b.dmc")).get(0));
    }

    @Test
    void aTypoIsRefusedNamingTheLimitAndTheFileIsLeftAsItWas() throws Exception {
        Path dir = folder();
        Path part = write(dir, "part.nc", METRIC);
        String before = "# the shop's wear, T0101 and T0808\r\nwear.8 = -0.02, 0   # boring bar\r\nwear.1 = 0.01, 0\r\n";
        Path offsets = write(dir, "shop.offsets", before);
        // 2.5 typed where 0.025 was meant
        RunOnControllerTest.Run r = gcnc("", "offsets", "wear", "T0101", "--measured", "X37.5", "--programmed", "X40.",
                part.toString(), "--machine", "fanuc", "--offsets", offsets.toString());
        assertEquals(1, r.status(), r.all());
        assertTrue(r.err().contains(offsets + ":3:1: error[E872]"), r.err());
        assertTrue(r.err().contains("+2.500 mm (programmed X40. minus measured X37.5): more than wear.max_step = 0.5 mm"),
                r.err());
        assertEquals(before, Files.readString(offsets));
        // two steps of 0.45 are each allowed, a third would make 1.36: beyond wear.max_total
        for (int i = 0; i < 2; i++) {
            assertEquals(0, gcnc("", "offsets", "wear", "T0101", "--measured", "X39.55", "--programmed", "X40.",
                    part.toString(), "--machine", "fanuc", "--offsets", offsets.toString()).status());
        }
        String twice = Files.readString(offsets);
        r = gcnc("", "offsets", "wear", "T0101", "--measured", "X39.55", "--programmed", "X40.", part.toString(),
                "--machine", "fanuc", "--offsets", offsets.toString());
        assertEquals(1, r.status(), r.all());
        assertTrue(r.err().contains("error[E873]: the X wear of tool offset 1 would be +1.360 mm: beyond wear.max_total"
                + " = 1 mm"), r.err());
        assertEquals(twice, Files.readString(offsets));
        // only the wear.1 line changed, its line ending and every other line and comment kept
        assertEquals("# the shop's wear, T0101 and T0808\r\nwear.8 = -0.02, 0   # boring bar\r\nwear.1 = 0.91, 0\r\n",
                twice);
    }

    @Test
    void aWearThatMakesTheSimulatorFindACollisionIsRefused() throws Exception {
        Path dir = folder();
        Path part = write(dir, "close.nc", CLOSE);
        Path offsets = dir.resolve("shop.offsets");
        // measured 40.5 where 40. is programmed: -0.5, 0.25 mm in on the radius, and the rapid 0.2 mm above
        // the blank now enters it
        RunOnControllerTest.Run r = gcnc("", "offsets", "wear", "T0101", "--measured", "X40.5", "--programmed", "X40.",
                part.toString(), "--machine", "fanuc", "--offsets", offsets.toString());
        assertEquals(1, r.status(), r.all());
        assertTrue(r.err().contains("close.nc:7:1: error[E874]: with the new wear of tool offset 1 (T01 X-0.500 Z0.000"
                + " (diameter, mm)) the program gets E305 at line 7: rapid move enters the blank"), r.err());
        assertFalse(Files.exists(offsets), "nothing was saved");
        // the same wear on the other side is clear of the bar
        assertEquals(0, gcnc("", "offsets", "wear", "T0101", "--measured", "X39.5", "--programmed", "X40.",
                part.toString(), "--machine", "fanuc", "--offsets", offsets.toString()).status());
    }

    @Test
    void anOffsetTheProgramDoesNotUseAndAShippedProfileWithNoFileAreRefused() throws Exception {
        Path dir = folder();
        Path part = write(dir, "part.nc", METRIC);
        Path offsets = dir.resolve("shop.offsets");
        RunOnControllerTest.Run r = gcnc("", "offsets", "wear", "T0303", "--measured", "X39.97", "--programmed", "X40.",
                part.toString(), "--machine", "fanuc", "--offsets", offsets.toString());
        assertEquals(1, r.status(), r.all());
        assertTrue(r.err().contains("error[E877]: the program does not use tool offset 3"), r.err());
        assertFalse(Files.exists(offsets));
        r = gcnc("", "offsets", "wear", "T0101", "--measured", "X39.97", "--programmed", "X40.", part.toString(),
                "--machine", "fanuc");
        assertEquals(1, r.status(), r.all());
        assertTrue(r.err().contains("error[E876]: the machine profile fanuc is one gcnc ships"), r.err());
        r = gcnc("", "offsets", "wear", "T0101", "--measured", "X39.97", "--programmed", "Z-30.", part.toString(),
                "--machine", "fanuc", "--offsets", offsets.toString());
        assertEquals(1, r.status(), r.all());
        assertTrue(r.err().contains("error[E871]"), r.err());
        r = gcnc("", "offsets", "wear", "T0100", "--measured", "X39.97", "--programmed", "X40.", part.toString(),
                "--machine", "fanuc", "--offsets", offsets.toString());
        assertTrue(r.err().contains("error[E870]: T0100 names no tool offset"), r.err());
    }

    @Test
    void withoutAnOffsetsFileTheWearLineGoesIntoTheProfileGiven() throws Exception {
        Path dir = folder();
        Path part = write(dir, "part.nc", METRIC);
        String shipped = new String(WearOffsetsTest.class.getResourceAsStream("/tables/machines/fanuc.machine")
                .readAllBytes(), StandardCharsets.UTF_8);
        Path profile = write(dir, "lathe.machine", shipped);
        RunOnControllerTest.Run r = gcnc("", "offsets", "wear", "T0101", "--measured", "X39.96", "--programmed", "X40.",
                part.toString(), "--machine", profile.toString());
        assertEquals(0, r.status(), r.all());
        assertEquals(shipped + "wear.1 = 0.04, 0\n", Files.readString(profile));
        assertEquals(0.04, Session.open(Session.Options.defaults().withMachine(profile.toString())).profile().wear()
                .of(1).orElseThrow().x(), 1e-12);
    }

    /**
     * A profile's own wear.N, its limits and its offsets.file (relative to the profile): the file's
     * wear.N replaces the profile's, --offsets replaces the file, and a test cut writes into it.
     */
    @Test
    void theProfileNamesItsOffsetsFileAndItsLimits() throws Exception {
        Path dir = folder();
        Path part = write(dir, "part.nc", METRIC);
        String shipped = new String(WearOffsetsTest.class.getResourceAsStream("/tables/machines/fanuc.machine")
                .readAllBytes(), StandardCharsets.UTF_8);
        Files.createDirectories(dir.resolve("shop"));
        Path profile = write(dir, "shop/lathe.machine", shipped + "wear.1 = 0.2, 0\nwear.3 = 0.1, 0.1\n"
                + "offsets.file = lathe.offsets\nwear.max_step = 0.05\nwear.max_total = 0.3\n");
        Path offsets = write(dir, "shop/lathe.offsets", "wear.1 = 0.01, 0\n");
        MachineProfile p = Session.open(Session.Options.defaults().withMachine(profile.toString())).profile();
        assertEquals(0.01, p.wear().of(1).orElseThrow().x(), 1e-12, "the file's wear.1 replaces the profile's");
        assertEquals(0.1, p.wear().of(3).orElseThrow().z(), 1e-12, "the profile's wear.3 stays");
        assertEquals(0.05, p.wear().maxStep(), 1e-12);
        // 0.06 is more than this profile's step of 0.05
        RunOnControllerTest.Run r = gcnc("", "offsets", "wear", "T0101", "--measured", "X39.94", "--programmed", "X40.",
                part.toString(), "--machine", profile.toString());
        assertEquals(1, r.status(), r.all());
        assertTrue(r.err().contains(offsets + ":1:1: error[E872]") && r.err().contains("wear.max_step = 0.05 mm"),
                r.err());
        r = gcnc("", "offsets", "wear", "T0101", "--measured", "X39.96", "--programmed", "X40.", part.toString(),
                "--machine", profile.toString());
        assertEquals(0, r.status(), r.all());
        assertEquals("wear.1 = 0.05, 0\n", Files.readString(offsets));
        assertTrue(Files.readString(profile).endsWith("wear.max_total = 0.3\n"), "the profile is not written");
        // --offsets replaces offsets.file
        Path other = write(dir, "other.offsets", "wear.1 = -0.02, 0\n");
        p = Session.open(Session.Options.defaults().withMachine(profile.toString()).withOffsets(other)).profile();
        assertEquals(-0.02, p.wear().of(1).orElseThrow().x(), 1e-12);
        // a step above the total could never be taken
        Path bad = write(dir, "bad.machine", shipped + "wear.max_step = 2\n");
        r = gcnc("", "check", part.toString(), "--machine", bad.toString());
        assertEquals(2, r.status(), r.all());
        assertTrue(r.err().contains("error[E454]: wear.max_step = 2 is more than wear.max_total = 1"), r.err());
    }

    @Test
    void theOffsetsFilesFaultsAreLocated() throws Exception {
        Path dir = folder();
        Path part = write(dir, "part.nc", METRIC);
        String[][] cases = {
            {"wear.1 = 0.01, 0, 0.002\n", ":1:10: error[E451]: wear.1 = 0.01, 0, 0.002: a third value (wear of the nose"
                    + " radius) is not supported yet"},
            {"# ok\ntool.1 = 0, 0\n", ":2:1: error[E450]: tool.1: an offsets file holds wear.N lines only"},
            {"wear.51 = 0.01, 0\n", ":1:1: error[E452]: wear.51: the machine profile fanuc has no tool offset 51"},
            {"wear.2 = 1.5, 0\n", ":1:10: error[E453]: wear.2: the X wear 1.5 mm is beyond wear.max_total = 1 mm"},
        };
        for (String[] c : cases) {
            Path offsets = write(dir, "bad.offsets", c[0]);
            RunOnControllerTest.Run r = gcnc("", "check", part.toString(), "--machine", "fanuc", "--offsets",
                    offsets.toString());
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains(offsets + c[1]), c[0] + ": " + r.err());
        }
        RunOnControllerTest.Run r = gcnc("", "check", part.toString(), "--machine", "fanuc", "--offsets",
                dir.resolve("missing.offsets").toString());
        assertEquals(2, r.status(), r.all());
        assertTrue(r.err().contains("error[E455]: the offsets file " + dir.resolve("missing.offsets") + " does not exist"),
                r.err());
    }

    @Test
    void aDanglingLinkIsNotWrittenThrough() throws Exception {
        Path dir = folder();
        Path part = write(dir, "part.nc", METRIC);
        Path elsewhere = dir.resolve("elsewhere.offsets");
        Path link = Files.createSymbolicLink(dir.resolve("shop.offsets"), elsewhere);
        RunOnControllerTest.Run r = gcnc("", "offsets", "wear", "T0101", "--measured", "X39.96", "--programmed", "X40.",
                part.toString(), "--machine", "fanuc", "--offsets", link.toString());
        assertEquals(2, r.status(), r.all());
        assertTrue(r.err().contains("a symbolic link to nothing"), r.err());
        assertFalse(Files.exists(elsewhere));
    }

    /** The next gcnc run uses the saved wear: its DMC is the moved one, and its pre-flight says so (text and JSON). */
    @Test
    void theNextRunSendsTheWearAndSaysSoInItsPreFlight() throws Exception {
        Path dir = folder();
        Path part = write(dir, "inch.nc", INCH);
        Path offsets = write(dir, "st20.offsets", "wear.1 = 0.0508, -0.0254  # T0101 after the test cut\n");
        gcnc("", "compile", part.toString(), "--machine", "haas", "-o", dir.resolve("plain.dmc").toString());
        try (gcnc.controller.VirtualController vc = RunOnControllerTest.fast(RunOnControllerTest.model("DMC-4040"))) {
            RunOnControllerTest.homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", part.toString(), "--machine", "haas", "--offsets",
                    offsets.toString(), "--tcp", RunOnControllerTest.tcp(vc), "--dry-run");
            assertEquals(0, r.status(), r.all());
            assertTrue(r.out().contains("wear offsets from " + offsets + ": T01 X+0.0508 Z-0.0254 (diameter, mm)"),
                    r.out());
            // what reached the controller is the program moved by the wear: 25 counts out in X, 25 toward -Z
            Path sent = dir.resolve("sent.dmc");
            Files.writeString(sent, vc.controller().programText().replace("\r\n", "\n").replace("\r", "\n"));
            assertEquals("-25,25", moved(dir.resolve("plain.dmc"), sent).get(0));
            r = gcnc("", "run", part.toString(), "--machine", "haas", "--offsets", offsets.toString(), "--tcp",
                    RunOnControllerTest.tcp(vc), "--dry-run", "--format", "json");
            assertEquals(0, r.status(), r.all());
            String wear = null;
            List<String> events = new ArrayList<>();
            for (String line : r.out().split("\n")) {
                String event = com.google.gson.JsonParser.parseString(line).getAsJsonObject().get("event").getAsString();
                events.add(event);
                if (event.equals("wear")) {
                    wear = line;
                }
            }
            assertEquals(events.indexOf("preflight") + 1, events.indexOf("wear"), events.toString());
            assertEquals("{\"event\":\"wear\",\"file\":\"" + offsets + "\",\"offset\":1,\"x\":0.0508,\"z\":-0.0254,"
                    + "\"unit\":\"mm\",\"diameter\":true}", wear);
        }
        // without the offsets file: no wear line
        try (gcnc.controller.VirtualController vc = RunOnControllerTest.fast(RunOnControllerTest.model("DMC-4040"))) {
            RunOnControllerTest.homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", part.toString(), "--machine", "haas", "--tcp",
                    RunOnControllerTest.tcp(vc), "--dry-run");
            assertEquals(0, r.status(), r.all());
            assertFalse(r.out().contains("wear offsets"), r.out());
        }
    }

    /** The setup sheet lists each used tool's geometry and wear. */
    @Test
    void theSetupSheetListsTheToolsGeometryAndWear() throws Exception {
        Path dir = folder();
        Path part = write(dir, "part.nc", METRIC);
        Path offsets = write(dir, "shop.offsets", "wear.1 = 0.04, 0.05\n");
        Path sheet = dir.resolve("part.html");
        RunOnControllerTest.Run r = gcnc("", "sheet", part.toString(), "--machine", "fanuc", "--offsets",
                offsets.toString(), "-o", sheet.toString());
        assertEquals(0, r.status(), r.all());
        String html = Files.readString(sheet);
        assertTrue(html.contains("<th>geometry (offset N)</th><th>wear (offset N)</th>"), html);
        assertTrue(html.contains("<td>X 0 Z 0 mm (tool.1, X a radius)</td><td>X+0.040 Z+0.050 (diameter, mm) from "
                + offsets + "</td>"), html);
        r = gcnc("", "sheet", part.toString(), "--machine", "fanuc", "-o", sheet.toString());
        assertTrue(Files.readString(sheet).contains("<td>X 0 Z 0 mm (tool.1, X a radius)</td><td>none</td>"));
    }

    @Test
    void theOffsetNamesAndTheMeasurementsReadAsTheCheckerReadsT() {
        assertEquals(1, TestCut.offset("T0101").getAsInt());
        assertEquals(1, TestCut.offset("T0301").getAsInt()); // station 3, offset 1: the second pair
        assertEquals(1, TestCut.offset("T01").getAsInt());
        assertEquals(12, TestCut.offset("12").getAsInt());
        assertTrue(TestCut.offset("T0100").isEmpty());
        assertTrue(TestCut.offset("TX1").isEmpty());
        assertEquals(0.03, TestCut.Measurement.parse("X25.37", "X25.40").orElseThrow().change(), 1e-12);
        // a bore measured 0.03 small needs the tool outward too: the same sign as an OD
        assertEquals(0.03, TestCut.Measurement.parse("X30.97", "X31.").orElseThrow().change(), 1e-12);
        assertEquals(0.05, TestCut.Measurement.parse("Z-20.05", "Z-20.").orElseThrow().change(), 1e-12);
        assertTrue(TestCut.Measurement.parse("X25.37", "Z25.40").isEmpty());
        assertEquals("T07 X-0.020 Z+0.050 (diameter, mm)", ToolWear.describe(7, -0.02, 0.05, true, "mm"));
    }
}
