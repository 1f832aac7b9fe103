package gcnc.junit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.sim.StockSize;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;

/**
 * One verdict (issue 9): the JUnit fixture and {@code gcnc compile} take the same inputs (tables,
 * machine, control, blank, the program's stock header) through {@link Session} and report the same
 * findings.
 */
class FixtureAgreesWithCliTest {
    /** A D30 blank in the header; a pass in the air at X36. (the generic profile's D44 blank would be in the way). */
    private static final String HEADER = "(100 30)\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X36. Z2.\n"
            + "G00 Z-20.\nG00 X60.\nM05\nM30\n";
    /** Written for a Haas: no G90, M10 closes the chuck. */
    private static final String HAAS = "G21 G98\nG50 S2500\nM10\nT0101\nG97 S1000 M03\nG00 X46. Z2.\nG00 X41.\n"
            + "G01 Z-20. F100.\nG00 U2.\nG00 Z2.\nM05\nM30\n";

    static Path write(String name, String text) throws Exception {
        Path p = Files.createTempDirectory("gcnc-fixture").resolve(name);
        Files.writeString(p, text);
        return p;
    }

    /** The codes {@code gcnc compile} prints for the program, in order. */
    static List<String> cli(Path program, String... options) {
        List<String> args = new ArrayList<>(List.of("compile", program.toString(), "-o",
                program.resolveSibling("out.dmc").toString()));
        args.addAll(List.of(options));
        StringWriter err = new StringWriter();
        picocli.CommandLine cl = gcnc.cli.Main.commandLine();
        cl.setOut(new PrintWriter(new StringWriter(), true));
        cl.setErr(new PrintWriter(err, true));
        cl.execute(args.toArray(new String[0]));
        List<String> codes = new ArrayList<>();
        Matcher m = Pattern.compile("(?:error|warning|note)\\[(E\\d+)\\]").matcher(err.toString());
        while (m.find()) {
            codes.add(m.group(1));
        }
        return codes;
    }

    static void agree(Path program, Session session, String... cliOptions) {
        List<String> codes = cli(program, cliOptions);
        GcodeAssertions.assertFindings(program, session, codes.toArray(new String[0]));
    }

    @Test
    void theStockHeaderIsReadByBoth() throws Exception {
        Path p = write("header.nc", HEADER);
        assertEquals(List.of(), cli(p));
        agree(p, GcodeAssertions.session("generic"));
        GcodeAssertions.assertCompilesClean(p, "generic");
    }

    @Test
    void aBlankGivenWinsInBoth() throws Exception {
        Path p = write("header.nc", HEADER);
        Session wide = GcodeAssertions.session("generic").withStock(new StockSize(50, 200, 150));
        assertTrue(cli(p, "--stock", "50,200,150").contains("E305"));
        agree(p, wide, "--stock", "50,200,150");
        assertThrows(AssertionError.class, () -> GcodeAssertions.assertCompilesClean(p, wide));
    }

    @Test
    void theControlOverrideAppliesToBoth() throws Exception {
        Path p = write("haas.nc", HAAS);
        Session haas = Session.open(Session.Options.defaults().withMachine("generic").withControl("haas"));
        assertFalse(cli(p).isEmpty(), "on the thesis's control M10 does not close the chuck");
        agree(p, GcodeAssertions.session("generic"));
        assertEquals(List.of(), cli(p, "--control", "haas"));
        agree(p, haas, "--control", "haas");
    }

    @Test
    void editedTablesApplyToBoth() throws Exception {
        // a copy of the tables whose generic machine has a Z travel too short for the pass
        Path tables = Files.createTempDirectory("gcnc-tables");
        gcnc.TestFiles.copyTree(Path.of("tables"), tables);
        Path machine = tables.resolve("machines/generic.machine");
        String text = Files.readString(machine);
        String shorter = text.replaceAll("(?m)^z\\.travel = .*$", "z.travel = 140, 400");
        assertFalse(shorter.equals(text), "the generic profile names its Z travel");
        Files.writeString(machine, shorter);
        Path p = write("header.nc", HEADER);
        List<String> codes = cli(p, "--tables", tables.toString());
        assertFalse(codes.isEmpty(), "the pass to Z-20. is beyond the shorter travel");
        agree(p, Session.open(Session.Options.defaults().withTables(tables)), "--tables", tables.toString());
    }

    @Test
    void everyProgramInTakesEveryShopExtensionAndFailsOnAnEmptyFolder() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-programs");
        Files.writeString(dir.resolve("A.NC"), HEADER);
        Files.writeString(dir.resolve("b.ngc"), HEADER);
        Files.writeString(dir.resolve("c.tap"), HEADER);
        Files.writeString(dir.resolve("notes.txt"), "not a program");
        SystemOut.Printed<List<DynamicTest>> scan = SystemOut.capture(
                () -> GcodeAssertions.everyProgramIn(dir, "generic").collect(Collectors.toList()));
        List<DynamicTest> tests = scan.value();
        assertEquals(List.of("A.NC", "b.ngc", "c.tap"), tests.stream().map(DynamicTest::getDisplayName).toList());
        assertTrue(scan.text().contains("gcnc: " + dir + ": skipped 1 file {txt=1}: not a program's extension"), scan.text());
        Path empty = Files.createTempDirectory("gcnc-empty");
        List<DynamicTest> none = GcodeAssertions.everyProgramIn(empty, "generic").collect(Collectors.toList());
        assertEquals(1, none.size());
        assertThrows(AssertionError.class, () -> none.get(0).getExecutable().execute());
    }

    @Test
    void everyProgramInTakesTheShopsOwnExtensions() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-programs");
        Files.writeString(dir.resolve("o1201.GCODE"), HEADER);
        Files.writeString(dir.resolve("o1202.nc"), HEADER);
        Files.writeString(dir.resolve("o1203.tap"), HEADER);
        SystemOut.Printed<List<DynamicTest>> scan = SystemOut.capture(() -> GcodeAssertions.everyProgramIn(dir,
                GcodeAssertions.session("generic"), List.of(".gcode", "NC")).collect(Collectors.toList()));
        List<DynamicTest> tests = scan.value();
        assertEquals(List.of("o1201.GCODE", "o1202.nc"), tests.stream().map(DynamicTest::getDisplayName).toList());
        assertTrue(scan.text().contains("gcnc: " + dir + ": skipped 1 file {tap=1}: not a program's extension (.gcode, .nc)"),
                scan.text());
        assertThrows(IllegalArgumentException.class,
                () -> GcodeAssertions.everyProgramIn(dir, GcodeAssertions.session("generic"), List.of()));
    }
}
