package gcnc.sim;

/**
 * The lower or the upper side of a sweep's hull ({@link Hull}), its corners z ascending, as
 * {@link UpperEnvelope#lower} reads it: on a stretch no corner of it falls inside, where the side is
 * one straight edge.
 */
record HullSide(double[] z, double[] r) {
    static HullSide bottom(Hull h) {
        int k = h.lowerEnd();
        return new HullSide(java.util.Arrays.copyOf(h.z(), k + 1), java.util.Arrays.copyOf(h.r(), k + 1));
    }

    /** Corner 0, then from the last corner back to where the lower side ends. */
    static HullSide top(Hull h) {
        double[] z = h.z();
        double[] r = h.r();
        int k = h.lowerEnd();
        int m = z.length - k + 1;
        double[] tz = new double[m];
        double[] tr = new double[m];
        tz[0] = z[0];
        tr[0] = r[0];
        for (int j = 1; j < m; j++) {
            tz[j] = z[z.length - j];
            tr[j] = r[z.length - j];
        }
        return new HullSide(tz, tr);
    }

    /**
     * The side's radius at s (start true) or t of a stretch [s, t]: on the one slanted or
     * level edge that spans the stretch (a vertical edge at an end of the hull is not it).
     */
    double at(double s, double t, boolean start) {
        for (int i = 0; i + 1 < z.length; i++) {
            if (z[i] <= s && z[i + 1] >= t && z[i + 1] > z[i]) {
                double q = start ? s : t;
                return r[i] + (r[i + 1] - r[i]) * (q - z[i]) / (z[i + 1] - z[i]);
            }
        }
        return Double.NaN; // no edge spans it (a hull with a NaN corner): the caller keeps the envelope
    }
}
