package gcnc.check.cycle;

import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.List;

/**
 * The moves of a drilling cycle on the spindle axis (Haas lathe G81, G82, G83; docs/cycles.md),
 * pure geometry in machine counts: from the start point A a rapid along X to the hole's X (when
 * it is given), a rapid along Z to the R plane, the drill fed to the bottom, and a rapid back to
 * A's Z. A peck drill (G83) feeds one peck at a time, rapids back to the R plane after each (a
 * full retract, to clear the chips), and rapids down again to the clearance short of the depth
 * reached before feeding on (Fanuc B/C G99: the last rapid ends at the R plane instead, {@link
 * #plan(int, double)}). The pecks are {@code first}, then each {@code reduce} less, never
 * less than {@code least} (Haas I, J, K; Q alone is first = least, reduce = 0).
 *
 * @param start     A, where the tool is at the cycle block
 * @param x         the hole's X (A's own when not given)
 * @param rPlane    the R plane's Z (A's own when not given)
 * @param bottom    the bottom's Z
 * @param first     the first peck, more than zero; NaN for one feed to the bottom (G81, G82)
 * @param reduce    how much less each next peck is, zero or more
 * @param least     the smallest peck, more than zero (ignored without pecks)
 * @param clearance how far short of the depth reached the drill rapids back down, zero or more
 */
public record Drilling(Point start, double x, double rPlane, double bottom, double first, double reduce,
                       double least, double clearance) {
    /** Geometric tolerance, counts. */
    private static final double EPS = 1e-6;

    /** The depths (distances below the R plane) the pecks reach, the last the bottom. */
    public List<Double> pecks(int most) {
        double depth = Math.abs(bottom - rPlane);
        List<Double> reached = new ArrayList<>();
        if (Double.isNaN(first)) {
            reached.add(depth);
            return reached;
        }
        double done = 0;
        double next = first;
        while (done < depth - EPS && reached.size() <= most) {
            done = Math.min(depth, done + next);
            reached.add(done);
            next = Math.max(least, next - reduce);
        }
        return reached;
    }

    /** The moves, back to A's Z; the index of the feed that reaches the bottom is the last FEED among them. */
    public List<Move> plan(int most) {
        return plan(most, start.z());
    }

    /**
     * The moves, the last a rapid back to {@code returnZ}: the R plane (Fanuc G99) or the initial
     * level (G98, Haas: A's Z, or for a Fanuc hole drilled again after G99 the level the cycle
     * started at).
     */
    public List<Move> plan(int most, double returnZ) {
        List<Move> moves = new ArrayList<>();
        double dir = Math.signum(bottom - rPlane);
        Point over = new Point(x, start.z());
        if (Math.abs(x - start.x()) > EPS) {
            moves.add(Move.line(true, over, 1));
        }
        if (Math.abs(rPlane - start.z()) > EPS) {
            moves.add(Move.line(true, new Point(x, rPlane), 1));
        }
        List<Double> pecks = pecks(most);
        double before = 0;
        for (int k = 0; k < pecks.size(); k++) {
            if (k > 0) {
                double back = Math.max(0, before - clearance);
                moves.add(Move.line(true, new Point(x, rPlane), 1));
                if (back > EPS) {
                    moves.add(Move.line(true, new Point(x, rPlane + dir * back), 1));
                }
            }
            moves.add(Move.line(false, new Point(x, rPlane + dir * pecks.get(k)), 1));
            before = pecks.get(k);
        }
        moves.add(Move.line(true, new Point(x, returnZ), 1));
        return moves;
    }
}
