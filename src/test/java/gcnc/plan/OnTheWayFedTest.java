package gcnc.plan;

import static gcnc.plan.ContouringTest.compile;
import static gcnc.plan.ContouringTest.profile;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.dmc.Command;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A sequence that sets something on the way is as long as its path (issue 33 item 1): 1,200 chords at
 * constant surface speed (G96: a spindle speed on the way at nearly every chord) with the coolant
 * switched on and off on the way (M08, M09) are one sequence, fed while it runs; each trip point
 * (AV) is written while the buffer is fed, once its segment is well inside the buffer and before the
 * path can have reached it (the COMALL VM reference: "Additional segments may be given during the
 * motion"); the replay finds every output where its block starts.
 */
class OnTheWayFedTest {
    static String g96Finish(int chords) {
        StringBuilder b = new StringBuilder("G21 G18 G40 G99\nT0101\nG50 S3000\nG96 S180 M03\nG00 X48. Z1.\nG01 Z0. F0.2\n");
        for (int k = 1; k <= chords; k++) {
            b.append(String.format(java.util.Locale.ROOT, "X%.3f Z%.3f%s%n", 46 + Math.sin(k / 40.0), -k * 0.02,
                    k == 300 ? " M08" : k == chords - 100 ? " M09" : ""));
        }
        return b.append("G00 X60.\nZ5.\nM05\nM30\n").toString();
    }

    @Test
    void aLongFinishWithSpeedsAndCoolantOnTheWayIsOneSequenceItsTripPointsFedWithIt() throws Exception {
        ContouringTest.Out o = compile(g96Finish(1200), profile("haas"));
        // rapid in; the feed and the 1,200 chords; the retract (G96 at its diameter: the spindle); no length stop
        assertEquals(List.of("rapid-feed", "spindle", "output"), o.stops());
        assertEquals(0, o.result().simulation().orElseThrow().findings(), "the replay finds every output where its block starts");
        List<Command> cs = o.instructions().stream().map(gcnc.dmc.Instruction::command).toList();
        List<Double> ends = new ArrayList<>(); // the path at each segment's end, counts from the sequence's start
        long u = 0;
        long v = 0;
        boolean begun = false;
        boolean ended = false;
        long trip = 0;
        int whileFed = 0;
        int fill = 0;
        for (Command c : cs) {
            if (c instanceof Command.VectorSpeed) {
                ends.clear();
                u = 0;
                v = 0;
                begun = false;
                ended = false;
                trip = 0;
            } else if (c instanceof Command.VectorPosition p) {
                double before = ends.isEmpty() ? 0 : ends.get(ends.size() - 1);
                ends.add(before + Math.hypot(p.first() - u, p.second() - v));
                u = p.first();
                v = p.second();
            } else if (c instanceof Command.VectorEnd) {
                ended = true;
            } else if (c instanceof Command.BeginSequence) {
                begun = true;
                fill = ends.size(); // (at BGS the path is at its start: any trip point in the fill is ahead)
            } else if (c instanceof Command.AfterVector av) {
                trip += av.counts(); // relative: the trip point is the sum of the sequence's AVs
                assertTrue(begun, "an AV before BGS would wait for ever");
                assertTrue(trip <= ends.get(ends.size() - 1), "within the path given so far");
                if (!ended) {
                    whileFed++;
                    int given = ends.size();
                    int at = 0; // the segment the trip point starts
                    while (at < given && ends.get(at) <= trip) {
                        at++;
                    }
                    assertTrue(given - at >= gcnc.dmc.StreamSplit.BUFFER_BATCH, "the trip point's segment " + at
                            + " at least a batch inside the buffer (" + given + " given): it cannot run dry while waiting");
                    assertTrue(given == fill || given - at <= 2 * gcnc.dmc.StreamSplit.BUFFER_BATCH + 1, "written at the first wait for room"
                            + " after that (segment " + at + ", " + given + " given): the path is still before it");
                }
            }
        }
        assertTrue(whileFed > 500, "trip points written while the sequence is fed: " + whileFed);
        boolean afterBgs = false;
        for (int i = 1; i < cs.size(); i++) {
            afterBgs |= cs.get(i - 1) instanceof Command.BeginSequence && !(cs.get(i - 2) instanceof Command.VectorEnd)
                    && cs.get(i) instanceof Command.AfterVector;
        }
        assertTrue(afterBgs, "the first trip points right after the fed sequence's BGS, before the first wait");
    }
}
