package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Severity;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import gcnc.parse.BlockReader;
import java.io.Reader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * G01 chamfering and corner rounding (docs/chamfer.md): the finishing contours in
 * src/test/resources/chamfer/NAME.MACHINE.nc expanded and compiled as reviewed (.expanded, .dmc;
 * regenerate with -PupdateGolden and review), the moves a corner makes on each control's form,
 * and each error as a tiny program with the line and column it is reported at.
 */
class CornerInsertionTest {
    private static final Path DIR = Path.of("src/test/resources/chamfer");

    /** The program checked as the compiler reads it for {@code p} (its control's comments). */
    /** The generic machine (mm, X a diameter, no nose) under {@code control}. */
    static CycleExpansionTest.Expanded run(String control, String program) {
        try {
            return CycleExpansionTest.expand(Run.profileWithControl("generic", control), new StringReader(HEAD.get(control) + program));
        } catch (Exception e) {
            throw new IllegalStateException(e);
        }
    }

    /** Four lines that set up a cut on each control; the program under test starts on line 5. */
    private static final java.util.Map<String, String> HEAD = java.util.Map.of(
            "haas", "G00 G18 G40 G80 G99\nT0101\nG97 S1000 M03\nG00 X20. Z2.\n",
            "fanuc-a", "G21 G18 G40 G99\nT0101\nG97 S1000 M03\nG00 X20. Z2.\n",
            "fanuc-b", "G21 G18 G40 G95\nT0101\nG97 S1000 M03\nG00 X20. Z2.\n",
            "thesis-2004", "N1 G21 G90\nN2 M11\nN3 T0101\nN4 G00 X20. Z2.\n");

    static String errs(CycleExpansionTest.Expanded e) {
        return e.diagnostics().sorted().stream().filter(d -> d.severity() == Severity.ERROR)
                .map(d -> d.code().id() + "@" + d.span().line() + ":" + d.span().column()).collect(Collectors.joining(", "));
    }

    /** Every move from line {@code fromLine} on, in program terms: "line G01 X.. Z..", arcs with their centre. */
    static List<String> moves(CycleExpansionTest.Expanded e, int fromLine) {
        List<String> out = new ArrayList<>();
        for (CheckedBlock b : e.blocks()) {
            if (b.line() < fromLine) {
                continue;
            }
            for (Motion m : b.motions()) {
                if (m instanceof Motion.Linear l) {
                    out.add(b.line() + (l.rapid() ? " G00 " : " G01 ") + CycleExpansionTest.at(l.to(), b.frame()));
                } else if (m instanceof Motion.Arc a) {
                    out.add(b.line() + (a.clockwise() ? " G02 " : " G03 ") + CycleExpansionTest.at(a.to(), b.frame())
                            + " about " + CycleExpansionTest.at(a.centre(), b.frame()));
                }
            }
        }
        return out;
    }


    @TestFactory
    Stream<DynamicTest> everyChamferedContourIsAsReviewed() throws Exception {
        return Run.programsIn(DIR).stream().map(p -> dynamicTest(p.getFileName().toString(),
                () -> Run.expandsAsGolden(p, Run.profile(p.getFileName().toString().split("\\.")[1]))));
    }

    /** The same contours compiled and replayed with no blank (they finish roughed parts; a blank would move G54 to its face): clean, DMC as reviewed. */
    @TestFactory
    Stream<DynamicTest> everyChamferedContourCompilesAndSimulatesClean() throws Exception {
        return Run.programsIn(DIR).stream().map(p -> dynamicTest(p.getFileName().toString(), () -> {
            Run.compilesCleanAsGolden(p, Run.profile(p.getFileName().toString().split("\\.")[1]));
        }));
    }

    // ---- the moves a corner makes ----------------------------------------------------------------

