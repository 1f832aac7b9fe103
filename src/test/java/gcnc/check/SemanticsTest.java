package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.ir.ArcGeometry;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * G-code semantics under the generic profile (docs/semantics.md): 1000 counts/mm on both axes,
 * X a diameter, home (105, 340) mm, G54 work zero at Z 150 mm, tool offset n = Table 8 row n.
 */
class SemanticsTest {
    static final String PRE = "G21 G90 G98\nG50 S2500\nM11\nT0101\nS1200 M03\n";

    private static Point end(String program, int line) {
        Run r = Run.generic(program + "\nM30");
        assertEquals("", r.errors());
        return r.line(line).end();
    }

    @Test
    void unitsApplyToTheWholeBlockWhateverTheWordOrder() {
        assertEquals(end("G00 X2. G20 Z1.", 1), end("G20 G00 X2. Z1.", 1));
        assertEquals(new Point(25400, 150000 + 25400), end("G00 X2. G20 Z1.", 1));
    }

    @Test
    void xIsADiameterAndZFromTheWorkZero() {
        assertEquals(new Point(21000, 152000), end("G00 X42. Z2.", 1));
    }

    @Test
    void numbersWithoutPointAreLeastIncrements() {
        assertEquals(new Point(21000, 152000), end("G00 X42000 Z2000", 1));
    }

    @Test
    void g91MakesXZIncrementalAndUWAreAlwaysIncremental() {
        assertEquals(new Point(15000, 145000), end("G00 X40. Z0.\nG91 G00 X-10. Z-5.", 2));
        assertEquals(new Point(15000, 145000), end("G00 X40. Z0.\nG00 U-10. W-5.", 2));
    }

    @Test
    void g50AndG92AreAPositionRegister() {
        for (String g : List.of("G50", "G92")) {
            Run r = Run.generic("G00 X40. Z0.\n" + g + " X100. Z50.\nG00 X90. Z40.\nM30");
            assertEquals("", r.errors());
            assertEquals(List.of(), r.line(2).motions());
            assertEquals(new Point(15000, 140000), r.line(3).end());
        }
    }

    @Test
    void workAndToolOffsetsApplyFromTheirOwnBlock() {
        assertEquals(new Point(20000, 140000), end("G55 G00 X40. Z0.", 1));
        assertEquals(new Point(20200, 150200), end("G00 X40. Z0. T0303", 1));
        assertEquals(new Point(20000, 150000), end("T0300 G00 X40. Z0.", 1));
    }

    @Test
    void g28GoesThroughTheIntermediatePointToTheReference() {
        Run r = Run.generic("G00 X40. Z0.\nG28 U10.\nM30");
        List<Motion> ms = r.line(2).motions();
        assertEquals(new Motion.Linear(true, new Point(20000, 150000), new Point(25000, 150000), null), ms.get(0));
        assertEquals(new Motion.Linear(true, new Point(25000, 150000), new Point(105000, 150000), null), ms.get(1));
    }

    @Test
    void g29ComesBackThroughTheIntermediatePoint() {
        Run r = Run.generic("G00 X40. Z0.\nG28 U10. W0.\nG29 X30. Z-5.\nM30");
        assertEquals("", r.errors());
        assertEquals(new Point(105000, 340000), r.line(2).end());
        List<Motion> ms = r.line(3).motions();
        assertEquals(new Motion.Linear(true, new Point(105000, 340000), new Point(25000, 150000), null), ms.get(0));
        assertEquals(new Motion.Linear(true, new Point(25000, 150000), new Point(15000, 145000), null), ms.get(1));
    }

    @Test
    void dwellIsIndependentOfWordOrder() {
        assertEquals(List.of(new Motion.Dwell(1.5)), Run.generic("X1.5 G04\nM30").line(1).motions());
        assertEquals(List.of(new Motion.Dwell(1.5)), Run.generic("G04 X1.5\nM30").line(1).motions());
        assertEquals(List.of(new Motion.Dwell(0.2)), Run.generic("G04 U0.2\nM30").line(1).motions());
        assertEquals(List.of(new Motion.Dwell(0.5)), Run.generic("G04 P500\nM30").line(1).motions());
        assertEquals(List.of(new Motion.Dwell(0.002)), Run.generic("G04 X2\nM30").line(1).motions());
    }

