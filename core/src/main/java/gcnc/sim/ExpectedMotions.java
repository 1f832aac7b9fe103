package gcnc.sim;

import gcnc.ir.ArcGeometry;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.List;

/**
 * The motions the checker meant that the DMC has not carried out yet, in program order, and the
 * pairing of each run of a sequence's segments with the motion it carries out (by where the
 * segments came from, {@code Source}). The planner holds at most a sequence's worth of motions
 * back, so this holds at most that many and one block's. A motion that moves and is passed over
 * is heard by the {@link Missed} once per block (E311 for the {@link Simulator}).
 */
final class ExpectedMotions {
    /** A motion the checker meant: its block, its index there, the motion; {@code done} counts the block's carried out. */
    record Expected(CheckedBlock block, int index, Motion motion, int[] done, int count) {
    }

    /** Hears of a block whose motions that move were not all carried out: {@code done} of {@code count}. */
    interface Missed {
        void missed(CheckedBlock block, int count, int done);
    }

    private final java.util.ArrayDeque<Expected> expected = new java.util.ArrayDeque<>();
    /** How far, mm, a motion may end from its start and still not move (the conformance tolerance). */
    private final double tolerance;
    private final Missed out;

    ExpectedMotions(double tolerance, Missed out) {
        this.tolerance = tolerance;
        this.out = out;
    }

    /** The motions of a block the checker meant, all but its dwells (which no segment carries out). */
    void add(CheckedBlock intended) {
        int count = 0;
        for (Motion m : intended.motions()) {
            count += m instanceof Motion.Dwell ? 0 : 1;
        }
        int[] done = {0};
        List<Motion> ms = intended.motions();
        for (int i = 0; i < ms.size(); i++) {
            if (!(ms.get(i) instanceof Motion.Dwell)) {
                expected.add(new Expected(intended, i, ms.get(i), done, count));
            }
        }
    }

    /** Passes over every motion still meant: the program's blocks so far have all their DMC. */
    void skipAll() {
        while (!expected.isEmpty()) {
            skip(expected.poll());
        }
    }

    /**
     * The motion the segments from {@code source} carry out: the next one meant, after the motions
     * that do not move (G28 U0 W0's intermediate point, an arc shorter than a count), which the
     * backend may leave out. A motion that moves and was left out is E311 at its block.
     */
    Expected match(gcnc.dmc.Source source, Segment first, Segment last) {
        while (!expected.isEmpty()) {
            Expected e = expected.peek();
            // the motion the run names (a hand-made DMC line names none, -1: its block's next one); a
            // motion that does not move is the run only when the run does not move either, since the
            // backend may have left it out and the next block's motion can have the same line and index
            // (asked in this order: the line first, the geometry only for a motion on that line)
            if (source != null && e.block().line() == source.line()
                    && (source.motion() < 0 || e.index() == source.motion())
                    && (!standing(e.motion()) || sameDisplacement(first, last, e.motion()))
                    && java.util.Objects.equals(e.block().origin().file(), source.file())) {
                expected.poll();
                e.done()[0]++;
                return e;
            }
            skip(expected.poll());
        }
        return null;
    }

    /** A motion meant and not carried out: nothing when it does not move, else E311 at its block (once). */
    private void skip(Expected e) {
        if (standing(e.motion())) {
            e.done()[0]++;
        } else if (e.done()[0] >= 0) {
            out.missed(e.block(), e.count(), e.done()[0]);
            e.done()[0] = -1; // reported: once per block
        }
    }

    /**
     * Ends within the tolerance; for an arc also no more than half a turn (so it bulges no more)
     * or a diameter within the tolerance (a circle that small).
     */
    private boolean standing(Motion m) {
        return m.accept(endsStanding); // one visitor for the simulator: asked for every motion matched, it makes no object
    }

    private final Motion.Visitor<Boolean> endsStanding = new Motion.Visitor<>() {
        @Override
        public Boolean linear(Motion.Linear l) {
            return distance(l.from(), l.to()) <= tolerance;
        }

        @Override
        public Boolean thread(Motion.Thread t) {
            return distance(t.from(), t.to()) <= tolerance;
        }

        @Override
        public Boolean arc(Motion.Arc a) {
            double tol = tolerance;
            return distance(a.from(), a.to()) <= tol
                    && (Math.abs(ArcGeometry.sweepDegrees(a.from(), a.to(), a.centre(), a.clockwise())) <= 180
                            || Conformance.pointLike(a, tol));
        }

        @Override
        public Boolean dwell(Motion.Dwell d) {
            return true;
        }
    };

    /** Where a motion that moves starts ({@code end} false) or ends: every motion but a dwell has both. */
    private static Point end(Motion m, boolean end) {
        if (!(m instanceof Motion.PathMotion p)) {
            throw new IllegalArgumentException("a dwell does not move");
        }
        return end ? p.to() : p.from();
    }

    /** Whether the segments from {@code first} to {@code last} move as the motion moves, within the tolerance. */
    private boolean sameDisplacement(Segment first, Segment last, Motion m) {
        Point from = end(m, false);
        Point to = end(m, true);
        return Geometry.length(last.toX() - first.fromX() - (to.x() - from.x()),
                last.toZ() - first.fromZ() - (to.z() - from.z())) <= tolerance;
    }

    private static double distance(Point a, Point b) {
        return Geometry.length(b.x() - a.x(), b.z() - a.z());
    }
}