    @Test
    void aHaasChamferShortensTheBlockAndTheNextMoveStartsWhereItEnds() {
        CycleExpansionTest.Expanded e = run("haas", "G01 Z0. F0.1\nX30. ,C1.\nZ-10.\nM30\n");
        assertEquals("", errs(e));
        assertEquals(List.of("5 G01 X20.0000 Z0.0000", "6 G01 X28.0000 Z0.0000", "6 G01 X30.0000 Z-1.0000",
                "7 G01 X30.0000 Z-10.0000"), moves(e, 5));
    }

    @Test
    void aHaasCornerRoundingIsATangentArcAtTheBlocksLine() {
        CycleExpansionTest.Expanded e = run("haas", "G01 Z-10. F0.1 ,R2.\nX30.\nM30\n");
        assertEquals("", errs(e));
        // along -Z then up +X: the path turns right, so the arc is clockwise (G02) about X24 Z-8
        assertEquals(List.of("5 G01 X20.0000 Z-8.0000", "5 G02 X24.0000 Z-10.0000 about X24.0000 Z-8.0000",
                "6 G01 X30.0000 Z-10.0000"), moves(e, 5));
        // and the program's G01 stays in force after the inserted arc
        assertEquals("6 G01 X30.0000 Z-10.0000", moves(e, 6).get(0));
    }

    @Test
    void aHaasChamferWorksAtAnyAngle() {
        CycleExpansionTest.Expanded e = run("haas", "G01 Z0. F0.1\nX30. Z-5. ,C1.\nZ-10.\nM30\n");
        assertEquals("", errs(e));
        List<String> m = moves(e, 6);
        assertEquals(3, m.size(), m::toString);
        assertEquals("7 G01 X30.0000 Z-10.0000", m.get(2));
    }

    @Test
    void fanucLettersMakeTheSameCornersAsHaasCommas() {
        String haas = "G01 Z0. F0.1\nX30. ,C1.\nZ-10. ,R2.\nX40.\nZ-20.\nM30\n";
        String fanuc = "G01 Z0. F0.1\nX30. C-1.\nZ-10. R2.\nX40.\nZ-20.\nM30\n";
        List<String> expected = moves(run("haas", haas), 5);
        assertEquals(expected, moves(run("fanuc-a", fanuc), 5));
        assertEquals(expected, moves(run("fanuc-b", fanuc), 5));
        assertEquals(expected, moves(run("haas", haas.replace(",C1.", "K1.")), 5), "Haas K: a 90-degree chamfer");
    }

    @Test
    void anIncrementalNextMoveStillEndsWhereItIsProgrammed() {
        CycleExpansionTest.Expanded e = run("fanuc-a", "G01 Z0. F0.1\nX30. C-1.\nW-10.\nU10.\nM30\n");
        assertEquals("", errs(e));
        assertEquals(List.of("7 G01 X30.0000 Z-10.0000", "8 G01 X40.0000 Z-10.0000"), moves(e, 7));
        CycleExpansionTest.Expanded b = run("fanuc-b", "G01 Z0. F0.1\nX30. C-1.\nG91 Z-10.\nX10.\nM30\n");
        assertEquals("", errs(b));
        assertEquals(List.of("7 G01 X30.0000 Z-10.0000", "8 G01 X40.0000 Z-10.0000"), moves(b, 7));
    }

    @Test
    void aHaasDwellMayStandBetweenTheTwoMoves() {
        CycleExpansionTest.Expanded e = run("haas", "G01 Z-10. F0.1 ,C1.\nG04 P0.5\nX30.\nM30\n");
        assertEquals("", errs(e));
        assertEquals(List.of("5 G01 X20.0000 Z-9.0000", "5 G01 X22.0000 Z-10.0000", "7 G01 X30.0000 Z-10.0000"),
                moves(e, 5));
    }

    @Test
    void fanucRIsTheArcRadiusOnG02AndICAndKStayAnArcsWordsOnG02() {
        assertEquals("", errs(run("fanuc-a", "G02 X30. Z-5. R5. F0.1\nM30\n")));
        assertEquals("", errs(run("haas", "G01 Z0. F0.1\nG02 X30. Z-5. I5. K0.\nM30\n")));
    }

