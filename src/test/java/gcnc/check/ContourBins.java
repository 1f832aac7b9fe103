package gcnc.check;

import java.util.List;

/**
 * The segments of a sampled contour (a polyline of {depth, cut} points, as the roughing property
 * tests build it) filed by where they lie along the cut axis, so that "which segments reach this Z?"
 * looks at a few segments instead of all of them. Why: the property tests ask it for every sampled
 * point of every pass, and a contour sampled at 400 points a move has thousands of segments; the
 * linear scans were most of those tests' time (issue 23: the default test run under five minutes).
 * Only the time changes, not what is judged: {@link #near} returns every segment whose span along the
 * axis comes within {@code pad} of the probe (and maybe a few more), the callers keep their own test of
 * each segment, and their minimum and maximum do not depend on the order the segments come in.
 */
final class ContourBins {
    private final double first;
    private final double width;
    private final int[][] bins;

    /** {@code shape}'s segments (point i to i + 1) by their span in coordinate {@code axis} of the points. */
    ContourBins(List<double[]> shape, int axis) {
        int segments = Math.max(1, shape.size() - 1);
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double[] p : shape) {
            lo = Math.min(lo, p[axis]);
            hi = Math.max(hi, p[axis]);
        }
        first = lo;
        width = hi > lo ? (hi - lo) / segments : 1;
        int[] counts = new int[segments];
        for (int pass = 0; pass < 2; pass++) {
            int[][] filled = pass == 0 ? null : new int[segments][];
            if (filled != null) {
                for (int b = 0; b < segments; b++) {
                    filled[b] = new int[counts[b]];
                    counts[b] = 0;
                }
            }
            for (int i = 0; i + 1 < shape.size(); i++) {
                double a = shape.get(i)[axis];
                double c = shape.get(i + 1)[axis];
                for (int b = bin(Math.min(a, c), segments); b <= bin(Math.max(a, c), segments); b++) {
                    if (filled != null) {
                        filled[b][counts[b]] = i;
                    }
                    counts[b]++;
                }
            }
            if (filled != null) {
                bins = filled;
                return;
            }
        }
        throw new AssertionError("unreachable");
    }

    private int bin(double at, int count) {
        return (int) Math.max(0, Math.min(count - 1, Math.floor((at - first) / width)));
    }

    /**
     * The segments (index of their first point) that may reach within {@code pad} of {@code at} along
     * the axis, each once, in increasing order. A probe outside the contour's span gets the end bins'
     * segments, which the caller's own test then rejects.
     */
    int[] near(double at, double pad) {
        int from = bin(at - pad, bins.length);
        int to = bin(at + pad, bins.length);
        if (from == to) {
            return bins[from];
        }
        java.util.BitSet seen = new java.util.BitSet();
        for (int b = from; b <= to; b++) {
            for (int i : bins[b]) {
                seen.set(i);
            }
        }
        return seen.stream().toArray();
    }
}
