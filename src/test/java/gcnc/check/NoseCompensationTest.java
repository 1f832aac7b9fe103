package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.diag.Diagnostic;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * Tool nose radius compensation (G41/G42/G40): compensated contours as reviewed (outside, inside,
 * both directions, every tip direction, line-arc corners, a G70 finish), in
 * src/test/resources/nose/NAME.MACHINE.expanded (regenerate with -PupdateGolden and review), the
 * same programs through the whole pipeline without a finding, and each error as a tiny program.
 */
class NoseCompensationTest {
    private static final Path DIR = Path.of("src/test/resources/nose");

    /**
     * The fanuc machine with a nose on offsets 1 to 9 whose tip direction is the offset's number
     * (radius 0.5 mm), for the tip-direction goldens.
     */
    static MachineProfile tips() throws Exception {
        String text = Files.readString(Path.of("tables/machines/fanuc.machine"), StandardCharsets.UTF_8)
                .lines().filter(l -> !l.startsWith("nose.") && !l.startsWith("name ")).collect(Collectors.joining("\n"));
        StringBuilder sb = new StringBuilder("name = fanuc-tips\n").append(text).append('\n');
        for (int t = 1; t <= 9; t++) {
            sb.append("nose.").append(t).append(" = 0.5, ").append(t).append('\n');
        }
        Path p = Files.createTempFile("fanuc-tips", ".machine");
        Files.writeString(p, sb.toString(), StandardCharsets.UTF_8);
        try {
            return ProfileLoader.load(p.toString(), TableSource.builtIn(), Run.TABLES);
        } finally {
            Files.delete(p);
        }
    }

    static MachineProfile machine(String name) throws Exception {
        return name.equals("fanuc-tips") ? tips() : Run.profile(name);
    }

    private static List<Path> programs() throws Exception {
        try (Stream<Path> s = Files.list(DIR)) {
            return s.filter(p -> p.toString().endsWith(".nc")).sorted().toList();
        }
    }

    @TestFactory
    Stream<DynamicTest> everyCompensatedContourIsAsReviewed() throws Exception {
        boolean update = Boolean.getBoolean("gcnc.updateGolden");
        return programs().stream().map(p -> dynamicTest(p.getFileName().toString(), () -> {
            String name = p.getFileName().toString();
            CycleExpansionTest.Expanded e;
            try (Reader in = Files.newBufferedReader(p, StandardCharsets.UTF_8)) {
                e = CycleExpansionTest.expand(machine(name.split("\\.")[1]), in);
            }
            for (Diagnostic d : e.diagnostics().sorted()) {
                assertTrue(d.severity() != gcnc.diag.Severity.ERROR, () -> name + ": " + d);
            }
            String actual = CycleExpansionTest.render(e);
            Path golden = DIR.resolve(name.replaceAll("\\.nc$", ".expanded"));
            if (update) {
                Files.writeString(golden, actual, StandardCharsets.UTF_8);
            }
            assertEquals(Files.readString(golden, StandardCharsets.UTF_8), actual);
        }));
    }

    /**
     * The same programs compiled and replayed: clean, and the simulator finds nothing (travel,
     * chuck, rapids), with no blank (--stock none), as they finish parts already roughed: a blank
     * given would be where G54 is (work.G54 = face), and these programs are written for the
     * profile's own work zero. The
     * Galil program, with its source map inline, is as reviewed in NAME.MACHINE.dmc.
     */
    @TestFactory
    Stream<DynamicTest> everyCompensatedProgramCompilesAndSimulatesClean() throws Exception {
        boolean update = Boolean.getBoolean("gcnc.updateGolden");
        return programs().stream().map(p -> dynamicTest(p.getFileName().toString(), () -> {
            String name = p.getFileName().toString();
            gcnc.Compiler.Settings settings = new gcnc.Compiler.Settings(Run.TABLES, machine(name.split("\\.")[1]),
                    "galil", java.util.Optional.of(gcnc.sim.SimOptions.defaults().withoutBlank()), true);
            gcnc.Compiler.Result r;
            StringBuilder dmc = new StringBuilder();
            try (Reader in = Files.newBufferedReader(p, StandardCharsets.UTF_8)) {
                r = gcnc.Compiler.compile(in, settings, l -> dmc.append(l.text()).append('\n'));
            }
            assertTrue(r.ok(), () -> name + ": " + r.diagnostics().sorted());
            assertEquals(0, r.simulation().orElseThrow().findings(), () -> name + ": " + r.diagnostics().sorted());
            Path golden = DIR.resolve(name.replaceAll("\\.nc$", ".dmc"));
            if (update) {
                Files.writeString(golden, dmc.toString(), StandardCharsets.UTF_8);
            }
            assertEquals(Files.readString(golden, StandardCharsets.UTF_8), dmc.toString());
        }));
    }

