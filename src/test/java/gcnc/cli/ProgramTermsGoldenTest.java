package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.SetupSheet;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * What a person reads of a run, byte for byte (issue 22: program terms first): the summary line,
 * the JSON report, the drawing and the setup sheet of the same locating pin written in inches and
 * in millimetres (src/test/resources/terms/), on the Haas. The two differ in the program's terms
 * and agree in the machine frame. After a deliberate change: {@code gradle junitPlatformTest
 * -PupdateGolden}, and review the diff in src/test/resources/golden/terms/.
 */
class ProgramTermsGoldenTest {
    private static final Path GOLDEN = Path.of("src/test/resources/golden/terms");
    private static final List<String> PROGRAMS = List.of("pin-inch", "pin-mm");

    private static Path program(String name) {
        return Path.of("src/test/resources/terms", name + ".nc");
    }

    @TestFactory
    Stream<DynamicTest> summaryJsonDrawingAndSheetMatchTheirGoldenFiles() {
        return PROGRAMS.stream().flatMap(name -> Stream.of(
                dynamicTest(name + ".nc summary: " + name + ".haas.summary.txt", () -> golden(name + ".haas.summary.txt", summary(name))),
                dynamicTest(name + ".nc JSON: " + name + ".haas.json", () -> golden(name + ".haas.json", json(name))),
                dynamicTest(name + ".nc drawing: " + name + ".haas.svg", () -> golden(name + ".haas.svg", svg(name))),
                dynamicTest(name + ".nc setup sheet: " + name + ".haas.html", () -> golden(name + ".haas.html", sheet(name)))));
    }

    /** The summary lines of {@code gcnc simulate}, the findings on standard error left out. */
    private static String summary(String name) {
        CliTest.Run r = CliTest.gcnc("simulate", program(name).toString(), "--machine", "haas");
        return r.out();
    }

    /** The JSON report; gcnc's own version masked (it is the build's, not the run's). */
    private static String json(String name) {
        CliTest.Run r = CliTest.gcnc("simulate", program(name).toString(), "--machine", "haas", "--format", "json");
        return r.out().replaceFirst("\"version\": \"[^\"]*\"", "\"version\": \"VERSION\"");
    }

    private static String svg(String name) throws Exception {
        Path out = Files.createTempDirectory("gcnc-terms").resolve(name + ".svg");
        CliTest.gcnc("simulate", program(name).toString(), "--machine", "haas", "--svg", out.toString());
        return Files.readString(out, StandardCharsets.UTF_8);
    }

    /** The sheet {@code gcnc sheet} writes (the Gradle plugin's gcncSimulate writes it with the same SetupSheet.of). */
    private static String sheet(String name) throws Exception {
        Path out = Files.createTempDirectory("gcnc-terms").resolve(name + ".html");
        CliTest.Run r = CliTest.gcnc("sheet", program(name).toString(), "--machine", "haas", "-o", out.toString());
        // the pins rapid into the blank on purpose (E305, status 1): the sheet lists the findings
        assertEquals(1, r.status(), r.err());
        return Files.readString(out, StandardCharsets.UTF_8);
    }

    @Test
    void theSheetsLogLineLeadsWithTheProgramNumberAndProgramTerms() throws Exception {
        Session session = Session.open(Session.Options.defaults().withMachine("haas"));
        Compiler.Result r = session.compile(program("pin-inch"));
        SetupSheet sheet = new SetupSheet("pin-inch.nc", "O1301", session.profile(), r.simulation().orElseThrow(),
                List.of());
        // each of its two tools starts the spindle: 2 s for it to reach speed before the first feed
        // the part (its feed moves), not the G28 home moves that reach 16.69 in out
        assertEquals("O1301, cycle about 0:00:48; part X -0.0600..2.1000 (diameter), Z -1.2000..0.1000 in from work zero;"
                + " 2 tools; no findings", sheet.summary());
    }

    private static void golden(String file, String actual) throws Exception {
        Path golden = GOLDEN.resolve(file);
        if (Boolean.getBoolean("gcnc.updateGolden")) {
            Files.createDirectories(GOLDEN);
            Files.writeString(golden, actual, StandardCharsets.UTF_8);
        }
        assertEquals(Files.readString(golden, StandardCharsets.UTF_8), actual, file);
    }
}