    @Test
    void constantSurfaceSpeedAtTheEndDiameterClampedByG50() {
        Run r = Run.generic(PRE + "G00 X60. Z2.\nG96 S150\nG01 X40. F100.\nG01 X10.\nM30");
        assertEquals("", r.errors());
        assertEquals(1000 * 150 / (Math.PI * 60), r.line(7).spindleRpm().getAsDouble(), 1e-9);
        assertEquals(1000 * 150 / (Math.PI * 40), r.line(8).spindleRpm().getAsDouble(), 1e-9);
        assertEquals(2500, r.line(9).spindleRpm().getAsDouble(), 1e-9);
    }

    @Test
    void feedPerMinuteAndPerRevolutionInCountsPerSecond() {
        Run min = Run.generic(PRE + "G01 X40. F120.\nM30");
        assertEquals(2000, ((Motion.Linear) min.line(6).motions().get(0)).feed().countsPerSecond(), 1e-9);
        Run rev = Run.generic(PRE + "G99 G01 X40. F0.2\nM30");
        assertEquals(4000, ((Motion.Linear) rev.line(6).motions().get(0)).feed().countsPerSecond(), 1e-9);
        assertEquals(0.2, ((Motion.Linear) rev.line(6).motions().get(0)).feed().programmed(), 1e-12);
    }

    @Test
    void arcsWithPositiveAndNegativeR() {
        Run r = Run.generic(PRE + "G00 X40. Z0.\nG02 X40. Z-6. R5. F100.\nG00 X40. Z0.\nG02 X40. Z-6. R-5.\nM30");
        assertEquals("", r.errors());
        Motion.Arc shortWay = (Motion.Arc) r.line(7).motions().get(0);
        Motion.Arc longWay = (Motion.Arc) r.line(9).motions().get(0);
        assertEquals(5000, shortWay.radius(), 1e-9);
        assertEquals(-5000, longWay.words().r(), 1e-9);
        assertEquals(5000, shortWay.centre().distanceTo(shortWay.to()), 1e-6);
        assertEquals(5000, longWay.centre().distanceTo(longWay.to()), 1e-6);
        assertNotEquals(shortWay.centre(), longWay.centre());
        assertTrue(Math.abs(ArcGeometry.sweepDegrees(shortWay.from(), shortWay.to(), shortWay.centre(), true)) < 180);
        assertTrue(Math.abs(ArcGeometry.sweepDegrees(longWay.from(), longWay.to(), longWay.centre(), true)) > 180);
    }

    /** R 0.005 mm short of half the chord (tolerance 0.01): the centre is the chord's midpoint, the radius half the chord. */
    @Test
    void anRJustShortOfHalfTheChordKeepsHalfTheChordAsRadius() {
        Run r = Run.generic(PRE + "G00 X40. Z0.\nG02 X40. Z-20. R9.995 F100.\nM30");
        assertEquals("", r.errors());
        Motion.Arc a = (Motion.Arc) r.line(7).motions().get(0);
        assertEquals(a.from().distanceTo(a.centre()), a.radius(), 1e-9);
        assertEquals(a.to().distanceTo(a.centre()), a.radius(), 1e-6);
        assertEquals(new Point(20000, 140000), a.centre());
        assertEquals(10000, a.radius(), 1e-6);
    }

    @Test
    void arcsWithIAndKAndAFullCircle() {
        Run r = Run.generic(PRE + "G00 X40. Z0.\nG03 X60. Z-10. I0. K-10. F100.\nG02 X60. Z-10. I5.\nM30");
        assertEquals("", r.errors());
        Motion.Arc a = (Motion.Arc) r.line(7).motions().get(0);
        assertEquals(new Point(20000, 140000), a.centre());
        assertEquals(10000, a.radius(), 1e-9);
        assertEquals(-10000, a.words().k(), 1e-9);
        Motion.Arc full = (Motion.Arc) r.line(8).motions().get(0);
        assertEquals(full.from(), full.to());
        assertEquals(new Point(35000, 140000), full.centre());
    }