    /**
     * On axis-parallel elements the imaginary tip of a tip-3 tool runs on the programmed line itself;
     * around the convex shoulder corner it goes by the intersection of the offset lines, and the
     * cancel (type A) leaves the last element perpendicular to its end: the tip r past it in Z.
     */
    @Test
    void anOutsideTurningToolsTipFollowsTheProgrammedDiameterAndFace() throws Exception {
        Run r = Run.of("fanuc", "G21 G99\nT0101\nG97 S1000 M03\nG00 X60. Z5.\nG42 G00 X20. Z2.\n"
                + "G01 Z-10. F0.2\nX40.\nZ-20.\nG40 G00 X60. Z5.\nM30\n");
        assertEquals("", errs(r));
        assertEquals(List.of("5 G00 X20.0000 Z1.2000", "6 G01 X20.0000 Z-10.0000", "7 G01 X38.4000 Z-10.0000",
                "7 G01 X40.0000 Z-10.0000", "7 G01 X40.0000 Z-10.8000", "8 G01 X40.0000 Z-20.8000", "9 G00 X60.0000 Z5.0000"), moves(r, 5));
    }

    @Test
    void offsetZeroOrAnOffsetWithoutANoseCompensatesByNothingWithANote() {
        Run r = Run.of("fanuc", "G21 G99\nT0202\nG97 S1000 M03\nG00 X60. Z5.\nG42 G00 X20. Z2.\n"
                + "G01 Z-10. F0.2\nX40.\nG40 G00 X60. Z5.\nM30\n");
        assertEquals("", errs(r));
        assertEquals("E177@5:1 [G42, 2, fanuc]", codes(r, gcnc.diag.Severity.NOTE));
        assertEquals(List.of("5 G00 X20.0000 Z2.0000", "6 G01 X20.0000 Z-10.0000", "7 G01 X40.0000 Z-10.0000",
                "8 G00 X60.0000 Z5.0000"), moves(r, 5));
    }

    private static final String HEAD = "G21 G99\nT0101\nG97 S1000 M03\nG00 X60. Z5.\n";

    @Test
    void aStartUpMoveShorterThanTheNoseRadiusIsE170() {
        Run r = Run.of("fanuc", HEAD + "G00 X20.5 Z2.\nG42 G01 X20. Z2. F0.2\nZ-10.\nG40 G00 X60.\nM30\n");
        assertEquals("E170@6:1", errs(r));
    }

    @Test
    void anArcAsTheStartUpOrTheCancelMoveIsE171() {
        Run start = Run.of("fanuc", HEAD + "G42 G02 X40. Z-5. R10. F0.2\nG01 Z-10.\nG40 G00 X60.\nM30\n");
        assertEquals("E171@5:1", errs(start));
        Run exit = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG40 G02 X30. Z-15. R5.\nM30\n");
        assertEquals("E171@7:1", errs(exit));
    }

    @Test
    void aGrooveNarrowerThanTheNoseIsE172OnTheBlockTheNoseCannotFollow() {
        // a 1 mm groove for a 0.8 mm nose (1.6 mm across)
        Run r = Run.of("fanuc", HEAD + "G42 G00 X40. Z2.\nG01 Z-10. F0.2\nX30.\nZ-11.\nX40.\nZ-20.\nG40 G00 X60.\nM30\n");
        assertEquals("E172@8:1", errs(r));
    }

