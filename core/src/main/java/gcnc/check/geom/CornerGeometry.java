package gcnc.check.geom;

import gcnc.ir.Point;

/**
 * The geometry of G01 chamfering and corner rounding (docs/chamfer.md): a G01 from {@code p0} to
 * the corner {@code p1}, the next G01 from {@code p1} to {@code p2}, and the chamfer line or the
 * tangent arc that replaces the corner. Points are in program units with X as a radius (a chamfer
 * of 1 mm is 1 mm along each edge of the part, whatever the X scale), Z across and X up as in the
 * (z right, x up) drawing the rest of gcnc uses for arcs.
 *
 * <p>Chamfer (Haas ",C", Fanuc C, I, K): the value is the distance from the corner to where the
 * chamfer starts on the first move and ends on the second. Corner rounding (",R", Fanuc R): an arc
 * of that radius tangent to both moves, which leaves each move {@code r tan(phi/2)} from the
 * corner, phi being the angle the path turns through there.
 */
public final class CornerGeometry {
    /** Below this (program units, or the sine of an angle) two values are the same. */
    private static final double EPS = 1e-9;

    /** Why a corner cannot be made. */
    public enum Failure {
        /** The two moves are in line (or the second turns straight back): no corner. */
        IN_LINE,
        /** The corner takes more than the first move's length. */
        FIRST_TOO_SHORT,
        /** The corner takes more than the second move's length. */
        SECOND_TOO_SHORT
    }

    /**
     * The corner: the first move now ends at {@code start}, the inserted move goes from there to
     * {@code end} on the second move (a line, or an arc about {@code centre}, clockwise in the
     * drawing when {@code clockwise}), and {@code taken} is how much it takes from each move.
     * {@code failure} is null for a corner that can be made; otherwise {@code taken} and
     * {@code length} say what did not fit (the amount, and the move's length).
     */
    public record Corner(Point start, Point end, Point centre, boolean clockwise, double taken, double length,
                         Failure failure) {
        static Corner failed(Failure f, double taken, double length) {
            return new Corner(null, null, null, false, taken, length, f);
        }

        public boolean ok() {
            return failure == null;
        }
    }

    private CornerGeometry() {
    }

    /** A chamfer {@code c} from the corner on each move. */
    public static Corner chamfer(Point p0, Point p1, Point p2, double c) {
        return make(p0, p1, p2, Math.abs(c), false);
    }

    /** A corner rounded with radius {@code r}. */
    public static Corner round(Point p0, Point p1, Point p2, double r) {
        return make(p0, p1, p2, Math.abs(r), true);
    }

    /** Whether the first move runs along one axis and the second along the other (the 90-degree forms). */
    public static boolean square(Point p0, Point p1, Point p2) {
        boolean firstAlongZ = Math.abs(p1.x() - p0.x()) <= EPS && Math.abs(p1.z() - p0.z()) > EPS;
        boolean firstAlongX = Math.abs(p1.z() - p0.z()) <= EPS && Math.abs(p1.x() - p0.x()) > EPS;
        boolean secondAlongZ = Math.abs(p2.x() - p1.x()) <= EPS && Math.abs(p2.z() - p1.z()) > EPS;
        boolean secondAlongX = Math.abs(p2.z() - p1.z()) <= EPS && Math.abs(p2.x() - p1.x()) > EPS;
        return firstAlongZ && secondAlongX || firstAlongX && secondAlongZ;
    }

    /** Whether the first move runs along Z only (then a 90-degree chamfer is an I; along X, a K). */
    public static boolean firstAlongZ(Point p0, Point p1) {
        return Math.abs(p1.x() - p0.x()) <= EPS;
    }

    private static Corner make(Point p0, Point p1, Point p2, double size, boolean round) {
        double l1 = p0.distanceTo(p1);
        double l2 = p1.distanceTo(p2);
        if (l1 <= EPS || l2 <= EPS) {
            return Corner.failed(l1 <= EPS ? Failure.FIRST_TOO_SHORT : Failure.SECOND_TOO_SHORT, size, 0);
        }
        // unit directions of travel, (x, z)
        double ax = (p1.x() - p0.x()) / l1;
        double az = (p1.z() - p0.z()) / l1;
        double bx = (p2.x() - p1.x()) / l2;
        double bz = (p2.z() - p1.z()) / l2;
        double cross = az * bx - ax * bz; // > 0: the path turns left (counter-clockwise) at the corner
        double dot = ax * bx + az * bz;
        if (Math.abs(cross) <= EPS) {
            return Corner.failed(Failure.IN_LINE, size, 0);
        }
        double phi = Math.atan2(Math.abs(cross), dot); // the angle the path turns through, 0..pi
        double taken = round ? size * Math.tan(phi / 2) : size;
        double tol = EPS * Math.max(1, Math.max(l1, l2));
        if (taken > l1 + tol) {
            return Corner.failed(Failure.FIRST_TOO_SHORT, taken, l1);
        }
        if (taken > l2 + tol) {
            return Corner.failed(Failure.SECOND_TOO_SHORT, taken, l2);
        }
        Point start = new Point(p1.x() - ax * taken, p1.z() - az * taken);
        Point end = new Point(p1.x() + bx * taken, p1.z() + bz * taken);
        if (!round) {
            return new Corner(start, end, null, false, taken, 0, null);
        }
        boolean left = cross > 0;
        // the centre is r from the start, square to the first move, on the side the path turns to;
        // the left of (x, z) in the (z right, x up) drawing is (z, -x)
        double nx = left ? az : -az;
        double nz = left ? -ax : ax;
        Point centre = new Point(start.x() + nx * size, start.z() + nz * size);
        return new Corner(start, end, centre, !left, taken, 0, null);
    }
}
