package gcnc.ir;

/**
 * A position in the machine frame, in encoder counts (not rounded): x along the lathe's X axis
 * as a radius, z along its Z axis. Units, diameter programming, G90/G91, work and tool offsets
 * are all resolved by the checker; nothing after it does mode arithmetic.
 */
public record Point(double x, double z) {
    public static final Point ORIGIN = new Point(0, 0);

    public Point plus(double dx, double dz) {
        return new Point(x + dx, z + dz);
    }

    public double distanceTo(Point o) {
        return Math.hypot(o.x - x, o.z - z);
    }
}
