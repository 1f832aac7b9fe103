package gcnc.sim;

/**
 * A convex polygon in the stock's frame (mm): its corners counterclockwise from the lowest z, the
 * lower chain first; what a tool part sweeps in one straight piece of a move ({@link #sweep}),
 * which the {@link Stock} cuts and its envelopes are lowered under.
 */
record Hull(double[] z, double[] r) {
    /** The hull's lowest r over z in [a, b] (its lower chain is convex, so a corner or an end of the range). */
    double lowest(double a, double b) {
        double m = Double.POSITIVE_INFINITY;
        for (int i = 0, end = lowerEnd(); i < end; i++) {
            double lo = Math.max(a, z[i]);
            double hi = Math.min(b, z[i + 1]);
            if (lo <= hi) {
                m = Math.min(m, Math.min(at(i, lo), at(i, hi)));
            }
        }
        return m;
    }

    private double at(int i, double v) {
        return r[i] + (r[i + 1] - r[i]) * (v - z[i]) / (z[i + 1] - z[i]);
    }

    /** The last corner of the lower chain: corners 0 .. lowerEnd() rise in z. */
    int lowerEnd() {
        int k = 0;
        while (k + 1 < z.length && z[k + 1] > z[k]) {
            k++;
        }
        return k;
    }

    double zMin() {
        return z[0];
    }

    double zMax() {
        double m = z[0];
        for (double v : z) {
            m = Math.max(m, v);
        }
        return m;
    }


    /**
     * The area a convex outline ({@code z}, {@code r} relative to the tip, mm) sweeps while its tip
     * moves in a straight line from (az, ar) to (bz, br): the convex hull of both positions; null
     * when it has no area.
     */
    static Hull sweep(double[] z, double[] r, double az, double ar, double bz, double br) {
        int n = z.length;
        double[] pz = new double[2 * n];
        double[] pr = new double[2 * n];
        for (int i = 0; i < n; i++) {
            pz[i] = az + z[i];
            pr[i] = ar + r[i];
            pz[n + i] = bz + z[i];
            pr[n + i] = br + r[i];
        }
        int[] h = gcnc.machine.MonotoneChain.hull(pz, pr);
        if (h.length < 3) {
            return null; // all points on one line: no area
        }
        double[] hz = new double[h.length];
        double[] hr = new double[h.length];
        for (int i = 0; i < h.length; i++) {
            hz[i] = pz[h[i]];
            hr[i] = pr[h[i]];
        }
        return new Hull(hz, hr);
    }

    /** Whether every corner of {@code h} is in the convex {@code c} (its corners counterclockwise), within 1e-9 mm. */
    static boolean inside(Hull h, Hull c) {
        double[] cz = c.z();
        double[] cr = c.r();
        int n = cz.length;
        for (int k = 0; k < h.z().length; k++) {
            double pz = h.z()[k];
            double pr = h.r()[k];
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double ez = cz[j] - cz[i];
                double er = cr[j] - cr[i];
                double len = Math.hypot(ez, er);
                if (len > 0 && (ez * (pr - cr[i]) - er * (pz - cz[i])) / len < -1e-9) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * A convex outline ({@code z}, {@code r}) moved toward its centre so that no point moves more
     * than half the {@link Stock#DEPTH}: the outline {@link Stock#mayBite} is given.
     */
    static double[][] smaller(double[] z, double[] r) {
        double cz = 0;
        double cr = 0;
        for (int i = 0; i < z.length; i++) {
            cz += z[i] / z.length;
            cr += r[i] / z.length;
        }
        double far = 0;
        for (int i = 0; i < z.length; i++) {
            far = Math.max(far, Math.hypot(z[i] - cz, r[i] - cr));
        }
        double k = far == 0 ? 1 : Math.max(0, 1 - Stock.DEPTH / 2 / far);
        double[] sz = new double[z.length];
        double[] sr = new double[r.length];
        for (int i = 0; i < z.length; i++) {
            sz[i] = cz + (z[i] - cz) * k;
            sr[i] = cr + (r[i] - cr) * k;
        }
        return new double[][] {sz, sr};
    }
}