    // ---- the errors, each where the control stops --------------------------------------------------

    @Test
    void aCommaWordOnTheThesisControlIsE604() {
        assertTrue(errs(run("thesis-2004", "N5 G01 X30. ,C1. F100.\nN6 M30\n")).contains("E604@5:13"));
    }

    // ---- without the comma, with the comma, and the angle: each control as it reads them ----------

    @Test
    void haasReadsRAndCWithoutTheCommaAsItsCommaForms() {
        // a Haas school program's corners, at any angle, as ,C and ,R
        CycleExpansionTest.Expanded bare = run("haas", "G01 Z0. F0.1\nX30. Z-5. C1.\nZ-10. R2.\nX40.\nM30\n");
        CycleExpansionTest.Expanded comma = run("haas", "G01 Z0. F0.1\nX30. Z-5. ,C1.\nZ-10. ,R2.\nX40.\nM30\n");
        assertEquals("", errs(bare));
        assertEquals(moves(comma, 5), moves(bare, 5));
        assertEquals(5, moves(bare, 6).size(), moves(bare, 6)::toString); // three moves and two corners
    }

    @Test
    void withTheCAxisEngagedACIsTheAxisNotAChamfer() {
        // M154 engages the C axis (a note); its C is then E650 (not supported), not a chamfer
        String found = errs(run("haas", "G01 Z0. F0.1\nM154\nX30. C90.\nZ-10.\nM30\n"));
        assertEquals("E650@7:6", found);
    }

    @Test
    void theThesisControlHasNoCornersButTheBlockStillRunsSoNoArcAfterItEchoes() {
        // E025 (its Table 5) on the R: the block is refused, and the tool taken to Z-10. as if the R
        // were struck out, so the G03 from there is judged from there (no E101, no E049 on line 9)
        String p = "N5 G50 S2000\nN6 S500 M03\nN7 G01 Z-10. R2. F100.\nN8 X30.\nN9 G03 X40. Z-15. R5.\nN10 M30\n";
        assertEquals("E025@7:14", errs(run("thesis-2004", p)));
        assertEquals("", errs(run("thesis-2004", p.replace(" R2.", ""))));
    }

    @Test
    void fanucCAndRWithoutTheCommaAreForASquareCornerAndTheErrorNamesTheCommaForm() {
        // a taper into a Z move: PS0054; the message names ,R, which the control takes at any angle
        String p = "G01 Z0. F0.1\nX30. Z-5. R1.\nZ-10.\nX40. Z-12.\nG02 X50. Z-17. R5.\nM30\n";
        CycleExpansionTest.Expanded e = run("fanuc-a", p);
        assertEquals("E210@6:11", errs(e), "and nothing echoes on the arc of line 9");
        assertTrue(e.diagnostics().sorted().get(0).toString().contains(",R"), e.diagnostics().sorted()::toString);
        assertEquals("E210@6:11", errs(run("fanuc-b", p)));
        assertEquals("", errs(run("haas", p)), "a Haas reads R at any angle");
    }

    @Test
    void fanucDirectDrawingCommaCAndRAreCornersAtAnyAngle() {
        CycleExpansionTest.Expanded fanuc = run("fanuc-a", "G01 Z0. F0.1\nX30. Z-5. ,C1.\nZ-10. ,R2.\nX40.\nM30\n");
        CycleExpansionTest.Expanded haas = run("haas", "G01 Z0. F0.1\nX30. Z-5. ,C1.\nZ-10. ,R2.\nX40.\nM30\n");
        assertEquals("", errs(fanuc));
        assertEquals(moves(haas, 5), moves(fanuc, 5));
        assertEquals("", errs(run("fanuc-b", "G01 Z-5. ,C1. F0.1\nX30.\nM30\n")));
    }

