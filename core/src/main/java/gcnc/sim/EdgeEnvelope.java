package gcnc.sim;

import java.util.ArrayList;
import java.util.List;
import org.locationtech.jts.geom.Coordinate;

/**
 * The envelope over [lo, hi] of a set of straight edges (the material's outlines), for
 * {@link UpperEnvelope#replace}: between two neighbouring ends of edges, a line from the largest radius
 * at one end to the largest at the other (the edges spanning that stretch are straight, so
 * their maximum is convex and the line lies on or above it); 0 where no edge spans. Vertical
 * edges add nothing: each ends on an edge that is not vertical.
 */
final class EdgeEnvelope {
    private final double lo;
    private final double hi;
    private double[] z0 = new double[64];
    private double[] z1 = new double[64];
    private double[] r0 = new double[64];
    private double[] r1 = new double[64];
    private int n;

    EdgeEnvelope(double lo, double hi) {
        this.lo = lo;
        this.hi = hi;
    }

    void edge(Coordinate a, Coordinate b) {
        if (a.x == b.x) {
            return;
        }
        Coordinate l = a.x < b.x ? a : b;
        Coordinate r = a.x < b.x ? b : a;
        double s = Math.max(lo, l.x);
        double t = Math.min(hi, r.x);
        if (!(s < t)) {
            return;
        }
        if (n == z0.length) {
            z0 = java.util.Arrays.copyOf(z0, 2 * n);
            z1 = java.util.Arrays.copyOf(z1, 2 * n);
            r0 = java.util.Arrays.copyOf(r0, 2 * n);
            r1 = java.util.Arrays.copyOf(r1, 2 * n);
        }
        double k = (r.y - l.y) / (r.x - l.x);
        z0[n] = s;
        z1[n] = t;
        r0[n] = s == l.x ? l.y : l.y + k * (s - l.x);
        r1[n] = t == r.x ? r.y : l.y + k * (t - l.x);
        n++;
    }

    List<UpperEnvelope.Piece> pieces() {
        double[] ends = new double[2 * n + 2];
        for (int i = 0; i < n; i++) {
            ends[2 * i] = z0[i];
            ends[2 * i + 1] = z1[i];
        }
        ends[2 * n] = lo;
        ends[2 * n + 1] = hi;
        java.util.Arrays.sort(ends);
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        java.util.Arrays.sort(order, (x, y) -> Double.compare(z0[x], z0[y]));
        List<Integer> active = new ArrayList<>();
        List<UpperEnvelope.Piece> out = new ArrayList<>();
        int next = 0;
        for (int e = 0; e + 1 < ends.length; e++) {
            double s = ends[e];
            double t = ends[e + 1];
            if (!(s < t)) {
                continue;
            }
            while (next < n && z0[order[next]] <= s) {
                active.add(order[next++]);
            }
            active.removeIf(i -> z1[i] <= s);
            double a = 0;
            double b = 0;
            for (int i : active) {
                a = Math.max(a, at(i, s));
                b = Math.max(b, at(i, t));
            }
            out.add(new UpperEnvelope.Piece(s, t, a, b));
        }
        return out;
    }

    private double at(int i, double z) {
        if (z <= z0[i]) {
            return r0[i];
        }
        if (z >= z1[i]) {
            return r1[i];
        }
        return r0[i] + (r1[i] - r0[i]) * (z - z0[i]) / (z1[i] - z0[i]);
    }
}
