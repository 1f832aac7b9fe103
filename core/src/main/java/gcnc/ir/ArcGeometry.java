package gcnc.ir;

import java.util.Optional;

/**
 * Arc centres for G02/G03 in the machine's (z, x) plane, x as a radius. G02 is clockwise when
 * drawn with +Z to the right and +X up, the lathe convention that makes one program fit front and
 * rear tool posts alike (the post changes how the arc looks from the operator's side, not where
 * its centre is). Pure functions; callers turn an empty result into a located diagnostic.
 */
public final class ArcGeometry {
    private ArcGeometry() {
    }

    /**
     * The centre of the arc of radius |r| from {@code a} to {@code b}. A positive R takes the short
     * way (sweep up to 180 degrees), a negative R the long way (Fanuc). Empty when the chord is longer
     * than 2|r| by more than {@code tolerance} counts, or the end points coincide.
     */
    public static Optional<Point> centreFromRadius(Point a, Point b, double r, boolean clockwise, double tolerance) {
        double dz = b.z() - a.z();
        double dx = b.x() - a.x();
        double chord = Math.hypot(dz, dx);
        double radius = Math.abs(r);
        if (chord == 0 || radius == 0 || chord > 2 * radius + tolerance) {
            return Optional.empty();
        }
        double half = chord / 2;
        double h = half >= radius ? 0 : Math.sqrt(radius * radius - half * half);
        // Unit normal to the chord, to the left of a->b in the (z right, x up) drawing.
        double nz = -dx / chord;
        double nx = dz / chord;
        // A clockwise short arc has its centre to the right of the chord; R<0 (long way) swaps sides.
        double side = (clockwise ? -1 : 1) * (r < 0 ? -1 : 1);
        return Optional.of(new Point(a.x() + dx / 2 + side * h * nx, a.z() + dz / 2 + side * h * nz));
    }

    /** How far {@code b} is from the circle through {@code a} about {@code centre} (I/K arcs). */
    public static double endPointError(Point a, Point b, Point centre) {
        return Math.abs(a.distanceTo(centre) - b.distanceTo(centre));
    }

    /**
     * The signed sweep in degrees of the arc from {@code a} to {@code b} about {@code centre},
     * measured in the (z right, x up) drawing: negative for clockwise (G02), in (-360, 0] or [0, 360).
     * A coinciding start and end make a full circle.
     */
    public static double sweepDegrees(Point a, Point b, Point centre, boolean clockwise) {
        double start = Math.atan2(a.x() - centre.x(), a.z() - centre.z());
        double end = Math.atan2(b.x() - centre.x(), b.z() - centre.z());
        double sweep = Math.toDegrees(end - start);
        if (clockwise) {
            while (sweep >= 0) {
                sweep -= 360;
            }
            while (sweep < -360) {
                sweep += 360;
            }
        } else {
            while (sweep <= 0) {
                sweep += 360;
            }
            while (sweep > 360) {
                sweep -= 360;
            }
        }
        return sweep;
    }

    /**
     * {xMin, xMax, zMin, zMax} of an arc in the (z right, x up) drawing: its end points and the
     * points where it crosses 0, 90, 180 or 270 degrees (0 = +z, 90 = +x), where it bulges most.
     */
    public static double[] bounds(double fromX, double fromZ, double toX, double toZ, double centreX, double centreZ,
                                  double radius, double startDeg, double sweepDeg) {
        double[] b = {Math.min(fromX, toX), Math.max(fromX, toX), Math.min(fromZ, toZ), Math.max(fromZ, toZ)};
        double lo = Math.min(startDeg, startDeg + sweepDeg);
        double hi = Math.max(startDeg, startDeg + sweepDeg);
        for (double q = Math.ceil(lo / 90) * 90; q <= hi; q += 90) {
            switch (Math.floorMod((int) Math.round(q / 90), 4)) {
                case 0 -> b[3] = Math.max(b[3], centreZ + radius);
                case 1 -> b[1] = Math.max(b[1], centreX + radius);
                case 2 -> b[2] = Math.min(b[2], centreZ - radius);
                default -> b[0] = Math.min(b[0], centreX - radius);
            }
        }
        return b;
    }

    /** The same for an arc motion. */
    public static double[] bounds(Motion.Arc a) {
        Point f = a.from();
        Point c = a.centre();
        double start = Math.toDegrees(Math.atan2(f.x() - c.x(), f.z() - c.z()));
        return bounds(f.x(), f.z(), a.to().x(), a.to().z(), c.x(), c.z(), a.radius(), start,
                sweepDegrees(f, a.to(), c, a.clockwise()));
    }
}
