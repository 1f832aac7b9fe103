package gcnc.check;

import gcnc.machine.MachineProfile;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * One tiny program per cycle finding (E150-E168), on the fanuc machine (metric, control fanuc-a)
 * or the haas machine (inch): the code at the word or contour block it names.
 */
class CycleErrorsTest {
    /** Lines 1-4: metric, feed per revolution, spindle on, at the start point X52 Z2. */
    private static final String START = "G21 G99\nT0101\nG97 S1000 M03\nG00 X52. Z2.\n";
    private static final String CONTOUR = "N10 G00 X20.\nG01 Z-15.\nX48.\nN20 Z-40.\n";

    private static String fanuc(String program) {
        return Run.of("fanuc", START + program).errors();
    }

    @Test
    void aGoodCycleAndItsFinishReportNothing() {
        assertEquals("", fanuc("G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\n" + CONTOUR + "G70 P10 Q20\nM30\n"));
        assertEquals("", fanuc("G71 P10 Q20 U0.4 W0.1 D2. F0.25\n" + CONTOUR + "M30\n"));
    }

    @Test
    void e150TheProgramEndsBeforeTheContoursLastBlock() {
        assertEquals("5:9:E150", fanuc("G71 P10 Q20 D2. F0.25\nN10 G00 X20.\nG01 Z-15.\nM30\n"));
    }

    @Test
    void e151TheFirstLabelTwiceInTheContour() {
        assertEquals("7:1:E151, 7:1:E114", fanuc("G71 P10 Q20 D2. F0.25\nN10 G00 X20.\nN10 G01 Z-15.\nN20 X48.\nM30\n"));
    }

    @Test
    void e644ABlockBetweenTheCycleAndItsContourIsNeverRun() {
        // issue 17: the control searches ahead for N(P) and goes on after N(Q), so the block between
        // is passed over: a warning where E152 was an error
        assertEquals("6:1:E644", fanuc("G71 P10 Q20 D2. F0.25\nG00 X50.\n" + CONTOUR + "M30\n"));
    }

    @Test
    void e153TheLastLabelIsBeyondTheLookAhead() {
        StringBuilder p = new StringBuilder("G71 P10 Q20 D2. F0.25\nN10 G00 X20.\n");
        for (int i = 0; i < CycleExpansion.LOOK_AHEAD; i++) {
            p.append("G01 Z-1.\n");
        }
        p.append("N20 X48.\nM30\n");
        assertEquals("5:9:E153", fanuc(p.toString()));
    }

    @Test
    void e154AContourThatGoesBack() {
        assertEquals("8:1:E154", fanuc("G71 P10 Q20 D2. F0.25\nN10 G00 X20.\nG01 Z-15.\nX18.\nN20 Z-40.\nM30\n"));
        assertEquals("8:1:E154", fanuc("G71 P10 Q20 D2. F0.25\nN10 G00 X20.\nG01 Z-15.\nX30. Z-10.\nN20 X48.\nM30\n"));
        Run typeOne = Run.of("fanuc", START + "G71 P10 Q20 D2. F0.25\nN10 G00 X20.\nG01 Z-15.\nX18.\nN20 Z-40.\nM30\n");
        assertEquals(true, typeOne.messages().contains("goes back in X here: a type I contour"), typeOne.messages());
    }

    @Test
    void e154ATypeTwoContourThatGoesBackAlongZ() {
        // X and Z in the first block: type II, X may go in and out, Z must not go back
        assertEquals("", fanuc("G71 P10 Q20 D2. F0.25\nN10 G00 X20. Z2.\nG01 Z-15.\nX30. Z-20.\nX24. Z-30.\n"
                + "N20 X48.\nM30\n"));
        assertEquals("8:1:E154", fanuc("G71 P10 Q20 D2. F0.25\nN10 G00 X20. Z2.\nG01 Z-15.\nX30. Z-10.\nN20 X48.\n"
                + "M30\n"));
        // an arc that bulges back along Z
        assertEquals("8:1:E154", fanuc("G71 P10 Q20 D2. F0.25\nN10 G00 X20. Z2.\nG01 Z-15.\nG02 X30. Z-15. R6.\n"
                + "N20 G01 X48.\nM30\n"));
        Run typeTwo = Run.of("fanuc", START + "G71 P10 Q20 D2. F0.25\nN10 G00 X20. Z2.\nG01 Z-15.\nX30. Z-10.\n"
                + "N20 X48.\nM30\n");
        assertEquals(true, typeTwo.messages().contains("goes back in Z here: a type II contour"), typeTwo.messages());
    }

