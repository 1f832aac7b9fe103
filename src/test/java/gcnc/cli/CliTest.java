package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/** gcnc as a user runs it: arguments in, exit status and text out (picocli execute, no System.exit). */
class CliTest {
    record Run(int status, String out, String err) {
    }

    static Run gcnc(String... args) {
        return run(Main.commandLine(args), args);
    }

    /** gcnc in an environment of its own (LANG, LC_ALL...) for the language of its help and usage errors. */
    static Run gcnc(java.util.Map<String, String> env, String... args) {
        return run(Main.commandLine(new Main.Streams(System.in, System.out), HelpLanguage.of(args, env)), args);
    }

    /** gcnc with its standard output (where {@code -o -} writes the DMC) into {@code stdout}, not the test JVM's. */
    static Run gcnc(java.io.OutputStream stdout, String... args) {
        return run(Main.commandLine(new Main.Streams(System.in, stdout), HelpLanguage.of(args, System.getenv()), args), args);
    }

    private static Run run(CommandLine cl, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int status = cl.execute(args);
        return new Run(status, out.toString(), err.toString());
    }

    static Path program(String text) throws IOException {
        Path dir = Files.createTempDirectory("gcnc-cli");
        Path p = dir.resolve("part.nc");
        Files.writeString(p, text);
        return p;
    }

    /** The README shows the output of docs/examples/mistakes.nc; it must be what gcnc prints. */
    @Test
    void theReadmeExampleIsWhatGcncPrints() throws IOException {
        String readme = Files.readString(Path.of("README.md"));
        String command = "$ java -jar build/libs/gcnc.jar check docs/examples/mistakes.nc\n";
        int from = readme.indexOf(command);
        assertTrue(from >= 0, "README lost its example");
        from += command.length();
        String shown = readme.substring(from, readme.indexOf("```", from));
        Run r = gcnc("check", "docs/examples/mistakes.nc");
        assertEquals(1, r.status());
        assertEquals(shown, r.err() + r.out());
    }

    /**
     * The README's command 1 (the bushing, from a 1.5 in bar) prints what the README shows under it: the
     * first numbers a newcomer reads are in the program's terms (issue 34).
     */
    @Test
    void theReadmeCommandOneIsWhatGcncPrints() throws IOException {
        String readme = Files.readString(Path.of("README.md"));
        String command = "java -jar build/libs/gcnc.jar compile docs/examples/bushing.nc --machine haas"
                + " --stock 1.5in,200mm,150mm -o bushing.dmc\n";
        assertTrue(readme.indexOf(command) >= 0 && readme.indexOf(command) < 1000, "README's command 1 is not the bushing");
        int from = readme.indexOf("```\n", readme.indexOf("Command 1 prints")) + 4;
        String shown = readme.substring(from, readme.indexOf("```", from));
        Path out = Files.createTempDirectory("gcnc-readme").resolve("bushing.dmc");
        Run r = gcnc("compile", "docs/examples/bushing.nc", "--machine", "haas", "--stock", "1.5in,200mm,150mm",
                "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals(shown, (r.err() + r.out()).replace(out.toString(), "bushing.dmc"));
    }

    /** docs/guide.md shows the simulation of docs/examples/back-turn.nc (E320 on N100); it must be what gcnc prints. */
    @Test
    void theGuidesBackTurnIsWhatGcncPrints() throws IOException {
        String readme = Files.readString(Path.of("docs/guide.md"));
        String command = "$ java -jar build/libs/gcnc.jar simulate docs/examples/back-turn.nc\n";
        int from = readme.indexOf(command);
        assertTrue(from >= 0, "docs/guide.md lost its example");
        from += command.length();
        String shown = readme.substring(from, readme.indexOf("```", from));
        Run r = gcnc("simulate", "docs/examples/back-turn.nc");
        assertEquals(1, r.status());
        assertTrue(shown.contains("error[E320]"), shown);
        assertEquals(shown, r.err() + r.out());
    }

    /**
     * The README's shop program (docs/examples/bushing.nc: G71/G70 with G42, a G76 thread, a G75
     * groove, on the haas) compiles and simulates clean from its 1.5 in bar, and its DMC gears the
     * thread to the spindle; a rapid moved into the bar is found on its line.
     */
    @Test
    void theReadmeBushingSimulatesCleanAndAMistakeInItIsFound() throws IOException {
        Run r = gcnc("simulate", "docs/examples/bushing.nc", "--machine", "haas", "--stock", "38.1mm,200mm,150mm");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains(", 0 findings;"), r.out());
        Path dmc = Files.createTempDirectory("gcnc-bushing").resolve("bushing.dmc");
        assertEquals(0, gcnc("compile", "docs/examples/bushing.nc", "--machine", "haas", "--stock", "38.1mm,200mm,150mm",
                "-o", dmc.toString()).status());
        assertTrue(Files.readString(dmc).contains(";GA C,C;"), "the thread is geared to the spindle");
        Path wrong = program(Files.readString(Path.of("docs/examples/bushing.nc")).replace("G00 X1.4 Z-1.4", "G00 X1.2 Z-1.4"));
        Run crash = gcnc("simulate", wrong.toString(), "--machine", "haas", "--stock", "38.1mm,200mm,150mm");
        assertTrue(crash.err().contains(":40:1: error[E305]"), crash.err());
        // without its M24 the Haas's M23 chamfers each thread pass: geared too, and as clean (README)
        String text = Files.readString(Path.of("docs/examples/bushing.nc"));
        Path chamfered = program(text.replaceFirst("M24 \\([^)]*\\)", "M23"));
        Run m23 = gcnc("simulate", chamfered.toString(), "--machine", "haas", "--stock", "38.1mm,200mm,150mm");
        assertEquals(0, m23.status(), m23.err());
        assertTrue(m23.out().contains(", 0 findings;"), m23.out());
        assertTrue(!Files.readString(chamfered).contains("M24"));
    }