    @Test
    void anAngleWithOneEndCoordinateGivesTheOther() {
        // from X20 Z2 (radius 10) at 150 degrees to X40 (radius 20): dz = 10 / tan 150 = -17.3205
        for (String c : List.of("haas", "fanuc-a", "fanuc-b")) {
            CycleExpansionTest.Expanded e = run(c, "G01 X40. F0.1 ,A150.\nM30\n");
            assertEquals("", errs(e), c);
            assertEquals(List.of("5 G01 X40.0000 Z-15.3205"), moves(e, 5), c);
        }
        // Z given: X from the angle (180 + 30 degrees goes down and back: X falls 2 * 5.7735 on the diameter)
        assertEquals(List.of("5 G01 X8.4530 Z-8.0000"), moves(run("haas", "G01 Z-8. F0.1 ,A210.\nM30\n"), 5));
        // U is a coordinate too, and the angle's line takes the corner after it
        CycleExpansionTest.Expanded e = run("fanuc-a", "G01 U20. F0.1 ,A150. ,R2.\nZ-30.\nM30\n");
        assertEquals("", errs(e));
        assertEquals(3, moves(e, 5).size(), moves(e, 5)::toString);
        assertEquals("6 G01 X40.0000 Z-30.0000", moves(e, 6).get(moves(e, 6).size() - 1));
    }

    @Test
    void theTwoBlockAngleFormEndsTheFirstLineWhereTheTwoLinesMeet() {
        // from X20 Z2 along -Z (180 degrees), then up (90 degrees) to X40 Z-20: the corner is X20 Z-20
        for (String c : List.of("haas", "fanuc-a", "fanuc-b")) {
            CycleExpansionTest.Expanded e = run(c, "G01 F0.1 ,A180.\nX40. Z-20. ,A90.\nM30\n");
            assertEquals("", errs(e), c);
            assertEquals(List.of("5 G01 X20.0000 Z-20.0000", "6 G01 X40.0000 Z-20.0000"), moves(e, 5), c);
        }
        // with a corner R between the two lines (the form ,A1_ ,R1_ ; X3_ Z3_ ,A2_)
        CycleExpansionTest.Expanded r = run("fanuc-a", "G01 F0.1 ,A180. ,R2.\nX40. Z-20. ,A90.\nM30\n");
        assertEquals("", errs(r));
        assertEquals(List.of("5 G01 X20.0000 Z-18.0000", "5 G02 X24.0000 Z-20.0000 about X24.0000 Z-18.0000",
                "6 G01 X40.0000 Z-20.0000"), moves(r, 5));
    }

    @Test
    void anAngleFormGcncDoesNotReadIsNotSupportedYetE606AndTheLinesStillRun() {
        // an angle alone whose next block does not complete the form; an angle with both X and Z
        assertEquals("E606@5:10", errs(run("haas", "G01 F0.1 ,A150.\nZ-10.\nM30\n")));
        assertEquals("E606@5:21", errs(run("fanuc-a", "G01 X40. Z-10. F0.1 ,A30.\nM30\n")));
        // an angle alone at the end of the program (no M30 after it either)
        assertEquals("E052@5:1, E606@5:10", errs(run("haas", "G01 F0.1 ,A150.\n")));
        // two parallel angles meet nowhere
        assertEquals("E634@5:10", errs(run("fanuc-a", "G01 F0.1 ,A180.\nX40. Z-20. ,A180.\nM30\n")));
    }

    @Test
    void anAngleAlongTheOtherAxisIsE632AndOnAG00E633AndOnTheThesisE604() {
        assertEquals("E632@5:15", errs(run("haas", "G01 X40. F0.1 ,A0.\nM30\n")));
        assertEquals("E632@5:15", errs(run("fanuc-a", "G01 Z-5. F0.1 ,A90.\nM30\n")));
        assertEquals("E633@5:10", errs(run("haas", "G00 X40. ,A150.\nM30\n")));
        assertTrue(errs(run("thesis-2004", "N5 G01 X40. ,A150. F100.\nN6 M30\n")).contains("E604@5:13"));
    }

