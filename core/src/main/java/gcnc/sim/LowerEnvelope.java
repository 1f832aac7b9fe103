package gcnc.sim;

import java.util.ArrayList;
import java.util.List;

/**
 * The bore: the smallest radius of material at each z of the blank, as a piecewise-linear function
 * over [back, face] (pieces end to end, a step of the bore a jump between two), never above the
 * material. It starts at the blank's bore (0 for a bar) and is raised by the cuts from inside: where
 * a sweep's lower side is at or below it and its upper side above it, nothing is left below the
 * upper side (a centre drill, a drill, a boring bar; {@link EnvelopeCut#stretch}, called by
 * {@link UpperEnvelope#lower}). It never comes down. The same kind of function holds the top run's
 * floor (from it up to the upper envelope the material is one run).
 *
 * <p>With it the stock knows two things without the polygons: a sweep whose upper side stays at
 * or below the bore everywhere it spans is in the hole and touches nothing (a drill's retract, a
 * boring bar's rapids), and, with the upper envelope, a cut from inside leaves each z's material
 * one run from the bore to the envelope, so a drilled or bored part keeps its drawing on the
 * envelope ({@link UpperEnvelope#solid}). Past {@link #MAX_PIECES} it is coarsened to level steps
 * at their smallest radius (lower: still never above the material, but no longer exact).
 */
final class LowerEnvelope {
    /** Pieces kept at most; a bore has a few, a ragged inside thousands. */
    static final int MAX_PIECES = 4096;
    /**
     * How far a sweep's upper side may be above the bore and still be in the hole, mm: a boring
     * bar pulled back along the wall it has just cut is at the bore to a rounding. A million times
     * finer than {@link Stock#DEPTH}, a hundred times finer than the polygons' grid.
     */
    static final double ON = 1e-7;

    private final double back;
    private final double face;
    private final List<UpperEnvelope.Piece> pieces = new ArrayList<>();
    private boolean exact = true;

    LowerEnvelope(double back, double face, double inner) {
        this.back = back;
        this.face = face;
        pieces.add(new UpperEnvelope.Piece(back, face, inner, inner));
    }

    /** Whether it is the material's smallest radius exactly where the material is one run (not coarsened). */
    boolean exact() {
        return exact;
    }

    int size() {
        return pieces.size();
    }

    /** The index of the piece that holds z (the later one where two meet). */
    private int index(double z) {
        return Pieces.holding(pieces, z);
    }

    /** The piece over the stretch [s, t] (no break of this envelope strictly inside it). */
    UpperEnvelope.Piece over(double s, double t) {
        return pieces.get(index((s + t) / 2));
    }

    /** The bore's radius at z (at a step, the larger of its two sides: for tests). */
    double at(double z) {
        int i = index(z);
        double r = pieces.get(i).at(z);
        return i > 0 && pieces.get(i).z0() == z ? Math.max(r, pieces.get(i - 1).at(z)) : r;
    }

    /** The z where pieces meet strictly inside (lo, hi). */
    double[] breaks(double lo, double hi) {
        if (pieces.size() == 1) {
            return new double[0];
        }
        int first = index(lo);
        int last = index(hi);
        double[] out = new double[Math.max(0, last - first)];
        int n = 0;
        for (int i = first + 1; i <= last; i++) {
            double z = pieces.get(i).z0();
            if (z > lo && z < hi) {
                out[n++] = z;
            }
        }
        return n == out.length ? out : java.util.Arrays.copyOf(out, n);
    }

    /**
     * Whether the hull is in the hole: over every z it shares with the blank its upper side is at
     * or below the bore (within {@link #ON}). A yes is certain: it touches no material.
     */
    boolean holds(Hull h) {
        double lo = Math.max(back, h.zMin());
        double hi = Math.min(face, h.zMax());
        if (!(lo <= hi)) {
            return false; // beside the blank: the upper envelope answers
        }
        HullSide top = HullSide.top(h);
        for (int i = index(lo); i < pieces.size() && pieces.get(i).z0() <= hi; i++) {
            UpperEnvelope.Piece p = pieces.get(i);
            double s = Math.max(lo, p.z0());
            double t = Math.min(hi, p.z1());
            if (s > t) {
                continue;
            }
            if (highest(top, s) > p.at(s) + ON || highest(top, t) > p.at(t) + ON) {
                return false;
            }
            for (double z : top.z()) {
                if (z > s && z < t && highest(top, z) > p.at(z) + ON) {
                    return false;
                }
            }
        }
        return true;
    }

    /** The largest radius of the hull's upper side at z (the top of a vertical edge there). */
    private static double highest(HullSide side, double z) {
        double[] sz = side.z();
        double[] sr = side.r();
        double m = Double.NEGATIVE_INFINITY;
        for (int i = 0; i + 1 < sz.length; i++) {
            if (sz[i] <= z && z <= sz[i + 1]) {
                m = Math.max(m, sz[i] == sz[i + 1] ? Math.max(sr[i], sr[i + 1])
                        : sr[i] + (sr[i + 1] - sr[i]) * (z - sz[i]) / (sz[i + 1] - sz[i]));
            }
        }
        return m == Double.NEGATIVE_INFINITY ? Double.POSITIVE_INFINITY : m;
    }

    /** Puts {@code fresh} (pieces covering [lo, hi] end to end) in place of what the envelope had there. */
    void replace(double lo, double hi, List<UpperEnvelope.Piece> fresh) {
        int first = index(lo);
        if (first > 0 && pieces.get(first).z0() == lo) {
            first--; // the piece ending at lo may join the first fresh one
        }
        int last = index(hi);
        List<UpperEnvelope.Piece> all = Pieces.spliced(pieces.subList(first, last + 1), lo, hi, fresh);
        pieces.subList(first, last + 1).clear();
        pieces.addAll(first, Pieces.join(all, false));
        if (pieces.size() > MAX_PIECES) {
            coarsen();
        }
    }

    /** Level steps at the smallest radius of each, MAX_PIECES / 2 of them: lower, never higher. */
    private void coarsen() {
        exact = false;
        int n = MAX_PIECES / 2;
        double w = (face - back) / n;
        List<UpperEnvelope.Piece> steps = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            double s = back + i * w;
            double t = i == n - 1 ? face : back + (i + 1) * w;
            double m = Double.POSITIVE_INFINITY;
            for (int k = index(s); k < pieces.size() && pieces.get(k).z0() <= t; k++) {
                UpperEnvelope.Piece p = pieces.get(k);
                double a = Math.max(s, p.z0());
                double b = Math.min(t, p.z1());
                if (a <= b) {
                    m = Math.min(m, Math.min(p.at(a), p.at(b)));
                }
            }
            steps.add(new UpperEnvelope.Piece(s, t, Math.max(0, m), Math.max(0, m)));
        }
        pieces.clear();
        pieces.addAll(Pieces.join(steps, false));
    }
}
