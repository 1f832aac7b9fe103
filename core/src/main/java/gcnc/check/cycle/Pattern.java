package gcnc.check.cycle;

import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.List;

/**
 * G73 pattern repeat (Fanuc 0i-TF; Haas G73 with I, K and D): the whole contour followed
 * {@code passes} times, each time moved off the part by a share of the relief, the first pass by
 * the relief plus the finishing allowance, the last by the allowance alone; each pass from the
 * start point to the moved contour's start, along it, and back to the start point by rapid.
 * The contour need not be monotonic (castings and forgings follow their shape). Pure geometry in
 * machine counts.
 */
public final class Pattern {
    private Pattern() {
    }

    /**
     * The moves: allowance (ux, wz) and relief (ix, kz) in counts (x a radius), the number of
     * passes (1 or more).
     */
    public static List<Move> moves(Contour c, double ux, double wz, double ix, double kz, int passes) {
        if (passes < 1) {
            throw new IllegalArgumentException("a pattern repeat makes one pass or more: " + passes);
        }
        Point a = c.start();
        int depthSign = (int) Math.signum(a.x() - c.shapeStart().x());
        List<Move> out = new ArrayList<>();
        Point at = a;
        for (int k = 1; k <= passes; k++) {
            double share = passes == 1 ? 0 : (passes - k) / (double) (passes - 1);
            double dx = ux + share * ix;
            double dz = wz + share * kz;
            List<Contour.Piece> moved = new ArrayList<>(c.shape().size());
            for (Contour.Piece p : c.shape()) {
                moved.add(p.shifted(dx, dz));
            }
            at = Roughing.add(out, at, Move.line(c.approach().rapid(), c.shapeStart().plus(dx, dz), k));
            at = Roughing.follow(out, at, moved, k);
            Roughing.back(out, at, a, Axes.TURNING, depthSign == 0 ? 1 : depthSign, k);
            at = a;
        }
        return out;
    }
}
