package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.galil.Dialect;
import org.junit.jupiter.api.Test;

/**
 * One tiny program per finding of the peck and drilling cycles (E180-E188), on the fanuc machine
 * (metric, control fanuc-a) or the haas machine (inch): the code at the word it names.
 */
class PeckCycleErrorsTest {
    /** Lines 1-4: metric, feed per revolution, spindle on, at X70 Z-10. */
    private static final String FANUC = "G21 G99\nT0505\nG97 S800 M03\nG00 X70. Z-10.\n";
    /** Lines 1-4: inch, feed per revolution, spindle on, on centre in front of the face. */
    private static final String HAAS = "G20 G99\nT101\nG97 S1200 M03\nG00 X0. Z0.5\n";

    private static String fanuc(String program) {
        return Run.of("fanuc", FANUC + program).errors();
    }

    private static String haas(String program) {
        return Run.of("haas", HAAS + program).errors();
    }

    @Test
    void goodCyclesReportNothing() {
        assertEquals("", fanuc("G75 R0.5\nG75 X40. Z-16. P3000 Q2500 F0.08\nM30\n"));
        assertEquals("", fanuc("G75 X40. Z-16. I3. K2.5 D1. F0.08\nM30\n"));
        assertEquals("", fanuc("G75 X40. F0.08\nM30\n"));
        assertEquals("", haas("G83 Z-1.2 R0.1 Q0.25 F0.005\nZ-1.4\nG80\nM30\n"));
    }

    @Test
    void e180APeckOrStepOfZeroOrLess() {
        assertEquals("5:16:E180", fanuc("G75 X40. Z-16. P0 Q2500 F0.08\nM30\n"));
        assertEquals("5:16:E180", fanuc("G75 X40. Z-16. I-1. K2.5 F0.08\nM30\n"));
        assertEquals("5:20:E180", fanuc("G75 X40. Z-16. I1. K0 F0.08\nM30\n"));
        assertEquals("5:11:E180", haas("G83 Z-1.2 Q0 F0.005\nM30\n"));
    }

    @Test
    void e181APeckDeeperThanTheWholeCut() {
        // 70 to 60 is 5 mm on the radius; a 6 mm peck
        assertEquals("5:10:E181", fanuc("G75 X60. P6000 F0.08\nM30\n"));
    }

    @Test
    void e182WhatTheCycleNeedsIsMissing() {
        assertEquals("5:1:E182", fanuc("G75 Z-16. P3000 Q2500 F0.08\nM30\n"));
        assertEquals("5:1:E182", fanuc("G74 X40. P3000 Q2500 F0.08\nM30\n"));
        assertEquals("5:1:E182", haas("G81 R0.1 F0.005\nM30\n"));
        assertEquals("5:1:E182", haas("G83 Z-1. R0.1 F0.005\nM30\n"));
        assertEquals("5:1:E182", haas("G82 Z-0.1 R0.1 F0.005\nM30\n"));
    }

    @Test
    void e183AReliefLargerThanTheStep() {
        assertEquals("5:25:E183", fanuc("G75 X40. Z-16. I3. K2.5 D3. F0.08\nM30\n"));
        assertEquals("5:28:E183", fanuc("G75 X40. Z-16. P3000 Q2500 R3. F0.08\nM30\n"));
    }

    @Test
    void e184ANegativeReliefWhenTheCycleSteps() {
        assertEquals("5:25:E184", fanuc("G75 X40. Z-16. I3. K2.5 D-1. F0.08\nM30\n"));
    }

    @Test
    void e185AnEndPointAlongTheStepAxisWithoutAStep() {
        assertEquals("5:1:E185", fanuc("G75 X40. Z-16. I3. F0.08\nM30\n"));
    }

    @Test
    void e186DrillingOffCentreIsAWarning() {
        Run r = Run.of("haas", HAAS + "G81 X0.2 Z-0.3 R0.1 F0.005\nM30\n");
        assertEquals("5:5:E186", r.errors());
        assertEquals(0, r.diagnostics.errorCount());
    }