    @Test
    void aCornerOnABlockThatIsNotAG01IsE607() {
        assertEquals("E607@5:10", errs(run("haas", "G00 X30. ,C1.\nZ-10.\nM30\n")));
    }

    @Test
    void twoCornerWordsInOneBlockAreE608AtTheSecond() {
        assertEquals("E608@5:20", errs(run("haas", "G01 X30. F0.1 ,C1. ,R1.\nZ-10.\nM30\n")));
        assertEquals("E608@5:19", errs(run("fanuc-a", "G01 X30. F0.1 C1. R1.\nZ-10.\nM30\n")));
    }

    @Test
    void noMoveAfterTheCornerIsE609() {
        // the program ends
        assertEquals("E609@5:15", errs(run("haas", "G01 X30. F0.1 ,C1.\nM30\n")));
        // Fanuc: the very next block must move (PS0051)
        assertEquals("E609@5:15", errs(run("fanuc-a", "G01 X30. F0.1 C1.\nG04 P500\nZ-10.\nM30\n")));
        // Haas: blocks without a move may stand between, up to the look-ahead
        StringBuilder p = new StringBuilder("G01 X30. F0.1 ,C1.\n");
        for (int i = 0; i < CornerInsertion.STILL_LIMIT + 1; i++) {
            p.append("M08\n");
        }
        p.append("Z-10.\nM30\n");
        assertEquals("E609@5:15", errs(run("haas", p.toString())));
    }

    @Test
    void aNextMoveThatIsNotAG01IsE610() {
        assertEquals("E610@5:15", errs(run("haas", "G01 X30. F0.1 ,C1.\nG00 Z-10.\nM30\n")));
        assertEquals("E610@5:15", errs(run("haas", "G01 X30. F0.1 ,R1.\nG02 X40. Z-5. R5.\nM30\n")));
    }

    @Test
    void aCornerLargerThanAMoveIsE611() {
        // X20 to X30 is 5 mm on the radius
        assertEquals("E611@6:6", errs(run("haas", "G01 Z0. F0.1\nX30. ,C6.\nZ-10.\nM30\n")));
        assertEquals("E611@6:6", errs(run("haas", "G01 Z0. F0.1\nX30. ,C2.\nZ-1.\nM30\n")));
        assertEquals("", errs(run("haas", "G01 Z0. F0.1\nX30. ,C5.\nZ-5.\nM30\n")), "a chamfer may take a whole move");
    }

    @Test
    void aNinetyDegreeFormBetweenMovesNotAlongTheAxesIsE612() {
        // Fanuc C on a taper (PS0054: E210, which names ,C); the same on Haas with ,C is a chamfer at any angle
        assertEquals("E210@6:11", errs(run("fanuc-a", "G01 Z0. F0.1\nX30. Z-5. C1.\nZ-10.\nM30\n")));
        assertEquals("", errs(run("haas", "G01 Z0. F0.1\nX30. Z-5. ,C1.\nZ-10.\nM30\n")));
        // I after a move along X (it belongs after a move along Z)
        assertEquals("E612@6:6", errs(run("fanuc-a", "G01 Z0. F0.1\nX30. I1.\nZ-10.\nM30\n")));
    }

    @Test
    void aFanucCornerWhoseSignPointsAwayFromTheNextMoveIsE615() {
        assertEquals("E615@6:6", errs(run("fanuc-a", "G01 Z0. F0.1\nX30. C1.\nZ-10.\nM30\n")));
        assertEquals("E615@6:6", errs(run("fanuc-b", "G01 Z0. F0.1\nX30. R-1.\nZ10.\nM30\n")));
        assertEquals("", errs(run("fanuc-a", "G01 Z0. F0.1\nX30. C-1.\nZ-10.\nM30\n")));
        // Haas reads only the size of I and K (its manual: they stand where ,C does)
        assertEquals("", errs(run("haas", "G01 Z0. F0.1\nX30. K1.\nZ-10.\nM30\n")));
    }

