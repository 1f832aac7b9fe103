package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The simulator's conformance of replayed segments to the motion they carry out (docs/galil.md). */
class ConformanceTest {
    /** A straight move written as pieces (longer than a VP segment): every joint must be on the programmed line. */
    @Test
    void theJointsOfASplitStraightMoveAreOnItsLine() {
        List<String> found = new ArrayList<>();
        Conformance c = new Conformance((code, line, args) -> found.add(code.id() + " " + args[0]), null, 1.5, 5);
        Point from = new Point(100_000, 28_000_000);
        Point to = new Point(100_000, 13_100_000);
        Motion.Linear rapid = new Motion.Linear(true, from, to, null);
        Point half = new Point(100_000, 20_550_000);
        assertEquals(null, c.check(rapid, List.of(line(from, half), line(half, to)), gcnc.dmc.Source.line(6)));
        assertEquals(List.of(), found);
        // the joint 40 counts off the line, the end still right: the path between is not the program's
        Point off = new Point(100_040, 20_550_000);
        c.check(rapid, List.of(line(from, off), line(off, to)), gcnc.dmc.Source.line(6));
        assertEquals(List.of("E308 path (a piece of a straight move off its line)"), found);
    }

    private static Segment line(Point a, Point b) {
        return new Segment(a.x(), a.z(), b.x(), b.z(), false, 0, 0, 0, 0, 0, null);
    }
}
