package gcnc.sim;

import java.util.Arrays;
import java.util.List;

/**
 * What one sweep ({@link Hull}) does to the stock's envelopes over a stretch of z where
 * everything is straight: the hull's lower and upper sides, the upper envelope's piece, the bore's
 * and the top run's floor ({@link #stretch}). A stretch is split where any two of them cross, so
 * that on each part the sweep covers the material from above (down to its lower side, or all of
 * it), from inside (up to its upper side), passes in the air or in the hole, or passes through the
 * material leaving some on both sides of it.
 */
final class EnvelopeCut {
    private EnvelopeCut() {
    }

    /** The z of every corner of the hull strictly inside (lo, hi), with {@code more} (other breaks), ascending, each once. */
    static double[] breaks(Hull h, double lo, double hi, double[] more) {
        double[] z = h.z();
        double[] in = new double[z.length + more.length];
        int n = 0;
        for (double v : z) {
            if (v > lo && v < hi) {
                in[n++] = v;
            }
        }
        for (double v : more) {
            if (v > lo && v < hi) {
                in[n++] = v;
            }
        }
        double[] sorted = Arrays.copyOf(in, n);
        Arrays.sort(sorted);
        int m = 0;
        for (int i = 0; i < n; i++) {
            if (m == 0 || sorted[i] != sorted[m - 1]) {
                sorted[m++] = sorted[i];
            }
        }
        return Arrays.copyOf(sorted, m);
    }

    /** What {@link #stretch} changed: the upper envelope, the bore, the run's floor; and whether the outline became inexact. */
    static final int UPPER = 1;
    static final int BORE = 2;
    static final int RUN = 4;
    static final int INEXACT = 8;

    /**
     * How the sweep leaves the three envelopes over [s, t]: the upper envelope u (the largest
     * radius of material), the bore l (never above the material) and the floor of the top run w
     * (from w to u the material is one run; between l and w there may be pieces a cut passed
     * above, such as the pip a drill's point leaves off the centreline), given with the hull's
     * lower side b and upper side t, all straight on the stretch. Appends each envelope's parts to
     * {@code upper}, {@code bore}, {@code run}; returns which changed ({@link #UPPER} ...).
     *
     * <p>A sweep reaching the upper envelope takes everything above its lower side: the envelope
     * comes down to that side, exactly when the side is in the top run (above w), to 0 when it is at
     * or below the bore (nothing is left), and otherwise to the side, no longer exact (what is left
     * below it is not known: {@link #INEXACT}). A sweep below the upper envelope that reaches above
     * the run's floor leaves the top run above its upper side: the floor comes up to it. Wherever
     * the lower side is at or below the bore and the upper side above it, the bore comes up to the
     * upper side.
     */
    static int stretch(double s, double t, double u0, double u1, double l0, double l1, double w0, double w1,
                       double b0, double b1, double t0, double t1, List<UpperEnvelope.Piece> upper,
                       List<UpperEnvelope.Piece> bore, List<UpperEnvelope.Piece> run) {
        if (Double.isNaN(b0 + b1 + t0 + t1) || Math.min(b0, b1) >= Math.max(u0, u1)
                || Math.max(t0, t1) <= Math.min(l0, l1)) { // the usual case: above the material, or in the hole
            upper.add(new UpperEnvelope.Piece(s, t, u0, u1));
            bore.add(new UpperEnvelope.Piece(s, t, l0, l1));
            run.add(new UpperEnvelope.Piece(s, t, w0, w1));
            return 0;
        }
        double[] at = {s, root(s, t, t0 - u0, t1 - u1), root(s, t, b0 - u0, b1 - u1), root(s, t, b0 - l0, b1 - l1),
            root(s, t, t0 - l0, t1 - l1), root(s, t, b0 - w0, b1 - w1), root(s, t, t0 - w0, t1 - w1), t};
        Arrays.sort(at);
        int result = 0;
        for (int i = 0; i + 1 < at.length; i++) {
            double x = at[i];
            double y = at[i + 1];
            if (Double.isNaN(x) || Double.isNaN(y) || !(x < y)) {
                continue;
            }
            double m = (x + y) / 2;
            double um = lerp(s, t, u0, u1, m);
            double lm = lerp(s, t, l0, l1, m);
            double wm = lerp(s, t, w0, w1, m);
            double bm = lerp(s, t, b0, b1, m);
            double tm = lerp(s, t, t0, t1, m);
            boolean fromAbove = tm >= um && bm < um;
            if (fromAbove && bm <= lm) { // through everything at these z: none left
                upper.add(new UpperEnvelope.Piece(x, y, 0, 0));
                result |= UPPER;
            } else if (fromAbove) {
                upper.add(new UpperEnvelope.Piece(x, y, Math.max(0, lerp(s, t, b0, b1, x)),
                        Math.max(0, lerp(s, t, b0, b1, y))));
                result |= bm <= wm ? UPPER | INEXACT : UPPER;
            } else {
                upper.add(new UpperEnvelope.Piece(x, y, lerp(s, t, u0, u1, x), lerp(s, t, u0, u1, y)));
            }
            if (bm <= lm && tm > lm) {
                bore.add(new UpperEnvelope.Piece(x, y, lerp(s, t, t0, t1, x), lerp(s, t, t0, t1, y)));
                result |= BORE;
            } else {
                bore.add(new UpperEnvelope.Piece(x, y, lerp(s, t, l0, l1, x), lerp(s, t, l0, l1, y)));
            }
            if (!fromAbove && bm < um && tm > wm) {
                run.add(new UpperEnvelope.Piece(x, y, lerp(s, t, t0, t1, x), lerp(s, t, t0, t1, y)));
                result |= RUN;
            } else {
                run.add(new UpperEnvelope.Piece(x, y, lerp(s, t, w0, w1, x), lerp(s, t, w0, w1, y)));
            }
        }
        return result;
    }

    /** Where a straight line from f0 at s to f1 at t crosses zero strictly inside, or NaN. */
    static double root(double s, double t, double f0, double f1) {
        if ((f0 < 0 && f1 > 0) || (f0 > 0 && f1 < 0)) {
            return s + (t - s) * f0 / (f0 - f1);
        }
        return Double.NaN;
    }

    static double lerp(double s, double t, double v0, double v1, double x) {
        if (x <= s) {
            return v0;
        }
        if (x >= t) {
            return v1;
        }
        return v0 + (v1 - v0) * (x - s) / (t - s);
    }
}
