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


    @TestFactory
    Stream<DynamicTest> everyCompensatedContourIsAsReviewed() throws Exception {
        return Run.programsIn(DIR).stream().map(p -> dynamicTest(p.getFileName().toString(),
                () -> Run.expandsAsGolden(p, machine(p.getFileName().toString().split("\\.")[1]))));
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
        return Run.programsIn(DIR).stream().map(p -> dynamicTest(p.getFileName().toString(), () -> {
            Run.compilesCleanAsGolden(p, machine(p.getFileName().toString().split("\\.")[1]));
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

    /**
     * Fanuc changes sides in offset mode without an alarm (the old E174 error was wrong by the
     * manual): a warning; the G42 path ends perpendicular, the block with G41 moves as programmed
     * from there, and G41 starts with the next move.
     */
    @Test
    void changingSidesWithoutG40WarnsE174AndStartsTheOtherSideWithTheNextMove() {
        Run r = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG41 X40.\nZ-20.\nG40 G00 X60.\nM30\n");
        assertEquals("", errs(r));
        assertEquals("E174@7:1 [G41, G42]", codes(r, gcnc.diag.Severity.WARNING));
        List<String> m = moves(r, 6);
        assertEquals("6 G01 X20.0000 Z-10.8000", m.get(0)); // G42 ends perpendicular (tip 3, r 0.8)
        assertEquals("7 G01 X40.0000 Z-10.0000", m.get(1)); // the block's own move, as programmed
        // G41 starts with Z-20. (a start-up from X40 Z-10), the nose now on the other side of the line
        assertTrue(m.get(2).startsWith("8 G01"), m::toString);
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

    /**
     * Fanuc's temporary cancel (0i-TF, "tool nose radius compensation": G28, G30, G53 and a G50
     * position register in offset mode): the path ends perpendicular, the block's move goes from
     * there to the programmed point (G28: to the intermediate point, then home), and the next move
     * is a start-up. A warning (E620), not an error: the control runs it.
     */
    @Test
    void g28UnderCompensationCancelsTheOffsetForItsMoveAndTheNextMoveStartsItAgain() {
        Run r = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG28 U0. W0.\nG00 X30. Z2.\nG01 Z-5.\n"
                + "G40 G00 X60.\nM30\n");
        assertEquals("", errs(r));
        assertEquals("E620@7:1 [G28, G42]", codes(r, gcnc.diag.Severity.WARNING));
        // line 6 ends perpendicular (the tip 0.8 past Z-10 in Z), line 7 goes to the intermediate
        // point (U0 W0: where the programmed tool is), then home; line 8 is the start-up again
        List<String> m = moves(r, 6);
        assertEquals("6 G01 X20.0000 Z-10.8000", m.get(0));
        assertEquals("7 G00 X20.0000 Z-10.0000", m.get(1));
        assertEquals("8 G00 X30.0000 Z1.2000", m.get(3));
        assertEquals("9 G01 X30.0000 Z-5.8000", m.get(4));
        // G53 and a G50 position register: the same temporary cancel
        Run g53 = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG53 X0.\nG00 X30. Z2.\nG40 G00 X60.\nM30\n");
        assertEquals("", errs(g53));
        assertEquals("E620@7:1 [G53, G42]", codes(g53, gcnc.diag.Severity.WARNING));
        // with G40 in the same block it is the cancel move, without a warning
        Run cancel = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG40 G28 U0. W0.\nM30\n");
        assertEquals("", errs(cancel));
        assertEquals("", codes(cancel, gcnc.diag.Severity.WARNING));
    }

    /** The same rules on haas and on fanuc-b, whose position register is G92 (G92 S alone only clamps the spindle). */
    @Test
    void theTemporaryCancelOnHaasAndFanucB() {
        Run haas = Run.of("haas", "G20 G99\nT101\nG97 S1000 M03\nG00 X2.5 Z0.2\nG42 G00 X0.8 Z0.1\nG01 Z-0.5 F0.01\n"
                + "G28 U0.\nG00 X1.2 Z0.1\nG40 G00 X2.5\nM30\n");
        assertEquals("", errs(haas));
        assertEquals("E620@7:1 [G28, G42]", codes(haas, gcnc.diag.Severity.WARNING));
        String b = "G21 G95\nT0101\nG97 S1000 M03\nG00 X60. Z5.\nG42 G00 X20. Z2.\nG01 Z-10. F0.2\n";
        Run register = Run.of(Run.profileWithControl("fanuc", "fanuc-b"), b + "G92 X20. Z-10.\nG00 X30. Z2.\n"
                + "G40 G00 X60.\nM30\n", Checker.ERROR_CAP);
        assertEquals("", errs(register));
        assertEquals("E620@7:1 [G92, G42]", codes(register, gcnc.diag.Severity.WARNING));
        Run clamp = Run.of(Run.profileWithControl("fanuc", "fanuc-b"), b + "G92 S2000\nX30.\nG40 G00 X60.\nM30\n",
                Checker.ERROR_CAP);
        assertEquals("", errs(clamp));
        assertEquals("", codes(clamp, gcnc.diag.Severity.WARNING));
    }

    /**
     * A T word under G41/G42: the control takes the new offset (and its nose) from the next move;
     * gcnc ends the compensated path perpendicular and starts it again, with the new nose, from
     * where the tool stands (E621, a warning).
     */
    @Test
    void aToolChangeUnderCompensationTakesTheNewNoseFromTheNextMove() {
        Run r = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nT0303\nG00 X30. Z2.\nG01 Z-5.\n"
                + "G40 G00 X60.\nM30\n");
        assertEquals("", errs(r));
        assertEquals("E621@7:1 [T0303, G42]", codes(r, gcnc.diag.Severity.WARNING));
        List<String> m = moves(r, 6);
        assertEquals("6 G01 X20.0000 Z-10.8000", m.get(0));
        // offset 03 has a 0.4 mm nose, tip 3: the start-up ends 0.4 mm short of Z2 (its own tool offsets apply)
        assertTrue(m.get(1).startsWith("8 G00 X30.0000"), m::toString);
        assertEquals("9 G01 X30.0000 Z-5.4000", m.get(2));
    }

    /**
     * Cycles under G41/G42 run: G71-G73 rough (note E622: the control roughs the offset contour), G90/G94
     * (E623: it offsets each path), threads, peck and drilling cycles are not offset (E624). gcnc
     * makes their moves as programmed, the path before ending perpendicular, and starts the
     * compensation again with the next move. G31 stays an error (Fanuc alarm PS0035).
     */
    @Test
    void cyclesUnderCompensationRunWithAWarningAndSkipIsE178() {
        Run g71 = Run.of("fanuc", HEAD + "G42 G00 X62. Z2.\nG71 U2. R0.5\n"
                + "G71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nN20 G01 Z-10.\nG70 P10 Q20\nG40 G00 X60.\nM30\n");
        assertEquals("", errs(g71));
        // a note, not a warning: the program is right, gcnc's roughing model differs from the control's
        assertEquals("", codes(g71, gcnc.diag.Severity.WARNING));
        assertEquals("E622@7:1 [G71, G42]", codes(g71, gcnc.diag.Severity.NOTE));
        Run g90 = Run.of("fanuc", HEAD + "G42 G00 X32. Z2.\nG90 X28. Z-10. F0.2\nX26.\nG40 G00 X60.\nM30\n");
        assertEquals("", errs(g90));
        assertEquals("E623@6:1 [G90, G42]", codes(g90, gcnc.diag.Severity.WARNING));
        Run g32 = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG32 W-10. F1.5\nG00 X30.\nG40 G00 X60.\nM30\n");
        assertEquals("", errs(g32));
        assertEquals("E624@6:1 [G32, G42]", codes(g32, gcnc.diag.Severity.WARNING));
        Run g76 = Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG76 X17.4 Z-10. P900 Q300 F1.5\nG40 G00 X60.\nM30\n");
        assertEquals("", errs(g76));
        assertEquals("E624@6:1 [G76, G42]", codes(g76, gcnc.diag.Severity.WARNING));
        assertEquals("E178@6:1", errs(Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG31 W-10. F0.2\nG40 G00 X60.\nM30\n")));
    }

    /**
     * A G41 whose block has an error (Fanuc and Haas read "G04 1P405" as G41 P405: spaces do not part
     * words, and P belongs to no function) still turns the compensation on; a G32 next is not offset
     * and warns (the fuzz campaign found it reaching the offset code and throwing).
     */
    @Test
    void aThreadAfterAG41WhoseBlockHadAnErrorIsNotOffset() {
        for (String machine : List.of("fanuc", "haas")) {
            Run r = Run.of(machine, HEAD + "G00 X22. Z5.\nG41 P405\nG32 Z-10. F1.5\nG00 X40.\nG40 Z20.\nM30\n");
            assertEquals("E032@6:5", errs(r), machine);
            assertTrue(codes(r, gcnc.diag.Severity.WARNING).contains("E624@7:1"), machine + ": " + r.messages());
        }
    }

    /**
     * A thread pass is spindle-synchronised and never offset; a block that runs a modal thread
     * cycle again when it turns the compensation on warns as the cycle's own block would (the
     * pipeline fuzz campaign once found such blocks reaching the offset code and throwing).
     */
    @Test
    void aModalCycleRunAgainByABlockThatTurnsCompensationOnWarns() {
        Run again = Run.of("fanuc", HEAD + "G00 X20. Z2.\nG92 X18. Z-10. F1.5\nG42 X17.6\nG40 G00 X60.\nM30\n");
        assertEquals("", errs(again));
        assertTrue(again.messages().contains("G92 again with nose radius compensation G42 in force"), again.messages());
        // a G00 with the G42 ends the G92 (same group): what follows is compensated, not threaded
        Run ended = Run.of("fanuc", HEAD + "G00 X20. Z2.\nG92 X18. Z-10. F1.5\nG42 G00 X30.\nX17.6\nG40 G00 X60.\nM30\n");
        assertEquals("", errs(ended));
        assertEquals("", codes(ended, gcnc.diag.Severity.WARNING));
        // G40 alone, then a thread: the thread is the cancel move (reached by a straight move)
        assertEquals("", errs(Run.of("fanuc", HEAD + "G42 G00 X20. Z2.\nG01 Z-10. F0.2\nG40\nG32 W-5. F1.5\nM30\n")));
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
