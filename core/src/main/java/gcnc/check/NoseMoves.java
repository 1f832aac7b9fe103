package gcnc.check;

import gcnc.check.geom.MotionParts;
import gcnc.check.geom.NoseGeometry;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.List;

/** The motions of checked blocks as nose radius compensation takes them apart and puts them back. */
final class NoseMoves {
    private NoseMoves() {
    }

    /**
     * The block's moves along the path (lines and arcs), not its dwells nor moves of no length
     * (a block that moves nothing is a block without a move, as for the control).
     */
    static List<Motion> path(CheckedBlock b) {
        List<Motion> ms = new ArrayList<>(1);
        for (Motion m : b.motions()) {
            MotionKind k = MotionKind.of(m);
            if (k.moves && !(k.linear() && from(m).distanceTo(to(m)) <= NoseGeometry.NOTHING)) {
                ms.add(m);
            }
        }
        return ms;
    }

    /** The motions of a block without a move, its moves of no length left out (they would go to the programmed point). */
    static List<Motion> still(CheckedBlock b) {
        List<Motion> ms = new ArrayList<>(b.motions().size());
        for (Motion m : b.motions()) {
            if (!MotionKind.of(m).moves) {
                ms.add(m);
            }
        }
        return ms;
    }

    /** The block's motions before {@code m}. */
    static List<Motion> before(CheckedBlock b, Motion m) {
        return b.motions().subList(0, b.motions().indexOf(m));
    }

    /** The block's motions after {@code m}. */
    static List<Motion> after(CheckedBlock b, Motion m) {
        int i = b.motions().indexOf(m);
        return b.motions().subList(i + 1, b.motions().size());
    }

    /** A straight move of the kind {@code m} is (rapid or at its feed) between two points. */
    static Motion line(Motion m, Point from, Point to) {
        boolean rapid = MotionKind.of(m) == MotionKind.RAPID;
        return new Motion.Linear(rapid, from, to, rapid ? null : MotionParts.path(m).feed());
    }

    /** Where a line, an arc or a thread pass starts. */
    static Point from(Motion m) {
        Motion.PathMotion p = MotionParts.path(m);
        return p == null ? null : p.from(); // a dwell has none (the callers pass moves only)
    }

    /** Where a line, an arc or a thread pass ends. */
    static Point to(Motion m) {
        Motion.PathMotion p = MotionParts.path(m);
        return p == null ? null : p.to();
    }

    /** The block with other motions, its end where the last of them ends. */
    static CheckedBlock with(CheckedBlock b, List<Motion> motions, Point end) {
        Point last = end;
        for (Motion m : motions) {
            if (MotionKind.of(m).moves) {
                last = to(m);
            }
        }
        return b.withMotions(motions, last);
    }

    /**
     * The block with its move {@code first} starting at {@code from}, where the tool stands: a line
     * goes from there; an arc (E171 reported) or a thread pass is reached by a straight move first,
     * so the path stays whole.
     */
    static CheckedBlock startingAt(CheckedBlock b, Motion first, Point from) {
        List<Motion> ms = new ArrayList<>(before(b, first));
        MotionKind k = MotionKind.of(first);
        if (k.linear()) {
            ms.add(line(first, from, to(first)));
        } else {
            if (from.distanceTo(from(first)) > NoseGeometry.NOTHING) {
                ms.add(k == MotionKind.ARC ? line(first, from, from(first))
                        : new Motion.Linear(true, from, from(first), null));
            }
            ms.add(first);
        }
        ms.addAll(after(b, first));
        return with(b, ms, b.end());
    }

    /**
     * The motions of {@code pending} with its move offset: after the motions before the move (and
     * {@code lead}, when not null: the rapid after E176), the move from {@code s} to {@code t} (an
     * arc about {@code c} of {@code radius} when {@code arc}, else a line), then straight moves
     * through the {@code corner} points, then the motions after the move. Moves of no length are
     * left out.
     */
    static List<Motion> offset(CheckedBlock pending, Motion lead, boolean arc, Point s, Point t, Point c, double radius,
                               List<Point> corner) {
        Motion m = path(pending).get(0);
        List<Motion> ms = new ArrayList<>(before(pending, m));
        if (lead != null) {
            ms.add(lead);
        }
        if (arc) {
            if (s.distanceTo(t) > NoseGeometry.NOTHING && radius > NoseGeometry.NOTHING) {
                Motion.Arc a = MotionKind.arc(m); // an arc element: the block's move is an arc
                Motion.ArcWords w = a.words().r() != null
                        ? new Motion.ArcWords(Math.copySign(radius, a.words().r()), null, null)
                        : new Motion.ArcWords(null, c.x() - s.x(), c.z() - s.z());
                ms.add(new Motion.Arc(a.clockwise(), s, t, c, radius, a.feed(), w));
            }
        } else if (s.distanceTo(t) > NoseGeometry.NOTHING) {
            ms.add(line(m, s, t));
        }
        Point at = t;
        for (Point next : corner) {
            if (at.distanceTo(next) > NoseGeometry.NOTHING) {
                ms.add(line(m, at, next));
                at = next;
            }
        }
        ms.addAll(after(pending, m));
        return ms;
    }
}