    /** docs/program-flow.md shows the output of docs/examples/flow/grooves.nc (a call into a file beside it and back). */
    @Test
    void theProgramFlowExampleIsWhatGcncPrints() throws IOException {
        assertDocShows("docs/program-flow.md", "docs/examples/flow/grooves.nc");
    }

    /** docs/program-flow.md shows the output of docs/examples/flow/pecks.nc (a macro B loop and a value only the machine knows). */
    @Test
    void theMacroExampleIsWhatGcncPrints() throws IOException {
        assertDocShows("docs/program-flow.md", "docs/examples/flow/pecks.nc");
    }

    /** The document shows, after "$ java -jar build/libs/gcnc.jar check PROGRAM --machine fanuc", what gcnc prints. */
    private static void assertDocShows(String document, String program) throws IOException {
        String doc = Files.readString(Path.of(document));
        String command = "$ java -jar build/libs/gcnc.jar check " + program + " --machine fanuc\n";
        int from = doc.indexOf(command);
        assertTrue(from >= 0, document + " lost its example of " + program);
        from += command.length();
        String shown = doc.substring(from, doc.indexOf("```", from));
        Run r = gcnc("check", program, "--machine", "fanuc");
        assertEquals(1, r.status());
        assertEquals(shown, r.err() + r.out());
    }

    /** A simulator finding in a called program is placed in its file, with the call, as the checker's are. */
    @Test
    void aSimulatorFindingInACalledFileNamesThatFileAndTheCall() throws IOException {
        Path main = program("O0001\nG00 G18 G21 G40 G80 G99\nT0101\nG50 S2000\nG97 S800 M03\nG00 X52. Z2.\n"
                + "M98 P1000\nG00 X100. Z100.\nM30\n");
        Path sub = main.resolveSibling("O1000.nc");
        Files.writeString(sub, "O1000\nG00 X20. Z-10.\nG00 X52.\nZ2.\nM99\n");
        Run r = gcnc("compile", main.toString(), "--machine", "fanuc", "-o", main.resolveSibling("part.dmc").toString());
        assertEquals(1, r.status(), r.err());
        assertTrue(r.err().contains(sub + ":2:1: error[E305]: rapid move enters the blank"), r.err());
        assertTrue(r.err().contains(sub + ":2:1: note[E145]: in O1000 called from line 7 of the program file (M98 P1000)"),
                r.err());
    }

