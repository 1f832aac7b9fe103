package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.diag.Diagnostic;
import gcnc.diag.Severity;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
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
 * The real Haas and Fanuc programs of {@code ../shared/corpus} (read where they are, never copied):
 * on the shipped haas or fanuc machine each reports nothing but "not supported yet" (E110, E111)
 * for the functions of the next issue, except the real mistakes the corpus's README names and
 * what following their G71/G72/G70 cycles finds, each on its line and on no line of a correct block.
 */
class CorpusTest {
    private static final Path CORPUS = Path.of("../shared/corpus");
    private static final Tables TABLES = Tables.builtIn();

    /** Errors other than "not supported yet", as "line:code", for the files that have real mistakes. */
    private static final Map<String, List<String>> MISTAKES = Map.of(
            // M93 typed for M03, 'Z,15' with a comma, a line of text outside a comment
            "misc/O0002_lathe_project_2.nc", List.of("10:E012", "19:E121", "27:E109"),
            // faces to mm, past the centreline; F50 is 50 mm/rev under the Fanuc power-up G99
            "uncleengineer/t24.gcode", List.of("2:E015", "4:E103", "7:E015", "11:E015"),
            // 'P1 X100.0 Z50.0': a P that no function takes
            "misc/O1000_with_G02.nc", List.of("3:E036"),
            // G71's contour (X and Z in its first block: type II) is followed; the G70 carries U and
            // D, words a G70 does not take (E161)
            "cadekiely/O58214.nc", List.of("31:E161"),
            // the third G71's contour goes in (X1.1 to X0.8) and out again: a type II pocket, with a Z
            // allowance W0.01 that would cut into the pocket's first wall (E189, Fanuc's rule)
            "enier-cnc/round_head_plug_240926.nc", List.of("98:E189"));

    /**
     * Programs that check clean; 0100.nc since gcnc runs its macro B variables and expressions
     * (docs/program-flow.md), the two enier-cnc shafts since it follows their G42 (docs/nose-compensation.md).
     */
    private static final List<String> CLEAN = List.of("mark-brannan/SB_SC_spacer12_Op2_v11_15.nc",
            "mark-brannan/SB_ViseStopRails_v11_06.nc", "gcodeworkshop/0100.nc",
            "enier-cnc/step_shaft_operation.nc", "enier-cnc/nims_1001_left_part.nc");

    private static String machineFor(String name) {
        return name.startsWith("gcodeworkshop/") || name.contains("O1000") || name.startsWith("uncleengineer/")
                ? "fanuc" : "haas";
    }

    @TestFactory
    Stream<DynamicTest> realProgramsReportOnlyWhatIsNotSupportedYetOrReallyWrong() throws Exception {
        assertTrue(Files.isDirectory(CORPUS), "../shared/corpus is beside the repository in CI");
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
                    r = Compiler.check(in, new Compiler.Settings(TABLES, m, "galil", Optional.empty()));
                }
                Map<Integer, String> others = new TreeMap<>();
                for (Diagnostic d : r.diagnostics().sorted()) {
                    String id = d.code().id();
                    if (d.severity() == Severity.ERROR && !id.equals("E110") && !id.equals("E111")) {
                        others.merge(d.span().line(), id, (a, b) -> a + "+" + b);
                    }
                }
                List<String> actual = new ArrayList<>();
                others.forEach((line, code) -> actual.add(line + ":" + code));
                assertEquals(MISTAKES.getOrDefault(name, List.of()), actual, name);
                if (CLEAN.contains(name)) {
                    assertTrue(r.ok(), name + " checks clean");
                }
            }));
        }
        return tests.stream();
    }
}