    @Test
    void twoMovesInLineHaveNoCornerE613() {
        assertEquals("E613@5:15", errs(run("haas", "G01 Z-5. F0.1 ,C1.\nZ-10.\nM30\n")));
    }

    @Test
    void aCornerInAStockRemovalContourIsMadeForTheRoughingAndTheG70() {
        String p = "G00 X50. Z2.\nG71 P10 Q20 U0.5 W0.1 D1. F0.2\nN10 G00 X20.\nG01 Z-10. ,C1.\nN20 X50.\nG70 P10 Q20\nM30\n";
        CycleExpansionTest.Expanded e = run("haas", p);
        assertEquals("", errs(e));
        // the G70 (line 10) runs the chamfer: Z-9 then X22 Z-10 (two moves at line 8)
        List<String> finish = moves(e, 7).stream().filter(m -> m.startsWith("8 ")).collect(Collectors.toList());
        assertTrue(finish.contains("8 G01 X22.0000 Z-10.0000"), finish::toString);
        // Haas's 90-degree I, a Haas R without the comma, and Fanuc's two-block G71 with C
        assertEquals("", errs(run("haas", p.replace("G01 Z-10. ,C1.", "G01 Z-10. I1."))));
        assertEquals("", errs(run("haas", p.replace("G01 Z-10. ,C1.", "G01 Z-10. R1."))));
        String f = "G00 X50. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U0.5 W0.1 F0.2\nN10 G00 X20.\nG01 Z-10. C1.\n"
                + "N20 X50.\nG70 P10 Q20\nM30\n";
        assertEquals("", errs(run("fanuc-a", f)));
        // a corner that cannot be made is the flow's error, and the contour runs without it
        assertEquals("E609@10:10", errs(run("fanuc-a", f.replace("N20 X50.", "N20 X50. C1."))));
    }

    @Test
    void g72AndG73ContoursTakeTheirCornersToo() {
        String p = "G00 X52. Z2.\nG72 P10 Q20 U0.4 W0.2 D1. F0.2\nN10 G00 Z-10.\nG01 X40. ,C1.\nZ-5. ,R1.\nX20. ,C0.5\n"
                + "N20 Z2.\nG70 P10 Q20\nG00 X52. Z2.\nG73 P30 Q40 U0.4 W0.2 I3. K1. D3 F0.2\nN30 G00 X20. Z1.\n"
                + "G01 Z-10. R1.\nX30. C0.5\nN40 Z-20.\nG70 P30 Q40\nM30\n";
        CycleExpansionTest.Expanded e = run("haas", p);
        assertEquals("", errs(e));
        // each G70 runs each corner block as two moves (the block shortened, then the chamfer or arc)
        List<String> all = moves(e, 5);
        for (int line : new int[] {8, 9, 10, 16, 17}) {
            String at = line + " ";
            assertEquals(2, all.stream().filter(m -> m.startsWith(at)).count(), line + ": " + all);
        }
        // Fanuc: C without the comma is for 90 degrees with the sign of the next move (-Z after line 17: C-0.5)
        assertEquals("E615@17:6", errs(run("fanuc-a", p)));
        assertEquals("", errs(run("fanuc-a", p.replace("X30. C0.5", "X30. C-0.5"))));
    }

