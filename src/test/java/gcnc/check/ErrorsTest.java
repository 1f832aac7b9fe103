package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.diag.Code;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Every error number the checker can raise, each with a tiny program and its exact place.
 * Programs: '|' separates lines; '$|' is a 5-line preamble that makes cutting legal (G21 G90 G98,
 * G50 S2500, M11, T0101, S1200 M03), so the line under test is line 6. An M30 line is appended.
 */
class ErrorsTest {
    static final String PREAMBLE = "G21 G90 G98|G50 S2500|M11|T0101|S1200 M03|";

    static Run run(String program) {
        String p = program.replace("$|", PREAMBLE) + (program.contains("M30") ? "" : "|M30");
        return Run.generic(p.replace('|', '\n'));
    }

    @ParameterizedTest(name = "{0} -> {1}")
    @CsvSource(delimiter = ';', value = {
        "G; 1:1:E001",
        "M; 1:1:E002",
        "G00 X; 1:5:E006",
        "G00 X1. X2.; 1:9:E007",
        "F0; 1:1:E008",
        "G00 X30000.; 1:5:E009",
        "G07; 1:1:E011",
        "M77; 1:1:E012",
        "N1.5; 1:1:E013",
        "G00 X1.2.3; 1:5:E014",
        "G00 X500.; 1:5:E015",
        "G50 S5000|S4500; 2:1:E119",
        "G00 G01 X1.; 1:5:E016",
        "M03 M05; 1:5:E016",
        "G20 G21; 1:5:E016",
        "G28 G04 X1.; 1:5:E017",
        "G04 G28 U0.; 1:5:E018",
        "G04 G29 U0.; 1:5:E019",
        "G04 G50 S100; 1:5:E020",
        "G28 G92 X1.; 1:5:E020",
        "G04 Z1.; 1:5:E022",
        "G50 U1.; 1:5:E023",
        "G50 W1.; 1:5:E024",
        "G00 X10. R5.; 1:10:E025",
        "G00 X10. I5.; 1:10:E026",
        "G00 X10. K5.; 1:10:E027",
        "G00 X10. U5.; 1:10:E028",
        "G00 Z10. W5.; 1:10:E029",
        "G04; 1:1:E030",
        "G28; 1:1:E030",
        "G50; 1:1:E031",
        "$|G96|G01 X10. F100.; 6:1:E648",
        "P10; 1:1:E032",
        "O1|O2; 2:1:E033",
        "G21|O5; 2:1:E034",
        "G01 G04 X1.; 1:5:E035",
        "G00 X1. P5; 1:9:E036",
        // E037 where the axis cannot feed: per revolution of a stopped spindle (G99)
        "$|M05|G99|G01 X40. F0.2; 8:1:E037",
        // per minute (G98) a move with the spindle stopped cuts only if it meets stock: compile decides
        "$|M05|G01 X40. F100.; 7:1:E660",
        // a Haas-style bar pull on the generic machine: M05, chuck open (M10 there), a G98 feed, chuck closed
        "$|M05|M10|G01 Z50. F1000.|M11; 8:1:E661",
        "G21 G90 G98|G50 S2500|T0101|S1200 M03|G01 X40. F100.; 5:1:E038",
        "$|G01 X40.; 6:1:E039",
        "$|M10; 6:1:E040",
        "$|M10 M05; 6:1:E040",
        "G21 G90 G98|M11|T0101|M03|G01 X40. F100.; 5:1:E041",
        "G29 U0.; 1:1:E042",
        "N10|N10; 2:1:E043",
        "N20|N10; 2:1:E043",
        "X10.; 1:1:E044",
        "T9901; 1:1:E046",
        "T0199; 1:1:E047",
        "$|S3000; 6:1:E048",
        "$|G02 X46. Z-33. F100.; 6:1:E049",
        "S100; 1:1:E050",
        "G21 G90 G98|G50 S2500|M11|G01 X40. F100.; 4:1:E051",
        "M30|G00 X10.; 2:1:E053",
        "$|G00 X40. Z0.|G02 X46. Z-33. R1. F100.; 7:16:E101",
        "$|G00 X40. Z0.|G02 X46. Z-33. I5. F100.; 7:16:E102",
        "$|G99|G01 X40. F3.; 7:10:E103",
        "G21 G90 G99|G50 S2500|M11|T0101|M03|G01 X40. F0.2; 6:10:E104",
        "$|G00 X40. Z0.|G02 X40. Z0. R5. F100.; 7:14:E105",
        "$|G00 X210. Z0.|G03 X210. Z-20. R10. F100.; 7:17:E106",
    })
    void reportsTheErrorWhereItIs(String program, String expected) {
        Run r = run(program);
        assertEquals(expected, r.errors());
        for (gcnc.diag.Diagnostic d : r.diagnostics.sorted()) {
            for (gcnc.tables.ErrorMessages.Lang lang : gcnc.tables.ErrorMessages.Lang.values()) {
                String text = Run.TABLES.messages().render(d.code(), d.args(), lang);
                assertEquals(false, text.contains("{"), "every placeholder filled: " + text);
            }
        }
    }