    @Test
    void aConcaveArcTighterThanTheNoseIsE173() {
        Run r = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG02 X21. Z-10.5 R0.5\nG01 X40.\n"
                + "G40 G00 X60.\nM30\n");
        assertTrue(errs(r).contains("E173@7:1"), errs(r));
        assertTrue(r.diagnostics.sorted().stream().anyMatch(d -> d.code() == gcnc.diag.Code.E173_NOSE_ARC_TOO_TIGHT
                && d.args().equals(List.of("0.5", "0.8"))), r.diagnostics.sorted()::toString);
    }

    @Test
    void changingSidesWithoutG40IsE174() {
        Run r = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG41 X40.\nG40 G00 X60.\nM30\n");
        assertEquals("E174@7:1", errs(r));
    }

    @Test
    void endingWithCompensationInForceWarnsE175AndKeepsEveryBlock() {
        Run r = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nX40.\nM30\n");
        assertEquals("", errs(r));
        assertEquals("E175@8:1 [G42]", codes(r, gcnc.diag.Severity.WARNING));
        assertEquals(List.of(5, 6, 7, 8), r.blocks.stream().skip(4).map(CheckedBlock::line).toList());
    }

    @Test
    void moreBlocksWithoutAMoveThanTheLookAheadIsE176() {
        StringBuilder p = new StringBuilder(HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\n");
        for (int i = 0; i < NoseCompensation.STILL_LIMIT + 1; i++) {
            p.append("M08\n");
        }
        p.append("X40.\nG40 G00 X60.\nM30\n");
        Run r = Run.of("fanuc", p.toString());
        assertEquals("E176@" + (7 + NoseCompensation.STILL_LIMIT) + ":1", errs(r));
        Run within = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nM08\nG04 P500\nX40.\nG40 G00 X60.\nM30\n");
        assertEquals("", errs(within));
    }

    @Test
    void aRoughingCycleG28OrAToolChangeUnderCompensationIsE178() {
        assertEquals("E178@6:1", errs(Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG28 U0. W0.\nG40 G00 X60.\nM30\n")));
        assertEquals("E178@6:1", errs(Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nT0303\nG40 G00 X60.\nM30\n")));
        assertEquals("E178@6:1", errs(Run.of("fanuc", HEAD + "G42 G00 X62. Z2.\nG71 U2. R0.5\n"
                + "G71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nN20 G01 Z-10.\nG40 G00 X60.\nM30\n")).split(",")[0]);
        assertEquals("", errs(Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG40 G28 U0. W0.\nM30\n")));
    }

    /**
     * A thread pass is spindle-synchronised and never offset: a G32, G92 or G76 under G41/G42 is
     * E178, and so is a block that would run a modal thread or turning cycle again (the pipeline
     * fuzz campaign found both reaching the offset code and throwing).
     */
    @Test
    void aThreadOrAModalCycleAgainUnderCompensationIsE178() {
        assertEquals("E178@6:1", errs(Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG32 W-10. F1.5\nG40 G00 X60.\nM30\n")));
        assertEquals("E178@6:1", errs(Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG92 X18. Z-10. F1.5\nG40 G00 X60.\nM30\n")));
        assertEquals("E178@6:1", errs(Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG76 X17. Z-10. P1000 Q300 F1.5\n"
                + "G40 G00 X60.\nM30\n")));
        // G92 in force, then G42 with X alone: the thread cycle would run again under compensation
        Run again = Run.of("fanuc", HEAD + "G00 X20. Z2.\nG92 X18. Z-10. F1.5\nG42 X17.6\nG40 G00 X60.\nM30\n");
        assertEquals("E178@7:1", errs(again));
        assertTrue(again.messages().contains("G92 again with nose radius compensation G42 in force"), again.messages());
        // a G00 with the G42 ends the G92 (same group): what follows is compensated, not threaded
        assertEquals("", errs(Run.of("fanuc", HEAD + "G00 X20. Z2.\nG92 X18. Z-10. F1.5\nG42 G00 X30.\n"
                + "X17.6\nG40 G00 X60.\nM30\n")));
    }

    @Test
    void aCompensatedMoveBeyondTheTravelIsE179WhereTheProgrammedOneIsInside() {
        // X-9. is radius -4.5 mm, inside fanuc's -5 mm; the nose ends 0.8 mm further: the tip at -5.3 mm
        Run r = Run.of("fanuc", HEAD + "G42 G00 X10. Z2.\nG01 Z-2. F0.2\nX-9.\nG40 G00 Z5.\nM30\n");
        assertEquals("E179@7:1", errs(r));
        assertTrue(r.diagnostics.sorted().get(0).args().equals(List.of("X", "-5.3", "-5", "215", "fanuc")),
                r.diagnostics.sorted()::toString);
        assertEquals("", errs(Run.of("fanuc", HEAD + "G00 X10. Z2.\nG01 Z-2. F0.2\nX-9.\nG00 Z5.\nM30\n")));
    }

    /** G42 alone arms the compensation for the next move; G40 alone makes the next move the cancel. */
    @Test
    void g42AndG40InBlocksOfTheirOwnTakeEffectWithTheNextMove() {
        Run r = Run.of("fanuc", HEAD + "G42\nM08\nG00 X20. Z2.\nG01 Z-10. F0.2\nX40.\nG40\nM09\nG00 X60. Z5.\nM30\n");
        assertEquals("", errs(r));
        assertEquals(List.of("7 G00 X20.0000 Z1.2000", "8 G01 X20.0000 Z-10.0000", "9 G01 X38.4000 Z-10.0000",
                "12 G00 X60.0000 Z5.0000"), moves(r, 7));
        assertEquals(List.of(5, 6, 7, 8, 9, 10, 11, 12, 13), r.blocks.stream().skip(4).map(CheckedBlock::line).toList());
    }

    /**
     * The other position of the block delete switch goes on with the compensation in progress: the
     * arc after the '/' block is a contour element there too, not a start-up (that would be E171).
     */
    @Test
    void aBlockDeleteBlockUnderCompensationStartsNothingAgain() throws Exception {
        CycleExpansionTest.Expanded e = CycleExpansionTest.expand("fanuc", new java.io.StringReader(
                HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\n/M08\nG02 X30. Z-15. R5.\nG01 Z-20.\nG40 G00 X60.\nM30\n"));
        assertEquals("[]", e.diagnostics().sorted().toString());
    }

    /** The moves of the blocks from {@code fromLine} on, in program terms, one line per motion. */
    static List<String> moves(Run r, int fromLine) {
        return r.blocks.stream().filter(b -> b.line() >= fromLine).flatMap(b -> b.motions().stream()
                .filter(m -> m instanceof Motion.Linear).map(m -> b.line() + " " + (((Motion.Linear) m).rapid() ? "G00 " : "G01 ")
                        + CycleExpansionTest.at(((Motion.Linear) m).to(), b.frame()))).toList();
    }

    @Test
    void theTipsTestMachineHasEveryTipDirection() throws Exception {
        MachineProfile p = tips();
        for (int t = 1; t <= 9; t++) {
            assertEquals(t, p.nose(t).tip());
            assertEquals(0.5 * p.x().countsPerMm(), p.nose(t).radius(), 1e-9);
        }
        assertEquals(0, p.nose(10).radius());
    }

    /** The errors, as {@code E170@6:1}, comma-separated. */
    static String errs(Run r) {
        return r.diagnostics.sorted().stream().filter(d -> d.severity() == gcnc.diag.Severity.ERROR)
                .map(d -> d.code().id() + "@" + d.span().line() + ":" + d.span().column()).collect(Collectors.joining(", "));
    }

    /** The findings of one severity, with their arguments. */
    static String codes(Run r, gcnc.diag.Severity s) {
        return r.diagnostics.sorted().stream().filter(d -> d.severity() == s)
                .map(d -> d.code().id() + "@" + d.span().line() + ":" + d.span().column() + " " + d.args())
                .collect(Collectors.joining(", "));
    }
}
