package gcnc.sim;

/**
 * A convex polygon in the lathe's half-section, points as (z, r) pairs in counts (r = radius from
 * the spindle centreline). Used for the tool's insert and holder (relative to the tip) and for the
 * chuck and tailstock (absolute).
 */
public record Shape(double[] z, double[] r) {
    public static Shape rect(double z0, double r0, double z1, double r1) {
        return new Shape(new double[] {z0, z1, z1, z0}, new double[] {r0, r0, r1, r1});
    }

    public int size() {
        return z.length;
    }
}
