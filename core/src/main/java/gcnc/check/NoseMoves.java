package gcnc.check;

import gcnc.check.geom.NoseGeometry;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Feed;
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
            if (!(m instanceof Motion.Dwell) && !(m instanceof Motion.Linear l
                    && l.from().distanceTo(l.to()) <= NoseGeometry.NOTHING)) {
                ms.add(m);
            }
        }
        return ms;
    }

    /** The motions of a block without a move, its moves of no length left out (they would go to the programmed point). */
    static List<Motion> still(CheckedBlock b) {
        List<Motion> ms = new ArrayList<>(b.motions().size());
        for (Motion m : b.motions()) {
            if (m instanceof Motion.Dwell) {
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
        Feed feed = m instanceof Motion.Linear l ? l.feed() : ((Motion.Arc) m).feed();
        boolean rapid = m instanceof Motion.Linear l && l.rapid();
        return new Motion.Linear(rapid, from, to, rapid ? null : feed);
    }

    /** Where a line, an arc or a thread pass starts. */
    static Point from(Motion m) {
        return m instanceof Motion.Linear l ? l.from() : m instanceof Motion.Thread t ? t.from() : ((Motion.Arc) m).from();
    }

    /** Where a line, an arc or a thread pass ends. */
    static Point to(Motion m) {
        return m instanceof Motion.Linear l ? l.to() : m instanceof Motion.Thread t ? t.to() : ((Motion.Arc) m).to();
    }

    /** The block with other motions, its end where the last of them ends. */
    static CheckedBlock with(CheckedBlock b, List<Motion> motions, Point end) {
        Point last = end;
        for (Motion m : motions) {
            if (!(m instanceof Motion.Dwell)) {
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
        if (first instanceof Motion.Linear) {
            ms.add(line(first, from, to(first)));
        } else {
            if (from.distanceTo(from(first)) > NoseGeometry.NOTHING) {
                ms.add(first instanceof Motion.Arc a ? line(a, from, a.from())
                        : new Motion.Linear(true, from, from(first), null));
            }
            ms.add(first);
        }
        ms.addAll(after(b, first));
        return with(b, ms, b.end());
    }
}