    @Test
    void e189ATypeTwoPocketWithAZAllowance() {
        // the contour goes in again at line 8 (X20. Z-15.): W would move both walls along Z
        assertEquals("5:18:E189", fanuc("G71 P10 Q20 U0.4 W0.1 D2. F0.25\nN10 G00 X30. Z2.\nG01 Z-10.\n"
                + "X20. Z-15.\nZ-20.\nX40. Z-25.\nN20 X48.\nM30\n"));
        assertEquals("", fanuc("G71 P10 Q20 U0.4 W0. D2. F0.25\nN10 G00 X30. Z2.\nG01 Z-10.\n"
                + "X20. Z-15.\nZ-20.\nX40. Z-25.\nN20 X48.\nM30\n"));
        // no pocket (X only goes out after the first move): W is fine, as in type I
        assertEquals("", fanuc("G71 P10 Q20 U0.4 W0.1 D2. F0.25\nN10 G00 X20. Z2.\nG01 Z-15.\nN20 X48.\nM30\n"));
        // G72: the allowance along X (U) is the one a pocket cannot take
        assertEquals("5:13:E189", fanuc("G72 P10 Q20 U0.4 W0.1 D2. F0.25\nN10 G00 X52. Z-8.\nG01 X40.\n"
                + "Z-4.\nX30.\nZ-8.\nX20.\nZ0.\nN20 X0.\nM30\n"));
        Run r = Run.of("fanuc", START + "G71 P10 Q20 U0.4 W0.1 D2. F0.25\nN10 G00 X30. Z2.\nG01 Z-10.\n"
                + "X20. Z-15.\nZ-20.\nX40. Z-25.\nN20 X48.\nM30\n");
        assertEquals(true, r.messages().contains("a type II contour with a pocket (line 8) takes no allowance along Z"),
                r.messages());
    }

    /**
     * A Haas leaves a type II pocket's Z allowance on both its walls ("Troughs"): the same contour
     * is followed there (golden cycles/type2-walls.haas), unless the pocket is narrower than twice
     * the allowance.
     */
    @Test
    void e189OnAHaasOnlyWhenThePocketIsTooNarrowForItsWalls() {
        String pocket = "G71 P10 Q20 U0.4 W0.1 D2. F0.25\nN10 G00 X30. Z2.\nG01 Z-10.\nX20. Z-15.\nZ-20.\nX40. Z-25.\n"
                + "N20 X48.\nM30\n";
        MachineProfile haasRules = Run.profileWithControl("fanuc", "haas");
        assertEquals("", Run.of(haasRules, START + pocket, Checker.ERROR_CAP).errors());
        Run narrow = Run.of(haasRules, START + pocket.replace("W0.1", "W3."), Checker.ERROR_CAP);
        assertEquals("5:18:E189", narrow.errors());
        assertEquals(true, narrow.messages().contains("a type II contour with a pocket (line 8) is too narrow for the"
                + " allowance along Z on both its walls"), narrow.messages());
    }

    @Test
    void e155AFirstMoveAlongTheCuttingAxis() {
        assertEquals("6:1:E155", fanuc("G71 P10 Q20 D2. F0.25\nN10 G01 Z-1.\nG01 X20.\nZ-15.\nN20 X48.\nM30\n"));
    }

    @Test
    void e156AndE158DepthAndRetract() {
        assertEquals("5:5:E156", fanuc("G71 U0. R0.5\nM30\n"));
        assertEquals("5:13:E156", fanuc("G71 P10 Q20 D0. F0.25\n" + CONTOUR + "M30\n"));
        assertEquals("5:9:E158", fanuc("G71 U2. R-0.5\nM30\n"));
    }

    @Test
    void e157NoDepthOfCut() {
        assertEquals("5:1:E157", fanuc("G71 P10 Q20 U0.4 W0.1 F0.25\n" + CONTOUR + "M30\n"));
    }

    @Test
    void e159AnAllowanceInsideThePart() {
        assertEquals("5:13:E159", fanuc("G71 P10 Q20 U-0.4 W0.1 D2. F0.25\n" + CONTOUR + "M30\n"));
        assertEquals("5:18:E159", fanuc("G71 P10 Q20 U0.4 W-0.1 D2. F0.25\n" + CONTOUR + "M30\n"));
    }

