package gcnc.galil;

import static gcnc.galil.Fixtures.motions;
import static gcnc.galil.Fixtures.rapid;
import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Feed;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import java.util.List;
import java.util.OptionalDouble;
import java.util.OptionalInt;
import org.junit.jupiter.api.Test;

/** The first groups of Table 5.2, from blocks built the way the checker builds bishop.nc's. */
class ThesisDialectTest {
    private static final MachineProfile THESIS = Fixtures.profile("thesis-2004");

    /** A bishop.nc literal in thesis-2004 machine counts: value x 1.5 - 20000. */
    private static double c(double literal) {
        return literal * 1.5 - 20000;
    }

    private static List<String> thesis(CheckedBlock... blocks) {
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("thesis", THESIS, d, blocks);
        assertEquals(0, d.size(), () -> d.sorted().toString());
        return out;
    }

    private static Motion.Arc arc(boolean g02, Point from, Point to, double r, double f) {
        // Centre and radius are what the checker would give; the thesis dialect ignores them.
        return new Motion.Arc(g02, from, to, from, Math.abs(r), new Feed(f, f * 20),
                new Motion.ArcWords(r, null, null));
    }

    @Test
    void firstRapidFromHomeAndTheSecond() {
        Point n100 = new Point(c(3234), c(500));
        Point n120 = new Point(c(2234), c(100));
        assertEquals(List.of("VS 20000", "VP 15149,19250", "BGS", "VS 20000", "VP 1500,600", "BGS"),
                thesis(motions(2, n100, rapid(Point.ORIGIN, n100)), motions(3, n120, rapid(n100, n120))));
    }

    @Test
    void m11AndM03InSourceOrderThenTheFeedMove() {
        Point a = new Point(c(2034), c(100));
        Point b = new Point(c(2034), c(-4500));
        CheckedBlock g50 = new CheckedBlock(4, OptionalDouble.empty(), OptionalInt.empty(),
                List.of(new MCall(11), new MCall(3)), List.of(), List.of(), a);
        CheckedBlock n135 = motions(6, b, new Motion.Linear(false, a, b, new Feed(150, 3000)));
        assertEquals(List.of("CB2", "CB4", "SB3", "VS 3000", "VP 0,6900", "BGS"), thesis(g50, n135));
    }

    @Test
    void halfCountsRoundAwayFromZeroBothWays() {
        Point a = new Point(c(1634), c(100));
        Point b = new Point(c(1634), c(-3487));
        assertEquals(List.of("VS 3000", "VP 0,5381", "BGS", "VS 20000", "VP 0,-5381", "BGS"),
                thesis(motions(15, b, new Motion.Linear(false, a, b, new Feed(150, 3000))),
                        motions(16, a, rapid(b, a))));
    }

    @Test
    void n240IsAZeroSweepArcWithTheChordAsRadius() {
        // chord 200 x 1.5 = 300; theta = atan(-20000/-18800) = 46.77; dtheta = atan(0/300) = 0, -0 for G03.
        Point a = new Point(c(800), c(0));
        Point b = new Point(c(1000), c(0));
        assertEquals(List.of("VS 1000", "CR 300,46.8000,0.0000", "BGS"),
                thesis(motions(32, b, arc(false, a, b, 2100, 50))));
    }

    @Test
    void n260F051GivesVs1020() {
        // theta = atan(-20600/-18500) = 48.08
        Point a = new Point(c(1000), c(-400));
        Point b = new Point(c(1400), c(-400));
        assertEquals(List.of("VS 1020", "CR 600,48.1000,0.0000", "BGS"),
                thesis(motions(34, b, arc(true, a, b, 2100, 51))));
    }

    @Test
    void negativeRSweepsThreeHundredSixtyMinusTheChordAngle() {
        // dtheta = atan(600/600) = 45 -> 360 - 45 = 315, G03 negates; theta = atan(-20000/-20000) = 45.
        Point a = new Point(-20000, -20000);
        Point b = new Point(-19400, -19400);
        assertEquals(List.of("VS 1000", "CR 849,45.0000,-315.0000", "BGS"),
                thesis(motions(5, b, arc(false, a, b, -600, 50))));
    }

