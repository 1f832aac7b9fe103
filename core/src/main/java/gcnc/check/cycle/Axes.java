package gcnc.check.cycle;

import gcnc.ir.Point;

/**
 * How a stock removal cycle cuts: G71 steps in along X (the depth axis) and cuts along Z; G72
 * steps in along Z and cuts along X. Every rule of the roughing is written once, on the depth
 * and cut coordinates these give; points stay in machine counts (x a radius).
 */
public enum Axes {
    /** G71: levels in X, cuts along Z. */
    TURNING("X", "Z"),
    /** G72: levels in Z, cuts along X. */
    FACING("Z", "X");

    private final String depthName;
    private final String cutName;

    Axes(String depthName, String cutName) {
        this.depthName = depthName;
        this.cutName = cutName;
    }

    public double depth(Point p) {
        return this == TURNING ? p.x() : p.z();
    }

    public double cut(Point p) {
        return this == TURNING ? p.z() : p.x();
    }

    /** The point at depth {@code d} and cut coordinate {@code c}. */
    public Point point(double d, double c) {
        return this == TURNING ? new Point(d, c) : new Point(c, d);
    }

    /** The depth axis as the program writes it ("X" for G71). */
    public String depthName() {
        return depthName;
    }

    public String cutName() {
        return cutName;
    }

    /** {xMin, xMax, zMin, zMax} as {depthMin, depthMax, cutMin, cutMax}. */
    double[] byAxes(double[] xz) {
        return this == TURNING ? xz : new double[] {xz[2], xz[3], xz[0], xz[1]};
    }
}
