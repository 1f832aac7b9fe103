package gcnc.machine;

import java.util.Arrays;

/**
 * The convex hull of a handful of points in the (z, r) plane by Andrew's monotone chain: the tool
 * library's holder (the insert's upper edges) and the simulator's swept areas (an outline at both
 * ends of a move) both need it, for a dozen points at most, which JTS's general algorithm is far
 * too heavy for. Collinear points are dropped.
 */
public final class MonotoneChain {
    private MonotoneChain() {
    }

    /** The hull's corners, counterclockwise from the lowest z (then lowest r); fewer than 3 when the points are on a line. */
    public static int[] hull(double[] z, double[] r) {
        int[] lower = chain(z, r, order(z, r, false));
        int[] upper = chain(z, r, order(z, r, true));
        int[] h = new int[lower.length + upper.length - 2];
        System.arraycopy(lower, 0, h, 0, lower.length - 1);
        System.arraycopy(upper, 0, h, lower.length - 1, upper.length - 1);
        return h;
    }

    /** The hull's upper chain, from the lowest z to the highest. */
    public static int[] upper(double[] z, double[] r) {
        int[] rightToLeft = chain(z, r, order(z, r, true));
        int[] out = new int[rightToLeft.length];
        for (int i = 0; i < out.length; i++) {
            out[i] = rightToLeft[out.length - 1 - i];
        }
        return out;
    }

    /** The points sorted by z then r, ascending, or descending for the upper chain. */
    private static Integer[] order(double[] z, double[] r, boolean descending) {
        Integer[] o = new Integer[z.length];
        for (int i = 0; i < o.length; i++) {
            o[i] = i;
        }
        Arrays.sort(o, (p, q) -> {
            int c = z[p] != z[q] ? Double.compare(z[p], z[q]) : Double.compare(r[p], r[q]);
            return descending ? -c : c;
        });
        return o;
    }

    /** One chain: the points in order, keeping only left turns. */
    private static int[] chain(double[] z, double[] r, Integer[] order) {
        int[] h = new int[order.length];
        int k = 0;
        for (int i : order) {
            while (k >= 2 && cross(z, r, h[k - 2], h[k - 1], i) <= 0) {
                k--;
            }
            h[k++] = i;
        }
        return Arrays.copyOf(h, k);
    }

    private static double cross(double[] z, double[] r, int o, int a, int b) {
        return (z[a] - z[o]) * (r[b] - r[o]) - (r[a] - r[o]) * (z[b] - z[o]);
    }
}