    /** The rough passes of a G71 over a chamfered and rounded contour never go below the finished contour. */
    @Test
    void roughPassesOverAChamferedContourNeverCutBelowIt() {
        String contour = "N10 G00 X16.\nG01 Z0.\nX24. ,C1.5\nZ-10. ,R2.\nX30. ,C1.\nX40. ,A150.\nN20 Z-30.\n";
        for (String c : List.of("haas", "fanuc-a")) {
            String cycle = c.equals("haas") ? "G71 P10 Q20 U0.5 W0.1 D1. F0.2\n" : "G71 U1. R0.5\nG71 P10 Q20 U0.5 W0.1 F0.2\n";
            CycleExpansionTest.Expanded e = run(c, "G00 X50. Z2.\n" + cycle + contour + "G70 P10 Q20\nM30\n");
            assertEquals("", errs(e), c);
            // the cycle's passes are at its line; the G70 runs the contour's blocks at their own lines
            int roughLine = c.equals("haas") ? 6 : 7;
            int g70 = roughLine + 8;
            List<String> finish = new ArrayList<>();
            List<double[]> rough = new ArrayList<>();
            for (String m : moves(e, 5)) {
                int line = Integer.parseInt(m.substring(0, m.indexOf(' ')));
                String[] w = m.split(" ");
                if (line > roughLine && line < g70) {
                    finish.add(m);
                } else if (line == roughLine && w[1].equals("G01")) {
                    rough.add(new double[] {Double.parseDouble(w[2].substring(1)), Double.parseDouble(w[3].substring(1))});
                }
            }
            List<double[]> finished = path(finish);
            assertTrue(rough.size() > 10, rough::toString);
            for (double[] p : rough) {
                double floor = lowest(finished, p[1]);
                assertTrue(p[0] >= floor - 1e-3, c + ": a rough cut at X" + p[0] + " Z" + p[1] + " is below the contour's X" + floor);
            }
        }
    }

    /** The points of a path of {@link #moves} (X a diameter), its arcs sampled on their circle. */
    static List<double[]> path(List<String> moves) {
        List<double[]> finished = new ArrayList<>();
        for (String m : moves) {
            String[] w = m.split(" ");
            double[] xz = {Double.parseDouble(w[2].substring(1)), Double.parseDouble(w[3].substring(1))};
            if (w[1].equals("G01") || w[1].equals("G00") || finished.isEmpty()) {
                finished.add(xz);
                continue;
            }
            double[] from = finished.get(finished.size() - 1);
            double cx = Double.parseDouble(w[5].substring(1)) / 2;
            double cz = Double.parseDouble(w[6].substring(1));
            double r = Math.hypot(from[0] / 2 - cx, from[1] - cz);
            double a0 = Math.atan2(from[0] / 2 - cx, from[1] - cz);
            double sweep = Math.atan2(xz[0] / 2 - cx, xz[1] - cz) - a0;
            sweep -= 2 * Math.PI * Math.round(sweep / (2 * Math.PI)); // a corner's arc: the short way
            for (int k = 1; k < 40; k++) {
                double a = a0 + sweep * k / 40;
                finished.add(new double[] {2 * (cx + r * Math.sin(a)), cz + r * Math.cos(a)});
            }
            finished.add(xz);
        }
        return finished;
    }

    /** The greatest diameter the finished path has at {@code z} (its pieces interpolated), or -infinity. */
    static double lowest(List<double[]> path, double z) {
        double best = Double.NEGATIVE_INFINITY;
        for (int i = 1; i < path.size(); i++) {
            double[] a = path.get(i - 1);
            double[] b = path.get(i);
            double lo = Math.min(a[1], b[1]);
            double hi = Math.max(a[1], b[1]);
            if (z < lo - 1e-9 || z > hi + 1e-9) {
                continue;
            }
            double x = Math.abs(b[1] - a[1]) < 1e-9 ? Math.max(a[0], b[0]) : a[0] + (b[0] - a[0]) * (z - a[1]) / (b[1] - a[1]);
            best = Math.max(best, x);
        }
        return best;
    }

    @Test
    void theCornerComposesWithNoseCompensation() throws Exception {
        MachineProfile p = Run.profile("fanuc");
        CycleExpansionTest.Expanded e = CycleExpansionTest.expand(p, new StringReader("G21 G99\nT0303\nG97 S1000 M03\nG00 X20. Z2.\n"
                + "G42 G01 Z0. F0.1\nX30. C-1.\nZ-10.\nG40 G00 X60. Z5.\nM30\n"));
        assertEquals("", errs(e));
        // the compensated path goes round the chamfer's two corners: more moves on line 6 than the two it has
        assertTrue(moves(e, 6).stream().filter(s -> s.startsWith("6 ")).count() > 2, moves(e, 6)::toString);
    }
}
