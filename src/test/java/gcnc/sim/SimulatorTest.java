package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Diagnostics;
import gcnc.ir.Motion;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.Tables;
import gcnc.ir.Point;
import java.util.List;
import org.junit.jupiter.api.Test;

class SimulatorTest {
    /** Rapid in above the stock, turn r 18 from z 102 to 50, rapid out: nothing to report. */
    @Test
    void cleanProgramHasNoFindings() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 22, 102);
        f.move(false, 18, 102);
        f.move(false, 18, 50);
        f.move(false, 22, 50);
        f.move(true, 90, 250);
        f.sim.end(SimFixture.lines(0, "EN"));
        assertEquals(List.of(), f.codes());
        SimReport r = f.sim.report();
        assertEquals(5, r.sequences());
        assertEquals(18, r.xMinMm(), 1e-9);
        assertEquals(90, r.xMaxMm(), 1e-9);
        assertEquals(50, r.zMinMm(), 1e-9);
        assertTrue(r.cycleSeconds() > 0);
    }

    @Test
    void rapidThroughUncutStockIsFound() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 22, 102);
        f.move(true, 15, 50); // line 3: dives into r 20 material
        assertEquals(List.of("E305@3"), f.codes());
    }

    /** The stock-removal rule: a rapid back through what a feed cut is fine, one deeper is not. */
    @Test
    void rapidThroughCutMaterialIsFineButNotBelowIt() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 22, 102);
        f.move(true, 15, 102);
        f.move(false, 15, 50);
        f.move(true, 15, 101);   // line 5: back through the groove just cut
        f.move(true, 12, 101);
        f.move(true, 12, 60);    // line 7: below what was cut
        assertEquals(List.of("E305@7"), f.codes());
    }

    @Test
    void faceCutIntoTheJawsIsFound() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 30, 102);
        f.move(false, 30, -5); // line 3: r 30 is inside the jaws (r 40) below z 0
        assertEquals(List.of("E303@3"), f.codes());
    }

    @Test
    void tipSkimmingAboveTheJawsIsClearButOneDeeperIsNot() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 45, 102);
        f.move(false, 41, -1);  // line 3: r 41 passes over the jaws (r 40)
        assertEquals(List.of(), f.codes());
        f.move(false, 41, 5);
        f.move(false, 37, 5);
        f.move(false, 37, -5);  // line 6: 5 into the jaws
        assertEquals(List.of("E303@6"), f.codes());
    }

    /** Tip at z 195 is short of the centre (z 200), but the holder (dz 0..10, dr 3..20) reaches its cone. */
    @Test
    void holderReachingTheTailstockIsFoundWithTheTipClear() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 10, 150);
        f.move(true, 10, 190);
        assertEquals(List.of(), f.codes());
        f.move(true, -1, 195); // line 4: the tip below the quill (r 15), the holder (r 5 and up) in it
        assertEquals(List.of("E304@4"), f.codes());
    }

    @Test
    void moveIntoTheTailstockIsFound() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 10, 150);
        f.move(true, 10, 210); // line 3: the tailstock quill is r 15 from z 200 on
        assertEquals(List.of("E304@3"), f.codes());
    }

    @Test
    void arcBulgingPastTravelBetweenInRangeEndsIsFound() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 95, 150);
        // Counter-clockwise half circle from z 150 to z 130 about (95, 140): its top is at x 105 > 100.
        f.block(List.of(new Motion.Arc(false, new Point(95, 150), new Point(95, 130), new Point(95, 140), 10,
                SimFixture.FEED, new Motion.ArcWords(10.0, null, null))), "VS 100", "CR 10,0,180", "VE", "BGS", "AMS");
        assertEquals(List.of("E302@3"), f.codes());
    }

    @Test
    void arcThatMatchesItsBlockConforms() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 60, 150);
        f.block(List.of(new Motion.Arc(true, new Point(60, 150), new Point(60, 130), new Point(60, 140), 10,
                SimFixture.FEED, new Motion.ArcWords(10.0, null, null))), "VS 100", "CR 10,0,-180", "VE", "BGS", "AMS");
        assertEquals(List.of(), f.codes());
        assertEquals(50, f.sim.report().xMinMm(), 1e-9); // the clockwise arc dips to x 50
    }

    @Test
    void arcTurningTheWrongWayIsAMismatch() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 60, 150);
        f.block(List.of(new Motion.Arc(true, new Point(60, 150), new Point(60, 130), new Point(60, 140), 10,
                SimFixture.FEED, new Motion.ArcWords(10.0, null, null))), "VS 100", "CR 10,0,180", "VE", "BGS", "AMS");
        assertEquals(List.of("E308@3"), f.codes());
    }

    /** The thesis dialect's zero-sweep CR: one finding, and the next block replays from where it should be. */
    @Test
    void zeroSweepArcIsFlaggedOnce() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 60, 150);
        f.block(List.of(new Motion.Arc(true, new Point(60, 150), new Point(60, 130), new Point(60, 140), 10,
                SimFixture.FEED, new Motion.ArcWords(10.0, null, null))), "VS 100", "CR 10,0.0000,0.0000", "BGS");
        f.move(false, 60, 120);
        assertEquals(List.of("E309@3"), f.codes());
    }

    @Test
    void endPointOffByMoreThanTheToleranceIsAMismatch() throws Exception {
        SimFixture f = new SimFixture();
        f.start();
        f.move(true, 60, 150);
        f.block(List.of(new Motion.Linear(true, new Point(60, 150), new Point(60, 140), null)),
                "VS 1000", "VP -8,0", "VE", "BGS", "AMS");
        assertEquals(List.of("E308@3"), f.codes());
    }

    @Test
    void unknownInstructionAndBadArgumentsAreLocated() throws Exception {
        SimFixture f = new SimFixture();
        f.block(List.of(), "XQ #FOO");
        f.block(List.of(), "VP 1.5,2");
        f.block(List.of(), "SB x");
        f.block(List.of(), "BGX");
        assertEquals(List.of("E300@1", "E301@2", "E301@3", "E301@4"), f.codes());
    }

    @Test
    void feedWithTheSpindleStoppedOrTheChuckOpenIsFound() throws Exception {
        SimFixture f = new SimFixture();
        f.move(true, 22, 102);
        f.block(List.of(), "CB4");           // chuck closed, spindle never started
        f.move(false, 18, 95);               // line 3: into the blank (r 20, face z 100)
        f.block(List.of(), "CB2", "SB1");    // M03
        f.block(List.of(), "SB4");           // M10: chuck open
        f.move(false, 18, 90);               // line 6
        f.block(List.of(), "CB4", "CB1");    // M11, M05
        f.move(false, 18, 80);               // line 8
        f.move(true, 22, 102);               // rapids are fine either way
        assertEquals(List.of("E306@3", "E307@6", "E306@8"), f.codes());
    }

    @Test
    void aFeedThatTakesNoMaterialIsNoCutWhateverTheSpindleAndChuck() throws Exception {
        // a bar puller's pull: M05, chuck open, a feed in the air in front of the blank's face
        SimFixture f = new SimFixture();
        f.move(true, 17, 110);
        f.block(List.of(), "CB1", "SB4");    // M05, M10: chuck open
        f.move(false, 17, 150);              // line 3: pulls toward the tailstock, no stock there
        f.move(false, 17, 104);              // line 4: back, still in the air
        f.move(false, 17, 95);               // line 5: into the blank: a cut with the spindle stopped, chuck open
        assertEquals(List.of("E306@5", "E307@5"), f.codes());
    }

    @Test
    void withNoBlankACompileLeavesTheFeedToTheCheckerAndABareReplayJudgesIt() throws Exception {
        SimFixture f = new SimFixture(SimFixture.PROFILE, SimOptions.defaults().withoutBlank());
        f.block(List.of(), "CB1", "SB4");    // M05, M10
        f.move(false, 10, 150);              // line 2: cannot be told from a cut without a blank
        assertEquals(List.of("E316@1"), f.codes());
        Diagnostics d = new Diagnostics();
        Simulator bare = new Simulator(ProfileLoader.read(ProfileFile.parse("tiny.machine", SimFixture.PROFILE),
                Tables.builtIn()), SimOptions.defaults().withoutBlank(), d);
        bare.replay(SimFixture.lines(1, "CB1", "SB4", "VS 100", "VP 10,0", "VE", "BGS", "AMS"));
        assertEquals(List.of("E306", "E307", "E316"), d.sorted().stream().map(x -> x.code().id()).sorted().toList());
    }

    @Test
    void countsBeyondThirtyTwoBitsAreFound() throws Exception {
        SimFixture f = new SimFixture();
        f.block(List.of(), "VS 1000", "VP 3000000000,0", "VE", "BGS", "AMS");
        assertTrue(f.codes().contains("E310@1"), f.codes().toString());
    }

    @Test
    void blockWhoseDmcMakesTooFewSequencesIsFound() throws Exception {
        SimFixture f = new SimFixture();
        f.block(List.of(new Motion.Linear(true, new Point(90, 250), new Point(80, 250), null)), "VS 1000");
        assertEquals(List.of("E311@1"), f.codes());
    }

    /** G28 U0 W0: the intermediate point is where the tool stands, so the backend may skip that move. */
    @Test
    void standingMotionMayHaveNoSequence() throws Exception {
        SimFixture f = new SimFixture();
        Point here = new Point(90, 250);
        Point ref = new Point(80, 240);
        f.block(List.of(new Motion.Linear(true, here, here, null), new Motion.Linear(true, here, ref, null)),
                "VS 1000", "VP -10,-10", "VE", "BGS", "AMS");
        f.block(List.of(new Motion.Linear(true, ref, ref, null), new Motion.Linear(true, ref, here, null)),
                "VS 1000", "VP 0,0", "VE", "BGS", "AMS", "VP 10,10", "VE", "BGS", "AMS");
        assertEquals(List.of(), f.codes());
    }

    @Test
    void segmentsNeverStartedAreFound() throws Exception {
        SimFixture f = new SimFixture();
        f.block(List.of(new Motion.Linear(true, new Point(90, 250), new Point(80, 250), null)), "VS 1000", "VP 0,-10");
        assertTrue(f.codes().contains("E314@1"), f.codes().toString());
    }

    @Test
    void directiveAfterEnIsFound() throws Exception {
        SimFixture f = new SimFixture();
        f.sim.end(SimFixture.lines(0, "EN", "SB1"));
        assertEquals(List.of("E312@1"), f.codes());
    }

    /** After EN a remark is taken, a command is E312 and does nothing, and a routine (after a label) is not run or reported. */
    @Test
    void afterEnOnlyRemarksAreTakenAndRoutinesAreNotRun() throws Exception {
        SimFixture f = new SimFixture();
        f.sim.end(SimFixture.lines(0, "EN", "NO a remark", "WT 5000", "#HOMEFAIL", "WT 7000", "SB1", "EN"));
        assertEquals(List.of("E312@1"), f.codes()); // the WT 5000 only
        assertEquals(0, f.sim.report().cycleSeconds(), 1e-9, "neither WT is run");
    }

    @Test
    void thesisDialectLinesAreAccepted() throws Exception {
        SimFixture f = new SimFixture();
        f.block(List.of(), "Revolver 2", "M08", "OF ,,4.0000", "NO L7", "WT 500");
        // the tiny machine does not describe station 2: it is checked as the default outline, said once
        assertEquals(List.of("E321@1"), f.codes());
        assertEquals(0.5, f.sim.report().cycleSeconds(), 1e-9);
    }

    /** Galil's OF takes -9.998..9.998 V: the thesis's OF ,,S/300 for S5000 cannot be sent. */
    @Test
    void spindleVoltageBeyondTheOutputRangeIsFound() throws Exception {
        SimFixture f = new SimFixture();
        f.block(List.of(), "OF ,,16.6667");
        assertEquals(List.of("E301@1"), f.codes());
    }

    @Test
    void planeOtherThanTheProfilesIsFound() throws Exception {
        SimFixture f = new SimFixture();
        f.block(List.of(), "VM XZ");
        assertEquals(List.of("E313@1"), f.codes());
    }
}