    /** With the shipped Table 7 every function takes X; a table that forbids it makes 21 reachable. */
    @Test
    void e021WithATable7ThatForbidsX() throws Exception {
        java.nio.file.Path dir = java.nio.file.Files.createTempDirectory("gcnc-tables");
        java.nio.file.Path src = java.nio.file.Path.of("tables");
        java.nio.file.Files.createDirectories(dir.resolve("machines"));
        java.nio.file.Files.createDirectories(dir.resolve("controls/thesis-2004"));
        for (String f : new String[] {"controls/thesis-2004/control.cfg", "controls/thesis-2004/m_codes.csv",
            "parameter_limits.csv", "tool_offsets.csv", "work_offsets.csv", "errors.csv", "phrases.csv", "galil_models.csv",
            "machines/generic.machine"}) {
            java.nio.file.Files.copy(src.resolve(f), dir.resolve(f));
        }
        String usage = java.nio.file.Files.readString(src.resolve("controls/thesis-2004/g_codes.csv"))
                .replace("4,0,dwell,X U P,", "4,0,dwell,U P,");
        java.nio.file.Files.writeString(dir.resolve("controls/thesis-2004/g_codes.csv"), usage);
        gcnc.tables.Tables t = gcnc.tables.Tables.load(gcnc.tables.TableSource.directory(dir));
        gcnc.machine.MachineProfile p = gcnc.machine.ProfileLoader.load("generic", gcnc.tables.TableSource.directory(dir), t);
        gcnc.diag.Diagnostics out = new gcnc.diag.Diagnostics();
        Checker c = new Checker(t, p, out);
        c.check(Run.block(1, "G04 X1."));
        assertEquals(Code.E021_X_NOT_ALLOWED, out.sorted().get(0).code());
        assertEquals(gcnc.diag.Span.of(1, 5), out.sorted().get(0).span());
    }

    @Test
    void malformedBlocksAreCountedButNotChecked() {
        gcnc.diag.Diagnostics out = new gcnc.diag.Diagnostics();
        Checker c = new Checker(Run.TABLES, Run.profile("generic"), out);
        gcnc.ir.RawBlock bad = Run.block(1, "G07 X");
        gcnc.ir.RawBlock malformed = new gcnc.ir.RawBlock(1, bad.words(), bad.last(), true);
        assertEquals(java.util.List.of(), c.check(malformed));
        assertEquals(0, out.size());
        c.check(Run.block(2, "M30"));
        gcnc.ir.RawBlock late = new gcnc.ir.RawBlock(3, bad.words(), bad.last(), true);
        c.check(late);
        c.finish(3);
        assertEquals(1, out.size());
        assertEquals(Code.E053_M30_NOT_LAST, out.sorted().get(0).code());
    }

    @Test
    void e052ProgramWithoutM30() {
        assertEquals("2:1:E052", Run.generic("G21\nG00 X10.").errors());
    }

    @Test
    void blankAndCommentLinesAfterM30AreFine() {
        assertEquals("", Run.generic("G21\nM30\n\n(end)\n").errors());
    }

    @Test
    void e116AfterTheErrorCapReportsOnceAndStops() {
        String program = "G07\nG07\nG07\nG07\nG07\n";
        Run r = Run.of(Run.profile("generic"), program, 3);
        assertEquals("1:1:E011, 2:1:E011, 3:1:E011, 4:1:E116", r.errors());
    }

    @Test
    void multiErrorProgramReportsEveryErrorOnItsOwnLine() {
        String program = String.join("\n",
                "O1001",
                "N10 G21 G90 G98",
                "N20 G50 S2500",
                "N30 M11",
                "N40 T0101",
                "N50 G01 X40. F100.",          // cut before M03 (51); F is not kept
                "N60 S1200 M03",
                "N70 F100.",
                "N80 M05",
                "N90 M10",
                "N100 G01 X40.",               // spindle stopped, chuck open, G98: a pull unless it meets stock (661)
                "N110 M11",
                "N120 M03",
                "N130 G01 X40.",
                "N140 S3000",                  // above the G50 clamp (48)
                "N150 G00 X40. Z0.",
                "N160 G02 X46. Z-33. R1.",     // R cannot span the chord (101)
                "N170 G00 X500.",              // beyond the travel (15)
                "N180 G01 X42.",
                "N190 M05",
                "N200 M30");
        assertEquals("6:5:E051, 11:6:E661, 15:6:E048, 17:21:E101, 18:10:E015", Run.generic(program).errors());
    }

    @Test
    void missingFeedIsReportedOnItsLine() {
        String program = "O1\nN10 G21 G90 G98\nN20 G50 S2500\nN30 M11\nN40 T0101\nN50 S1200 M03\nN60 G01 X40.\nN70 M30";
        assertEquals("7:5:E039", Run.generic(program).errors());
    }
}