    @Test
    void theSampleProgramChecksClean() {
        Run r = gcnc("check", "samples/turning.nc");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("samples/turning.nc: 13 blocks, no errors"), r.out());
        assertEquals("", r.err());
    }

    @Test
    void everyErrorOfTheProgramInOneRunSortedWithExitOne() throws IOException {
        Path p = program(String.join("\n",
                "O1001",
                "N10 G21 G90 G98",
                "N20 G50 S2500",
                "N30 M11",
                "N40 T0101",
                "N50 G01 X40. Z2. F120.",       // cut before M03
                "N60 S1200 M03",
                "N70 G01 X40. Z-10. F120.",   // clean: N50 broke only a prerequisite, so its state was taken
                "N80 G01 Z-12. $",              // illegal character
                "N90 G02 X46. Z-40. R3.",       // R cannot span the chord
                "N100 M05",
                "N110 M30", ""));
        Run r = gcnc("check", p.toString());
        assertEquals(1, r.status(), r.err());
        String[] lines = r.err().strip().split("\n");
        assertEquals(4, lines.length, r.err());
        assertEquals("For more information about this error try `gcnc explain E051`.", lines[3]);
        assertTrue(lines[0].startsWith(p + ":6:"), lines[0]);
        assertTrue(lines[1].startsWith(p + ":9:15: error[E003]:"), lines[1]);
        assertTrue(lines[2].startsWith(p + ":10:"), lines[2]);
        assertTrue(r.out().contains("3 errors"), r.out());
    }

    @Test
    void spanishMessagesOnRequest() throws IOException {
        Path p = program("G21\nM93\nM30\nG00 X1. Z1.\n");
        Run r = gcnc("check", "--lang", "es", p.toString());
        assertEquals(1, r.status());
        assertTrue(r.err().contains("error[E012]: Función miscelánea no definida M93"), r.err());
        // a block after M30 never runs: a warning (issue 31), in Spanish the thesis's words
        assertTrue(r.err().contains("warning[E053]: La función M30 solo puede estar al final del programa"), r.err());
    }

    @Test
    void aMissingFileIsAnIoProblemExitTwo() {
        Run r = gcnc("check", "no/such/file.nc");
        assertEquals(2, r.status());
        assertEquals("no/such/file.nc:1:1: error[E500]: cannot read: no such file or directory\n", r.err());
    }

    @Test
    void aBrokenProfileIsReportedWhereItIsBroken() throws IOException {
        Path bad = Files.createTempFile("lathe", ".machine");
        Files.writeString(bad, Files.readString(Path.of("tables/machines/generic.machine")).replace("x.sign = 1", "x.sign = up"));
        Run r = gcnc("check", "--machine", bad.toString(), "samples/turning.nc");
        assertEquals(2, r.status());
        assertTrue(r.err().startsWith(bad + ":"), r.err());
        assertTrue(r.err().contains("error[E400]: 'up' is not a number (x.sign)"), r.err());
    }

    /** A bad simulator key was once reported by the simulator, at the program's line of that number. */
    @Test
    void aSimulatorKeyFaultIsTheProfilesNeverTheProgramsLine() throws IOException {
        Path bad = Files.createTempFile("lathe", ".machine");
        String text = Files.readString(Path.of("tables/machines/generic.machine"))
                + "sim.tool.default.holder = 0, 5; 20, 5; 2, 9; 20, 40; 0, 40\n";
        Files.writeString(bad, text);
        Run r = gcnc("simulate", "--machine", bad.toString(), "samples/turning.nc");
        assertEquals(2, r.status(), r.err());
        int line = text.substring(0, text.indexOf("sim.tool.default.holder")).split("\n", -1).length;
        assertTrue(r.err().startsWith(bad + ":" + line + ":"), r.err());
        assertTrue(r.err().contains("error[E400]: 'sim.tool.default.holder' must be a convex outline"), r.err());
        assertFalse(r.err().contains("turning.nc"), r.err());
    }

    @Test
    void unknownOptionsAndCommandsAreUsageErrors() {
        assertEquals(2, gcnc("check", "--frobnicate", "x.nc").status());
        assertEquals(2, gcnc("launch").status());
        assertEquals(2, gcnc().status());
        assertEquals(2, gcnc("check", "--lang", "fr", "samples/turning.nc").status());
    }

    @Test
    void helpAndVersion() {
        Run help = gcnc("--help");
        assertEquals(0, help.status());
        assertTrue(help.out().contains("compile"), help.out());
        Run version = gcnc("--version");
        assertEquals(0, version.status());
        assertTrue(version.out().startsWith("gcnc "), version.out());
    }

    @Test
    void tablesPrintsTheThesisTables() {
        Run r = gcnc("tables");
        assertEquals(0, r.status());
        assertTrue(r.out().contains("Control thesis-2004:"), r.out());
        assertTrue(r.out().contains("G02       01  arc_cw                Circular interpolation clockwise"), r.out());
        assertTrue(r.out().contains("M03       02  start    spindle_cw      Spindle rotation normal (CW)"), r.out());
        assertTrue(r.out().contains("E054  comment opened inside a comment"), r.out());
    }

    @Test
    void compileReproducesTableFiveTwoByteForByte() throws IOException {
        Path out = Files.createTempDirectory("gcnc-out").resolve("bishop.dmc");
        Run r = gcnc("compile", "samples/bishop.nc", "--machine", "thesis-2004", "--dialect", "thesis", "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(Files.readAllBytes(Path.of("src/test/resources/golden/bishop.thesis-2004.thesis.dmc")), Files.readAllBytes(out));
    }

    @Test
    void aProgramWithErrorsLeavesNoOutputAtAll() throws IOException {
        Path p = program("G21\nG01 X10. Z5.\nM30\n");
        Path out = p.resolveSibling("part.dmc");
        Files.writeString(out, "old output\n");
        Run r = gcnc("compile", p.toString());
        assertEquals(1, r.status(), r.err());
        assertEquals("old output\n", Files.readString(out), "a failed compile must not touch an existing output");
        try (Stream<Path> s = Files.list(p.getParent())) {
            assertFalse(s.anyMatch(f -> f.getFileName().toString().endsWith(".part")), "no temporary file left behind");
        }
    }

    @Test
    void compileWritesTheDefaultDialectAndASourceMap() throws IOException {
        Path p = program(Files.readString(Path.of("samples/turning.nc")));
        Run r = gcnc("compile", p.toString());
        assertEquals(0, r.status(), r.err());
        Path dmc = p.resolveSibling("part.dmc");
        String text = Files.readString(dmc);
        assertTrue(text.startsWith("#GCNC;SH XY;"), "the commands are packed into lines: " + text);
        assertTrue(text.endsWith("EN\n"), text);
        // The side map is a line-number table: header from no block, then a run per emitting block.
        List<String> map = Files.readAllLines(p.resolveSibling("part.dmc.map"));
        assertEquals("# source part.nc", map.get(0), "the map names the G-code file");
        // then the G-code file's SHA-256, and last the DMC's: the map belongs to this DMC (SideFilesTest)
        assertTrue(map.get(1).startsWith("# source sha256 "), map.get(1));
        assertTrue(map.get(map.size() - 1).startsWith("# dmc sha256 "), map.get(map.size() - 1));
        map = map.subList(2, map.size() - 1);
        assertEquals("1 0", map.get(0), "DMC lines 1-4 are the header (vector setup, IT 1, spindle output, limits, homing)");
        assertEquals("5 4", map.get(1), "DMC line 5 starts with G-code line 4's commands (N30 M11: gline=4, then CB4)");
        assertEquals("5.2 5", map.get(2), "its third command (gline=5) starts G-code line 5's");
        List<String> lines = text.lines().toList();
        int en = 0;
        while (!gcnc.dmc.DmcReader.statements(lines.get(en)).contains("EN")) {
            en++;
        }
        assertEquals((en + 1) + "." + gcnc.dmc.DmcReader.statements(lines.get(en)).indexOf("EN") + " 0", map.get(map.size() - 1),
                "from EN on (the routines, the handlers) is the footer");
        Run inline = gcnc("compile", "--source-map", p.toString(), "-o", p.resolveSibling("inline.dmc").toString());
        assertEquals(0, inline.status(), inline.err());
        assertTrue(Files.readString(p.resolveSibling("inline.dmc")).contains("NO L7\n"));
    }

    @Test
    void anUnwritableOutputIsNamedAsTheProblem() {
        Run r = gcnc("compile", "samples/turning.nc", "-o", "no/such/dir/part.dmc");
        assertEquals(2, r.status());
        assertEquals("no/such/dir/part.dmc:1:1: error[E500]: cannot write: no such file or directory\n", r.err());
    }
}