    @Test
    void e187AnRPlaneOutsideTheStartAndTheBottom() {
        assertEquals("5:11:E187", haas("G81 Z-0.3 R0.6 F0.005\nM30\n"));
        assertEquals("5:11:E187", haas("G81 Z-0.3 R-0.4 F0.005\nM30\n"));
    }

    @Test
    void e188RepeatsAreFollowedOnlyAsAWholeNumberOfTheSameHole() {
        assertEquals("", haas("G81 Z-0.3 R0.1 L2 F0.005\nM30\n"));
        assertEquals("5:16:E188", haas("G81 Z-0.3 R0.1 L2.5 F0.005\nM30\n"));
        // stepped along X by U: a row of holes off the centre line
        assertEquals("5:21:E188", haas("G81 U0.2 Z-0.3 R0.1 L2 F0.005\nM30\n"));
    }

    @Test
    void aWordOfTheOtherFormOrOfAnotherCycleIsE161() {
        assertEquals("5:28:E161", fanuc("G75 X40. Z-16. P3000 Q2500 K1. F0.08\nM30\n"));
        assertEquals("5:16:E161", haas("G81 Z-0.3 R0.1 Q0.1 F0.005\nM30\n"));
    }

    @Test
    void fanucPAndQAreWholeNumbersOfIncrements() {
        assertEquals("5:16:E013", fanuc("G75 X40. Z-16. P3. Q2500 F0.08\nM30\n"));
    }

    @Test
    void theDrillingCycleStaysInForceUntilG80OrAMotionG() {
        Run r = Run.of("haas", HAAS + "G81 Z-0.3 R0.1 F0.005\nZ-0.4\nG80\nG00 Z0.6\nG81 Z-0.3 R0.1\nG00 Z0.7\nZ0.8\nM30\n");
        assertEquals("", r.errors());
        assertEquals(3, lines(r, 6), "Z-0.4 drills again: to the R plane, down, back");
        assertEquals(1, lines(r, 8), "after G80 a G00 is a rapid");
        assertEquals(3, lines(r, 9), "G81 again");
        assertEquals(1, lines(r, 10), "a G00 ends the cycle");
        assertEquals(1, lines(r, 11), "and Z0.8 is a rapid");
    }

    private static long lines(Run r, int line) {
        return r.blocks.stream().filter(b -> b.line() == line).count();
    }

    @Test
    void aDrillingCycleWithTheSpindleStoppedIsCaught() {
        String stopped = "G20 G99\nT101\nG00 X0. Z0.5\nG81 Z-0.3 R0.1 F0.005\nM30\n";
        assertEquals(false, Run.of("haas", stopped).errors().isEmpty());
    }

    /** Compiles and simulates on the fanuc machine (its 65 mm bar); the simulator's findings by code. */
    private static String simulated(String program) throws Exception {
        gcnc.Compiler.Settings settings = new gcnc.Compiler.Settings(Run.TABLES, Run.profile("fanuc"), Dialect.Kind.GALIL,
                java.util.Optional.of(gcnc.sim.SimOptions.defaults()), true);
        gcnc.Compiler.Result r = gcnc.Compiler.compile(new java.io.StringReader(program), settings, l -> { });
        java.util.Set<String> codes = new java.util.TreeSet<>();
        r.diagnostics().sorted().forEach(d -> codes.add(d.code().id()));
        return String.join(" ", codes);
    }

    @Test
    void aGrooveAndAPartOffWithTheGroovingBladeSimulateClean() throws Exception {
        // tool 5 is a 3 mm grooving blade reaching 25 mm; the G75 moves replay over the 65 mm bar
        // without a finding, and a part-off of a 40 mm bar (stock header) too
        String head = FANUC + "G00 X70. Z-30.\n";
        assertEquals("", simulated(head + "G75 X40. P4000 F0.06\nG00 X100. Z100.\nM30\n"));
        assertEquals("", simulated("(150 40)\n" + head + "G75 X0. P4000 F0.06\nG00 X100. Z100.\nM30\n"));
        // parting the 65 mm bar needs 32.5 mm of blade: the clamp block meets the groove's walls
        assertEquals("E315", simulated(head + "G75 X0. P4000 F0.06\nG00 X100. Z100.\nM30\n"));
    }
}