    @Test
    void divisionsByZeroTakeTheLimitOfTheThesisFormula() {
        // x1 = 0: theta = atan(-20000/0) -> -90; dX = 0: dtheta = atan(-300/0) -> -90.
        Point a = new Point(0, -20000);
        Point b = new Point(0, -20300);
        assertEquals(List.of("VS 1000", "CR 300,-90.0000,-90.0000", "BGS"),
                thesis(motions(5, b, arc(true, a, b, 2100, 50))));
    }

    @Test
    void spindleToolUnmappedMAndDwell() {
        CheckedBlock b = new CheckedBlock(7, OptionalDouble.of(1000), OptionalInt.of(5),
                List.of(new MCall(41)), List.of(new Motion.Dwell(1.5)), List.of(new MCall(9)), Point.ORIGIN);
        // 1000 div 300 = 3 in OF's third field (spindle.axis = Z)
        assertEquals(List.of("OF ,,3", "Revolver 5", "M41", "WT 1500", "CB5"), thesis(b));
    }

    @Test
    void ikEndOffTheCircleGivesTheTwoPieceOutput() {
        // Start (x 100, z 100), I 0 K 100: centre (100, 200), r 100; end (200, 210) is 100.5 away.
        // m = atan(10/100) = 0.09967 (the angle used as a slope), b0 = 210 - 200 m = 190.066;
        // A = m^2 + 1, B = 2 m b0 - 2 xc - 2 m zc = -201.980, C = zc^2 + b0^2 - 2 zc b0 - r^2;
        // neither root lies in [xc, x2], so xf is the second: -40.727, zf = m xf + b0 = 186.007.
        // CR radius |(xf, zf) - start| = 164.93; theta = atan(100/100) = 45;
        // dtheta = atan(86.007 / -140.727) = -31.43 (G02: kept); VP -(end - (xf, zf)) = -240.73, -23.99.
        Point a = new Point(100, 100);
        Point b = new Point(200, 210);
        Motion.Arc arc = new Motion.Arc(true, a, b, new Point(100, 200), 100, new Feed(10, 200),
                new Motion.ArcWords(null, 0.0, 100.0));
        assertEquals(List.of("VS 200", "CR 165,45.0000,-31.4000", "BGS", "VS 200", "VP -241,-24", "BGS"),
                thesis(motions(8, b, arc)));
    }

    @Test
    void ikEndOnTheCircleIsOneChordArc() {
        // Centre (100, 200) r 100; end (200, 200) is on it: chord hypot(100, 100) = 141.42;
        // theta = atan(100/100) = 45; dtheta = atan(100/100) = 45, negated for G03.
        Point a = new Point(100, 100);
        Point b = new Point(200, 200);
        Motion.Arc arc = new Motion.Arc(false, a, b, new Point(100, 200), 100, new Feed(10, 200),
                new Motion.ArcWords(null, 0.0, 100.0));
        assertEquals(List.of("VS 200", "CR 141,45.0000,-45.0000", "BGS"), thesis(motions(8, b, arc)));
    }

    @Test
    void aNumberTooLongForTheThesisFormatIsE205() {
        Diagnostics d = new Diagnostics();
        Point far = new Point(1e9, 0);
        List<String> out = Fixtures.run("thesis", THESIS, d, motions(4, far, rapid(Point.ORIGIN, far)));
        assertEquals(List.of(), out, "the group that does not fit is left out");
        assertEquals(gcnc.diag.Code.E205_THESIS_NUMBER, d.sorted().get(0).code());
        assertEquals(gcnc.diag.Span.of(4, 1), d.sorted().get(0).span());
    }

    @Test
    void anIkArcTheThesisFormulaCannotSolveIsE206() {
        // From (x5, z0) about (0, 0), r = 5, to (x1, z100), far off the circle. The thesis takes
        // m = atan(100/1) = 1.5608 as the slope of a line through the end point; that line passes
        // 98.4 from the centre (D^2 = 9690 > (1 + m^2) r^2 = 85.9): no intersection to cut to.
        Point a = new Point(5, 0);
        Point b = new Point(1, 100);
        Motion.Arc arc = new Motion.Arc(false, a, b, Point.ORIGIN, 5, new Feed(10, 200),
                new Motion.ArcWords(null, -5.0, 0.0));
        Diagnostics d = new Diagnostics();
        Fixtures.run("thesis", THESIS, d, motions(9, b, arc));
        assertEquals(gcnc.diag.Code.E206_THESIS_ARC, d.sorted().get(0).code());
        assertEquals(gcnc.diag.Span.of(9, 1), d.sorted().get(0).span());
    }
}