    @Test
    void arcEndOffTheCircleBeyondTheToleranceIsAnError() {
        // end 0.005 mm off: accepted; 0.05 mm off: E102
        assertEquals("", Run.generic(PRE + "G00 X40. Z0.\nG03 X60.01 Z-10. I0. K-10. F100.\nM30").errors());
        assertEquals("7:17:E102", Run.generic(PRE + "G00 X40. Z0.\nG03 X60.1 Z-10. I0. K-10. F100.\nM30").errors());
    }

    @Test
    void aBlockWithoutModalWordsLeavesTheStateUnchanged() {
        for (String block : List.of("G04 P100", "G04 U0.5", "M08", "(comment) G04 X1.")) {
            Run before = Run.generic(PRE);
            Run after = Run.generic(PRE + block);
            assertEquals(before.checker.state(), after.checker.state(), block);
        }
    }

    @Test
    void aBlockWithAnErrorKeepsOnlyItsUnambiguousModalWords() {
        Run before = Run.generic(PRE);
        Run after = Run.generic(PRE + "G01 X40. F100. G07 T0303 G91");
        assertEquals("6:1:E052, 6:16:E011", after.errors());
        ModalState b = before.checker.state();
        ModalState a = after.checker.state();
        // no move, no tool change; but G01 (the block's only motion G), F100. and G91 stand on their
        // own (issue 8: no echoes; issue 17: the motion G too, so the next X is read under it)
        assertEquals(b.position(), a.position());
        assertEquals(1, a.motion());
        assertEquals(b.tool(), a.tool());
        assertEquals(100, a.feed());
        assertTrue(a.incremental());
    }

    /** Recovery: the cut was meant; its F, G01 and end point hold, so the next cut has no error of its own. */
    @Test
    void aCutThatBreaksOnlyAPrerequisiteStillSetsTheState() {
        Run r = Run.generic("G21 G90 G98\nG50 S2500\nT0101\nS1200 M03\nG01 X40. Z1. F100.\nM11\nG01 Z-10.\nM30");
        assertEquals("5:1:E038", r.errors());
        ModalState s = r.checker.state();
        assertEquals(100, s.feed());
        assertEquals(1, s.motion());
        Run fixed = Run.generic("G21 G90 G98\nG50 S2500\nM11\nT0101\nS1200 M03\nG01 X40. Z1. F100.\nG01 Z-10.\nM30");
        assertEquals("", fixed.errors());
        assertEquals(fixed.checker.state().position(), s.position());
    }

    @Test
    void aSpeedAboveTheClampStillStartsTheSpindle() {
        Run r = Run.generic("G21 G90 G98\nG50 S2500\nM11\nT0101\nS3000 M03\nG01 X40. Z1. F100.\nM30");
        assertEquals("5:1:E048", r.errors());
    }

    @Test
    void anErrorInTheBlocksFormKeepsOnlyItsModalWords() {
        Run r = Run.generic(PRE + "G01 X40. F100. G00\nG01 Z-10.\nM30");
        // the move is not made, but F100. is kept: the next cut reports nothing of its own
        assertEquals("6:16:E016", r.errors());
    }

    @Test
    void theGenericProgramChecksClean() {
        String program = String.join("\n", "O1001", "N10 G21 G90 G98", "N20 G50 S2500", "N30 M11", "N40 T0101",
                "N50 S1200 M03", "N60 G00 X42. Z2.", "N70 G01 X40. F120.", "N80 G01 Z-30.", "N90 G02 X46. Z-33. R3.",
                "N100 G00 X60. Z5.", "N110 M05", "N120 M30");
        Run r = Run.generic(program);
        assertEquals("", r.errors());
        CheckedBlock arc = r.line(10);
        Motion.Arc a = (Motion.Arc) arc.motions().get(0);
        assertEquals(new Point(20000, 120000), a.from());
        assertEquals(new Point(23000, 117000), a.to());
        // G02 is clockwise with +Z right and +X up (ArcGeometry): the centre is at X46 Z-30
        assertEquals(new Point(23000, 120000), a.centre());
        assertEquals(1200, r.line(6).spindleRpm().getAsDouble(), 1e-9);
    }
}
