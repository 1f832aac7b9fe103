package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/** explain, machines, completion, exit codes in --help and picocli's suggestions. */
class CommandsTest {
    @Test
    void explainGivesSeverityAndBothLanguages() {
        for (String name : new String[] {"E305", "e305", "305"}) {
            CliTest.Run r = CliTest.gcnc("explain", name);
            assertEquals(0, r.status(), r.err());
            assertTrue(r.out().startsWith("E305 (error)\n"), r.out());
            assertTrue(r.out().contains("  en: rapid move enters the blank at {0}"), r.out());
            assertTrue(r.out().contains("  es: movimiento rápido entra en la pieza en bruto"), r.out());
        }
        CliTest.Run es = CliTest.gcnc("explain", "--lang", "es", "E316");
        assertTrue(es.out().startsWith("E316 (note)\n  es: sin pieza en bruto"), es.out());
    }

    @Test
    void explainShowsTheTablesExplanationWhenItHasOne() throws IOException {
        Path dir = Files.createTempDirectory("gcnc-explain");
        StringBuilder csv = new StringBuilder();
        for (String line : Files.readAllLines(Path.of("tables/errors.csv"))) {
            if (line.startsWith("#") || line.isBlank()) {
                csv.append(line);
            } else if (line.startsWith("code,")) {
                csv.append(line).append(",explanation");
            } else if (line.startsWith("305,")) {
                csv.append(line).append(",A G00 that goes through material breaks the insert: retract first");
            } else {
                csv.append(line).append(",");
            }
            csv.append('\n');
        }
        Files.writeString(dir.resolve("errors.csv"), csv);
        CliTest.Run r = CliTest.gcnc("explain", "--tables", dir.toString(), "E305", "E001");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("\n  A G00 that goes through material breaks the insert: retract first\n"), r.out());
    }

    @Test
    void anUnknownCodeIsAUsageError() {
        CliTest.Run r = CliTest.gcnc("explain", "E999");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("'E999' is not a diagnostic code"), r.err());
        // a G or M code is explained on its control (ExplainFunctionTest); another letter is not a code
        assertEquals(2, CliTest.gcnc("explain", "Q01").status());
    }

    @Test
    void machinesListsEveryShippedProfile() throws IOException {
        CliTest.Run r = CliTest.gcnc("machines");
        assertEquals(0, r.status(), r.err());
        List<String> shipped;
        try (var s = Files.list(Path.of("tables/machines"))) {
            shipped = s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".machine"))
                    .map(n -> n.substring(0, n.length() - 8)).sorted().toList();
        }
        String[] lines = r.out().split("\n");
        assertEquals(shipped.size(), lines.length, r.out());
        for (int i = 0; i < lines.length; i++) {
            assertTrue(lines[i].startsWith(shipped.get(i) + " "), lines[i]);
        }
        assertTrue(r.out().contains("haas           control haas"), r.out());
    }

    /** A shop's --tables folder: its own profiles are listed, and a broken one is reported where it is broken. */
    @Test
    void machinesInATablesFolderListsItsProfilesAndReportsABrokenOne() throws IOException {
        Path dir = Files.createTempDirectory("gcnc-machines");
        try (var s = Files.list(Path.of("tables"))) {
            for (Path p : s.filter(Files::isRegularFile).toList()) {
                Files.copy(p, dir.resolve(p.getFileName()));
            }
        }
        gcnc.TestFiles.copyTree(Path.of("tables/controls"), dir.resolve("controls"));
        Files.createDirectory(dir.resolve("machines"));
        String generic = Files.readString(Path.of("tables/machines/generic.machine"));
        Files.writeString(dir.resolve("machines/shop.machine"), generic.replace("name = generic", "name = shop"));
        Files.writeString(dir.resolve("machines/broken.machine"), generic.replace("x.sign = 1", "x.sign = up"));
        CliTest.Run r = CliTest.gcnc("machines", "--tables", dir.toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.out().startsWith("shop "), r.out());
        assertEquals(1, r.out().split("\n").length, r.out());
        assertTrue(r.err().contains("broken.machine:") && r.err().contains("error[E400]"), r.err());
        CliTest.Run none = CliTest.gcnc("machines", "--tables", dir.resolve("nowhere").toString());
        assertEquals(2, none.status());
    }

    @Test
    void machinesShowPrintsTheProfileAsWritten() throws IOException {
        CliTest.Run r = CliTest.gcnc("machines", "show", "haas");
        assertEquals(0, r.status(), r.err());
        assertEquals(Files.readString(Path.of("tables/machines/haas.machine")), r.out());
        assertEquals(2, CliTest.gcnc("machines", "show", "no-such-lathe").status());
    }

    @Test
    void machinesValidateRunsTheLoadTimeChecks() throws IOException {
        CliTest.Run good = CliTest.gcnc("machines", "validate", "tables/machines/fanuc.machine");
        assertEquals(0, good.status(), good.err());
        assertTrue(good.out().contains("tables/machines/fanuc.machine: valid (machine fanuc, control fanuc-a)"), good.out());
        Path bad = Files.createTempFile("lathe", ".machine");
        Files.writeString(bad, Files.readString(Path.of("tables/machines/generic.machine")).replace("x.sign = 1", "x.sign = up"));
        CliTest.Run r = CliTest.gcnc("machines", "validate", bad.toString());
        assertEquals(2, r.status());
        assertTrue(r.err().startsWith(bad + ":"), r.err());
        assertTrue(r.err().contains("error[E400]: 'up' is not a number (x.sign)"), r.err());
        CliTest.Run sarif = CliTest.gcnc("machines", "validate", "--format", "sarif", bad.toString());
        assertEquals(2, sarif.status());
        com.fasterxml.jackson.databind.JsonNode doc = new com.fasterxml.jackson.databind.ObjectMapper().readTree(sarif.out());
        ReportFormatTest.assertValidSarif(doc);
        assertEquals("E400", doc.get("runs").get(0).get("results").get(0).get("ruleId").asText());
    }

    @Test
    void helpListsTheExitCodes() {
        for (String command : new String[] {"--help", "check --help", "compile --help", "simulate --help"}) {
            CliTest.Run r = CliTest.gcnc(command.split(" "));
            assertEquals(0, r.status());
            assertTrue(r.out().contains("Exit status:"), command + "\n" + r.out());
            assertTrue(r.out().contains("  2   "), r.out());
        }
    }

    @Test
    void mistypedCommandsAndOptionsGetSuggestions() {
        CliTest.Run command = CliTest.gcnc("compil", "x.nc");
        assertEquals(2, command.status());
        assertTrue(command.err().contains("Did you mean: gcnc compile"), command.err());
        CliTest.Run option = CliTest.gcnc("check", "--formt", "json", "x.nc");
        assertEquals(2, option.status());
        assertTrue(option.err().contains("--format"), option.err());
    }

    /** The completion script is valid bash and completes commands and --format values. */
    @Test
    void completionCompletesCommandsAndFormats() throws Exception {
        CliTest.Run r = CliTest.gcnc("completion");
        assertEquals(0, r.status(), r.err());
        Path script = Files.createTempFile("gcnc", ".bash");
        Files.writeString(script, r.out());
        String probe = "source '" + script + "' 2>/dev/null\n"
                + "ask() { COMP_WORDS=(\"$@\"); COMP_CWORD=$(($# - 1)); COMP_LINE=\"$*\"; COMP_POINT=${#COMP_LINE};"
                + " _complete_gcnc 2>/dev/null; echo \"${COMPREPLY[*]}\"; }\n"
                + "ask gcnc com\nask gcnc check --format ''\nask gcnc machines v\n";
        Process bash = new ProcessBuilder("bash", "-c", probe).redirectErrorStream(true).start();
        String out = new String(bash.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(bash.waitFor(60, TimeUnit.SECONDS));
        assertEquals(List.of("compile completion", "gnu json sarif", "validate"), out.lines().toList(), out);
    }

    @Test
    void theOutputCodesExplainThemselves() {
        CliTest.Run r = CliTest.gcnc("explain", Code.E501_OUTPUT_IS_INPUT.id(), Code.E502_OUTPUT_IS_DIRECTORY.id());
        assertEquals(0, r.status());
        assertTrue(r.out().contains("E501 (error)\n  en: the output is the program being read ({0})"), r.out());
        assertTrue(r.out().contains("E502 (error)\n  en: the output is a directory: name a file to write\n"
                + "  es: la salida es un directorio"), r.out());
    }

    /** A run of one command builds only that command; its help and options are the same as with all of them. */
    @Test
    void oneCommandAloneIsTheSameCommand() {
        for (String name : new String[] {"check", "compile", "simulate", "tables", "explain", "machines"}) {
            assertEquals(name, Main.onlyCommand(new String[] {"--lang", "es", name, "part.nc"}));
            picocli.CommandLine all = Main.commandLine(new Main.Streams(System.in, System.out), gcnc.tables.ErrorMessages.Lang.EN);
            picocli.CommandLine one = Main.commandLine(new Main.Streams(System.in, System.out), gcnc.tables.ErrorMessages.Lang.EN,
                    new String[] {name, "--help"});
            assertEquals(1, one.getSubcommands().size());
            assertEquals(all.getSubcommands().get(name).getUsageMessage(), one.getSubcommands().get(name).getUsageMessage());
        }
        for (String[] args : new String[][] {{"help", "check"}, {"completion"}, {"chek"}, {"--help"}, {}}) {
            assertEquals(null, Main.onlyCommand(args), String.join(" ", args) + " needs every command");
        }
    }

    /** A folder is every part program in it (any case, sub-folders too), and several end with a total. */
    @Test
    void aFolderIsItsProgramsAndSeveralEndWithATotal() throws IOException {
        Path dir = Files.createTempDirectory("gcnc-folder");
        Files.createDirectories(dir.resolve("ops"));
        String clean = Files.readString(Path.of("samples/home.nc"));
        Files.writeString(dir.resolve("A.NC"), clean);
        // a feed per revolution after M05: the axis cannot feed (E037)
        Files.writeString(dir.resolve("ops/b.tap"), clean.replace("M30", "G99 G01 X10. F0.1\nM30"));
        Files.writeString(dir.resolve("notes.txt"), "not a program");
        CliTest.Run r = CliTest.gcnc("check", dir.toString());
        assertEquals(1, r.status(), r.err());
        assertTrue(r.out().contains(dir.resolve("A.NC") + ": "), r.out());
        assertTrue(r.err().contains(dir.resolve("ops/b.tap") + ":"), r.err());
        assertFalse((r.out() + r.err()).contains("notes.txt"), r.out());
        // not passed over silently: the note counts it (ProgramFilesTest)
        assertTrue(r.out().contains(dir + ": skipped 1 file (.txt 1)"), r.out());
        String[] lines = r.out().strip().split("\n");
        assertTrue(lines[lines.length - 1].matches("total: 2 programs, \\d+ blocks, \\d+ errors?"), lines[lines.length - 1]);
        Path empty = Files.createTempDirectory("gcnc-empty");
        CliTest.Run none = CliTest.gcnc("check", empty.toString());
        assertEquals(2, none.status());
        assertTrue(none.err().contains(empty + ":1:1: error[E500]: cannot check: no part program (.nc, .ngc, .tap, .gcode) in it"),
                none.err());
        CliTest.Run es = CliTest.gcnc("--lang", "es", "check", empty.toString(), dir.resolve("missing.nc").toString());
        assertTrue(es.err().contains("error[E500]: no se puede comprobar: no hay ningún programa pieza"), es.err());
        assertTrue(es.err().contains("error[E500]: no se puede leer: no existe el archivo o la carpeta"), es.err());
        assertTrue(es.out().strip().endsWith("total: 0 programas, 0 bloques, 2 errores"), es.out());
    }

    /** --stock takes a bore as its fourth number, smaller than the diameter; a bad one is a usage error. */
    @Test
    void stockTakesABore() throws Exception {
        assertEquals(new gcnc.sim.StockSize(65, 150, 100, 30), gcnc.StockText.parse("--stock", "65,150,100,30", 0, false));
        assertEquals(new gcnc.sim.StockSize(65, 150, 7, 0), gcnc.StockText.parse("--stock", "65,150", 7, false));
        // a bar bought in inches, given as it is named; mm may be written too (issue 34)
        assertEquals(new gcnc.sim.StockSize(44.45, 101.6, 50.8, 0), gcnc.StockText.parse("--stock", "1.75in,4in,2\"", 7, false));
        assertEquals(new gcnc.sim.StockSize(44.45, 150, 7, 0), gcnc.StockText.parse("--stock", "44.45mm,150", 7, false));
        for (String bad : new String[] {"65,150,100,65", "65,150,100,70", "65,150,100,-1", "65,150,100,30,1", "65,150,100,NaN", "2ft,150", "in,150"}) {
            org.junit.jupiter.api.Assertions.assertThrows(gcnc.StockText.Bad.class, () -> gcnc.StockText.parse("--stock", bad, 0, false), bad);
        }
        Path p = CliTest.program("G21 G18 G40 G99\nT0808\nG97 S800 M03\nG00 X28. Z5.\nG00 Z2.\nG01 X32. Z0. F0.1\n"
                + "Z-20.\nX28.\nG00 Z5.\nG00 X70. Z50.\nM30\n");
        assertEquals(0, CliTest.gcnc("simulate", p.toString(), "--machine", "fanuc", "--stock", "65,150,100,30").status());
        CliTest.Run bar = CliTest.gcnc("simulate", p.toString(), "--machine", "fanuc", "--stock", "65,150,100");
        assertEquals(1, bar.status());
        assertTrue(bar.err().contains(":7:1: error[E315]"), bar.err());
    }
}