    @Test
    void e160AStartPointInsideTheContourWithItsAllowance() {
        assertEquals("6:1:E160", fanuc("G71 P10 Q20 U4. D2. F0.25\nN10 G00 X50.\nG01 Z-15.\nN20 X52.\nM30\n"));
    }

    @Test
    void e160ATypeTwoContourThatRisesPastTheStartAndComesBack() {
        // a collar at X56 above the start's X52, then a pocket after it
        assertEquals("8:1:E160", fanuc("G71 P10 Q20 D2. F0.25\nN10 G00 X40. Z2.\nG01 Z-10.\nX56.\nZ-15.\nX30. Z-20.\n"
                + "N20 X56.\nM30\n"));
    }

    @Test
    void e161AWordTheCycleDoesNotTake() {
        assertEquals("5:14:E161", fanuc("G71 U2. R0.5 X3.\nM30\n"));
        assertEquals("10:13:E161", fanuc("G71 P10 Q20 D2. F0.25\n" + CONTOUR + "G70 P10 Q20 R0.1\nM30\n"));
    }

    @Test
    void e162AnMInTheContour() {
        assertEquals("6:14:E162", fanuc("G71 P10 Q20 D2. F0.25\nN10 G00 X20. M08\nG01 Z-15.\nN20 X48.\nM30\n"));
    }

    @Test
    void e163AContourOfOneMove() {
        assertEquals("5:1:E163", fanuc("G71 P10 Q10 D2. F0.25\nN10 G00 X20.\nM30\n"));
    }

    @Test
    void e164RoughAllowancesAreNotSupportedYet() {
        assertEquals("5:23:E164", fanuc("G71 P10 Q20 D2. F0.25 I0.1\n" + CONTOUR + "M30\n"));
        // Haas R1 (type II) is followed; another R is no word of the one-block form
        assertEquals("", fanuc("G71 P10 Q20 D2. F0.25 R1\n" + CONTOUR + "M30\n"));
        assertEquals("5:23:E161", fanuc("G71 P10 Q20 D2. F0.25 R2\n" + CONTOUR + "M30\n"));
    }

    @Test
    void e165AFindingInAPassNamesThePass() {
        // the spindle never started: the first cut, in pass 1, is where that matters
        String program = "G21 G99\nT0101\nG97 S1000\nG00 X52. Z2.\nG71 P10 Q20 D2. F0.25\n" + CONTOUR + "M30\n";
        assertEquals("5:1:E051, 5:1:E165", Run.of("fanuc", program).errors());
        assertEquals("[G71, 1, 8, 5, 10, 20]", Run.of("fanuc", program).diagnostics.sorted().get(1).args().toString());
        // the cycle is not followed past the pass that failed: the tool goes back to the start point
        Run r = Run.of("fanuc", program);
        assertEquals(r.line(4).end(), r.checker.state().position());
    }

    @Test
    void e166AFinishWithoutRoughing() {
        assertEquals("5:1:E166", fanuc("G70 P10 Q20\nM30\n"));
    }

    @Test
    void e167TooManyPasses() {
        assertEquals("5:13:E167", fanuc("G71 P10 Q20 D0.0001 F0.25\n" + CONTOUR + "M30\n"));
    }

    @Test
    void e168AContourWithoutItsLastLabel() {
        assertEquals("5:1:E168", fanuc("G71 P10 D2. F0.25\n" + CONTOUR + "M30\n"));
    }

    @Test
    void aPatternRepeatNeedsAWholeNumberOfPasses() {
        String contour = "N10 G00 X20. Z2.\nG01 Z-15.\nN20 X48.\nM30\n";
        assertEquals("", fanuc("G73 U4. W1. R3\nG73 P10 Q20 U0.4 W0.1 F0.25\n" + contour));
        assertEquals("5:1:E157", fanuc("G73 P10 Q20 U0.4 W0.1 F0.25\n" + contour));
        assertEquals("5:31:E008", fanuc("G73 P10 Q20 U0.4 W0.1 I4. K1. D0 F0.25\n" + contour));
        assertEquals("5:13:E013", fanuc("G73 U4. W1. R2.5\nM30\n"));
    }
}
