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

    @Test
    void aCommaWordOnFanucIsDirectDrawingInputNotSupportedYetE605() {
        CycleExpansionTest.Expanded e = run("fanuc-a", "G01 Z-5. ,C1. F0.1\nX30.\nM30\n");
        assertEquals("E605@5:10", errs(e));
    }

    @Test
    void anAngleIsNotSupportedYetE606() {
        assertEquals("E606@5:15", errs(run("haas", "G01 X30. F0.1 ,A30.\nM30\n")));
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
        // Fanuc C on a taper (PS0054); the same on Haas with ,C is a chamfer at any angle
        assertEquals("E612@6:11", errs(run("fanuc-a", "G01 Z0. F0.1\nX30. Z-5. C1.\nZ-10.\nM30\n")));
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
    void aCornerInAStockRemovalContourIsNotSupportedYetE614() {
        String p = "G00 X50. Z2.\nG71 P10 Q20 U0.5 W0.1 D1. F0.2\nN10 G00 X20.\nG01 Z-10. ,C1.\nN20 X50.\nM30\n";
        assertTrue(errs(run("haas", p)).startsWith("E614@8:11"), errs(run("haas", p)));
        // so is Haas's 90-degree I/K there
        String k = p.replace("G01 Z-10. ,C1.", "G01 Z-10. I1.");
        assertTrue(errs(run("haas", k)).startsWith("E614@8:11"), errs(run("haas", k)));
        // Fanuc's two-block G71 reads its contour ahead: the corner is E614 there too, not E108,
        // and the G70 after it does not echo the cycle's failure
        String f = "G00 X50. Z2.\nG71 U1. R0.5\nG71 P10 Q20 U0.5 W0.1 F0.2\nN10 G00 X20.\nG01 Z-10. C1.\n"
                + "N20 X50.\nG70 P10 Q20\nM30\n";
        assertEquals("E614@9:11", errs(run("fanuc-a", f)));
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
