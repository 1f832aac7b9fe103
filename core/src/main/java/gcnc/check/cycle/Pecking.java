package gcnc.check.cycle;

import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.List;

/**
 * The moves of a G74 or G75 peck cycle (docs/cycles.md), pure geometry in machine counts. G75
 * pecks along X (a groove or a part-off) and steps along Z between grooves; G74 pecks along Z (a
 * face groove or a peck-drilled hole) and steps along X. From the start point A each cut:
 * <ol>
 *   <li>feeds toward the end level along the peck axis by the peck depth, rapids back by the
 *       retract, feeds on (the retract plus the next peck), until it reaches the end level (the
 *       last peck is what is left; no peck = one plunge);</li>
 *   <li>at the bottom rapids aside by the relief along the step axis, opposite the step (with no
 *       step: the relief's own sign gives the direction, as Fanuc's Δd);</li>
 *   <li>rapids back to A's level along the peck axis.</li>
 * </ol>
 * Between cuts it rapids along the step axis by the step, the last step clipped to the end point;
 * after the last cut it rapids back to A along the step axis. Each cut is one pass.
 *
 * @param peckAlongX true for G75 (pecks along X), false for G74 (pecks along Z)
 * @param start      A, where the tool is at the cycle block
 * @param peckEnd    the end coordinate along the peck axis (the groove's bottom)
 * @param stepEnd    the end coordinate along the step axis (A's own for a single cut)
 * @param peck       the peck depth, more than zero; NaN for one plunge
 * @param step       the step between cuts, more than zero; NaN when there is one cut
 * @param retract    the rapid back after each peck, zero or more
 * @param relief     the move aside at the bottom: against the step when there is one (zero or
 *                   more), else along the step axis with its sign
 */
public record Pecking(boolean peckAlongX, Point start, double peckEnd, double stepEnd, double peck, double step,
                      double retract, double relief) {

    /** The moves and the number of cuts (passes). */
    public record Plan(List<Move> moves, int passes) {
        public Plan {
            moves = List.copyOf(moves);
        }
    }

    /** Geometric tolerance, counts: a step that leaves less than this is no step. */
    private static final double EPS = 1e-6;

    private double peckOf(Point p) {
        return peckAlongX ? p.x() : p.z();
    }

    private double stepOf(Point p) {
        return peckAlongX ? p.z() : p.x();
    }

    private Point at(double peckC, double stepC) {
        return peckAlongX ? new Point(peckC, stepC) : new Point(stepC, peckC);
    }

    /** How many cuts the step makes between A and the end point (1 when there is no step to go). */
    public int cuts() {
        double span = Math.abs(stepEnd - stepOf(start));
        if (span <= EPS) {
            return 1;
        }
        return (int) Math.ceil(span / step - EPS) + 1;
    }

    /** How many pecks one cut makes. */
    public int pecksPerCut() {
        double depth = Math.abs(peckEnd - peckOf(start));
        if (Double.isNaN(peck) || depth <= EPS) {
            return 1;
        }
        return (int) Math.ceil(depth / peck - EPS);
    }

    public Plan plan() {
        double a = peckOf(start);
        double s0 = stepOf(start);
        double depth = Math.abs(peckEnd - a);
        double pd = Math.signum(peckEnd - a);
        double span = stepEnd - s0;
        double sd = Math.signum(span);
        int cuts = cuts();
        double aside = Math.abs(span) <= EPS ? relief : -sd * relief;
        List<Move> moves = new ArrayList<>();
        double s = s0;
        for (int c = 1; c <= cuts; c++) {
            double next = c == cuts ? (cuts == 1 ? s0 : stepEnd) : s0 + sd * step * (c - 1);
            if (c > 1) {
                moves.add(Move.line(true, at(a, next), c));
            }
            s = next;
            double done = 0;
            int pecks = pecksPerCut();
            for (int k = 1; k <= pecks; k++) {
                double reach = k == pecks ? depth : Math.min(depth, peck * k);
                moves.add(Move.line(false, at(a + pd * reach, s), c));
                done = reach;
                if (k < pecks && retract > 0) {
                    moves.add(Move.line(true, at(a + pd * Math.max(0, done - retract), s), c));
                }
            }
            if (Math.abs(aside) > EPS) {
                moves.add(Move.line(true, at(a + pd * done, s + aside), c));
            }
            moves.add(Move.line(true, at(a, s + (Math.abs(aside) > EPS ? aside : 0)), c));
        }
        Point last = moves.get(moves.size() - 1).to();
        if (last.distanceTo(start) > EPS) {
            moves.add(Move.line(true, start, cuts));
        }
        return new Plan(moves, cuts);
    }
}
