package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.diag.Diagnostic;
import gcnc.diag.Severity;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.sim.SimOptions;
import gcnc.sim.StockSize;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * The real Haas and Fanuc programs of {@code ../shared/corpus} (read where they are, never copied),
 * each on the shipped haas or fanuc machine it was written for: every file but the ones with real
 * mistakes checks clean, and then compiles and simulates clean from a blank that fits the part
 * (scripts/corpus-table.sh gives the same blanks), except the one fault of a program that only the
 * simulator sees; the real mistakes are reported on their lines and on no line of a correct block.
 */
class CorpusTest {
    private static final Path CORPUS = Path.of("../shared/corpus");
    private static final Tables TABLES = Tables.builtIn();

    /** Errors, as "line:code", for the files that have real mistakes. */
    private static final Map<String, List<String>> MISTAKES = Map.of(
            // M93 typed for M03, 'Z,15' with a comma, a line of text outside a comment
            "misc/O0002_lathe_project_2.nc", List.of("10:E012", "19:E121", "27:E109"),
            // faces to mm, past the centreline; F50 is 50 mm/rev under the Fanuc power-up G99
            "uncleengineer/t24.gcode", List.of("2:E015", "4:E103", "7:E015", "11:E015"),
            // 'P1 X100.0 Z50.0': a P that no function takes
            "misc/O1000_with_G02.nc", List.of("3:E036"));
    // cadekiely/O58214.nc is no longer among them (issue 17): its G70 carries U and D, which the
    // control ignores, so they are warning E642 (pinned below), not an error

    /** Warnings, as "line:code", that a file must have (every file is checked for them, none may be missing). */
    private static final Map<String, List<String>> WARNED = Map.of(
            "cadekiely/O58214.nc", List.of("31:E642", "31:E642"));

    /** The blank each file is simulated from where the haas profile's 2 in bar does not fit it. */
    private static final Map<String, SimOptions> BLANKS = Map.of(
            // "material is .375 SS round stock"; 150 mm out of the jaws puts its face at work zero
            "mark-brannan/SB_SC_spacer12_Op2_v11_15.nc", SimOptions.defaults().withStock(new StockSize(9.525, 160, 150)),
            "mark-brannan/SB_ViseStopRails_v11_06.nc", SimOptions.defaults().withStock(new StockSize(9.525, 160, 150)),
            // its G71 roughs from X1.5 and its finish faces the shoulder up to X1.5: a 1.5 in bar
            "enier-cnc/weld_pin.nc", SimOptions.defaults().withStock(new StockSize(38.1, 160, 150)),
            // the second operation on a 350 mm flange: no bar describes it, so no blank
            "gcodeworkshop/0100.nc", SimOptions.defaults().withoutBlank());

    /** What the simulator finds in a program that checks clean, as "line:code". */
    private static final Map<String, List<String>> SIMULATED = Map.of(
            // G00 G40 X2.1: cancelling the parting blade's nose compensation on the rapid out of its
            // groove moves the blade sideways by its 0.2 mm nose radius into the groove's wall
            "misc/O10061_crush_ring.nc", List.of("143:E305"));

    private static String machineFor(String name) {
        return name.startsWith("gcodeworkshop/") || name.contains("O1000") || name.startsWith("uncleengineer/")
                ? "fanuc" : "haas";
    }

    @TestFactory
    Stream<DynamicTest> realProgramsAreCleanButForTheirRealMistakes() throws Exception {
        // a clone away from ../shared skips it; .ci/run, beside it, runs every file
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isDirectory(CORPUS),
                "needs ../shared/corpus (the real programs beside the checkout); absent here");
        List<Path> files;
        try (Stream<Path> s = Files.walk(CORPUS)) {
            files = s.filter(Files::isRegularFile).filter(p -> !p.getFileName().toString().equals("README.md"))
                    .sorted().toList();
        }
        assertEquals(15, files.size(), "the corpus has fifteen programs");
        List<DynamicTest> tests = new ArrayList<>();
        for (Path p : files) {
            String name = CORPUS.relativize(p).toString();
            tests.add(dynamicTest(name, () -> {
                MachineProfile m = ProfileLoader.load(machineFor(name), TableSource.builtIn(), TABLES);
                Compiler.Result r;
                try (Reader in = Files.newBufferedReader(p, StandardCharsets.UTF_8)) {
                    r = Compiler.check(in, new Compiler.Settings(TABLES, m, Dialect.Kind.GALIL, Optional.empty()));
                }
                assertEquals(MISTAKES.getOrDefault(name, List.of()), errors(r), name + ": check");
                if (WARNED.containsKey(name)) {
                    assertEquals(WARNED.get(name), found(r, Severity.WARNING, WARNED.get(name)), name + ": warnings");
                }
                if (MISTAKES.containsKey(name)) {
                    return;
                }
                Compiler.Result sim;
                try (Reader in = Files.newBufferedReader(p, StandardCharsets.UTF_8)) {
                    sim = Compiler.compile(in, new Compiler.Settings(TABLES, m, Dialect.Kind.GALIL,
                            Optional.of(BLANKS.getOrDefault(name, SimOptions.defaults()))), line -> { });
                }
                assertEquals(SIMULATED.getOrDefault(name, List.of()), errors(sim), name + ": compile and simulate");
            }));
        }
        return tests.stream();
    }

    /** The findings of {@code severity} with the codes named in {@code wanted}, as "line:code" in order. */
    private static List<String> found(Compiler.Result r, Severity severity, List<String> wanted) {
        List<String> codes = wanted.stream().map(w -> w.substring(w.indexOf(':') + 1)).toList();
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            if (d.severity() == severity && codes.contains(d.code().id())) {
                out.add(d.span().line() + ":" + d.code().id());
            }
        }
        return out;
    }

    private static List<String> errors(Compiler.Result r) {
        Map<Integer, String> byLine = new TreeMap<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            if (d.severity() == Severity.ERROR) {
                byLine.merge(d.span().line(), d.code().id(), (a, b) -> a + "+" + b);
            }
        }
        List<String> out = new ArrayList<>();
        byLine.forEach((line, code) -> out.add(line + ":" + code));
        return out;
    }
}
