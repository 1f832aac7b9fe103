package gcnc.check.geom;

import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.List;

/**
 * The geometry of tool nose radius compensation, exact and pure (docs/nose-compensation.md): the
 * programmed contour's lines and arcs offset by the nose radius to one side, and the corners
 * between consecutive offset elements. Everything is in the machine's (z, x) plane in counts,
 * x a radius; "right" is the right of the direction of travel drawn with +Z to the right and +X
 * up, the frame G02/G03 are read in ({@link gcnc.ir.ArcGeometry}). A signed offset {@code e} is
 * +r for the right side (G42) and -r for the left (G41).
 */
public final class NoseGeometry {
    /** Cross products of unit tangents below this are a straight continuation (a tangent join). */
    private static final double STRAIGHT = 1e-9;
    /** Lengths below this (counts) are nothing: a corner move or an offset element of no length. */
    public static final double NOTHING = 1e-6;

    private NoseGeometry() {
    }

    /** One element of the programmed path: a line, or an arc about {@code centre} ({@code centre} null for a line). */
    public record Element(Point from, Point to, Point centre, double radius, boolean clockwise) {
        public static Element of(Motion m) {
            return m.accept(new Motion.Visitor<Element>() {
                @Override
                public Element linear(Motion.Linear l) {
                    return new Element(l.from(), l.to(), null, 0, false);
                }

                @Override
                public Element arc(Motion.Arc a) {
                    return new Element(a.from(), a.to(), a.centre(), a.radius(), a.clockwise());
                }

                @Override
                public Element dwell(Motion.Dwell d) {
                    throw new IllegalArgumentException("a dwell is not an element of the path");
                }

                @Override
                public Element thread(Motion.Thread t) {
                    // E178 keeps threads out of compensation: a spindle-synchronised pass is never offset
                    throw new IllegalArgumentException("a thread pass is not compensated (E178)");
                }
            });
        }

        public boolean arc() {
            return centre != null;
        }

        public double length() {
            return from.distanceTo(to);
        }

        /** The unit tangent {x, z} in the direction of travel at {@code p} (a point of the element). */
        public double[] tangentAt(Point p) {
            if (!arc()) {
                double len = length();
                return new double[] {(to.x() - from.x()) / len, (to.z() - from.z()) / len};
            }
            double ux = (p.x() - centre.x()) / radius;
            double uz = (p.z() - centre.z()) / radius;
            double n = Math.hypot(ux, uz);
            ux /= n;
            uz /= n;
            // counter-clockwise in the (z right, x up) drawing turns +z toward +x
            return clockwise ? new double[] {-uz, ux} : new double[] {uz, -ux};
        }

        /** The arc's radius moved by {@code e}: the right of a counter-clockwise arc is outside it. */
        public double offsetRadius(double e) {
            return clockwise ? radius - e : radius + e;
        }

        /** The point {@code p} of the element moved by {@code e} to its right. */
        public Point offsetAt(Point p, double e) {
            double[] n = right(tangentAt(p));
            return new Point(p.x() + e * n[0], p.z() + e * n[1]);
        }
    }

    /**
     * The corner between two consecutive elements: where the first offset element ends, the
     * straight moves the nose makes around a convex corner, and where the second starts.
     * {@code null} from {@link #corner} when the offset elements of a concave corner never meet.
     */
    public record Corner(Point endOfFirst, List<Point> around, Point startOfSecond, boolean concave) {
    }

    /** The right of a unit tangent {x, z}: turned clockwise in the (z right, x up) drawing. */
    static double[] right(double[] t) {
        return new double[] {-t[1], t[0]};
    }

    /** The z-x cross product: positive when {@code b} turns left (counter-clockwise) from {@code a}. */
    static double cross(double[] a, double[] b) {
        return a[1] * b[0] - a[0] * b[1];
    }

    /**
     * The corner at the end of {@code a} (the start of {@code b}) with the offset {@code e}, as a
     * Fanuc type C control makes it: a concave corner at the intersection of the two offset
     * elements (line-line, line-arc, arc-arc), the one nearest the programmed corner; a convex
     * corner of at most 90 degrees of turn at the intersection of the offset tangents; a sharper
     * convex corner (or a reversal) by the two tangents extended by |e| and a move between them.
     */
    public static Corner corner(Element a, Element b, double e) {
        Point p = a.to();
        double[] ta = a.tangentAt(p);
        double[] tb = b.tangentAt(b.from());
        Point ea = a.offsetAt(p, e);
        Point sb = b.offsetAt(b.from(), e);
        double c = cross(ta, tb);
        double dot = ta[0] * tb[0] + ta[1] * tb[1];
        if (Math.abs(c) <= STRAIGHT && dot > 0) {
            return new Corner(ea, List.of(), ea, false);
        }
        boolean convex = Math.signum(e) * c > STRAIGHT || Math.abs(c) <= STRAIGHT;
        if (!convex) {
            Point x = meet(a, b, e, ea, sb, ta, tb, p);
            return x == null ? null : new Corner(x, List.of(), x, true);
        }
        List<Point> around = new ArrayList<>(2);
        if (dot >= 0) {
            double[] na = right(ta);
            double[] nb = right(tb);
            double k = e / (1 + na[0] * nb[0] + na[1] * nb[1]);
            around.add(new Point(p.x() + k * (na[0] + nb[0]), p.z() + k * (na[1] + nb[1])));
        } else {
            double r = Math.abs(e);
            around.add(new Point(ea.x() + r * ta[0], ea.z() + r * ta[1]));
            around.add(new Point(sb.x() - r * tb[0], sb.z() - r * tb[1]));
        }
        return new Corner(ea, List.copyOf(around), sb, false);
    }

    /** Where the offset elements of a concave corner meet, nearest the programmed corner {@code p}. */
    private static Point meet(Element a, Element b, double e, Point ea, Point sb, double[] ta, double[] tb, Point p) {
        List<Point> found;
        if (!a.arc() && !b.arc()) {
            double u = cross(new double[] {sb.x() - ea.x(), sb.z() - ea.z()}, tb) / cross(ta, tb);
            return new Point(ea.x() + u * ta[0], ea.z() + u * ta[1]);
        } else if (!a.arc()) {
            found = lineCircle(ea, ta, b.centre(), b.offsetRadius(e));
        } else if (!b.arc()) {
            found = lineCircle(sb, tb, a.centre(), a.offsetRadius(e));
        } else {
            found = circleCircle(a.centre(), a.offsetRadius(e), b.centre(), b.offsetRadius(e));
        }
        Point best = null;
        for (Point q : found) {
            if (best == null || q.distanceTo(p) < best.distanceTo(p)) {
                best = q;
            }
        }
        return best;
    }

    /** The points of the line through {@code q} along the unit {@code t} at {@code radius} from {@code c}. */
    static List<Point> lineCircle(Point q, double[] t, Point c, double radius) {
        double dx = q.x() - c.x();
        double dz = q.z() - c.z();
        double half = t[0] * dx + t[1] * dz;
        double disc = half * half - (dx * dx + dz * dz - radius * radius);
        if (radius <= 0 || disc < -NOTHING * radius) {
            return List.of();
        }
        double root = Math.sqrt(Math.max(0, disc));
        List<Point> out = new ArrayList<>(2);
        for (double u : new double[] {-half - root, -half + root}) {
            out.add(new Point(q.x() + u * t[0], q.z() + u * t[1]));
        }
        return out;
    }

    /** The points at {@code r1} from {@code c1} and {@code r2} from {@code c2}. */
    static List<Point> circleCircle(Point c1, double r1, Point c2, double r2) {
        double d = c1.distanceTo(c2);
        if (r1 <= 0 || r2 <= 0 || d < NOTHING || d > r1 + r2 + NOTHING || d < Math.abs(r1 - r2) - NOTHING) {
            return List.of();
        }
        double a = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
        double h = Math.sqrt(Math.max(0, r1 * r1 - a * a));
        double ux = (c2.x() - c1.x()) / d;
        double uz = (c2.z() - c1.z()) / d;
        Point m = new Point(c1.x() + a * ux, c1.z() + a * uz);
        return List.of(new Point(m.x() - h * uz, m.z() + h * ux), new Point(m.x() + h * uz, m.z() - h * ux));
    }

    /**
     * Whether the offset element from {@code s} to {@code t} still runs the way the programmed one
     * does: false when a concave corner has cut it back past its other end (interference). This is
     * the Fanuc interference check (PS0041, "interference in CRC"; Fanuc 0i/30i manual, tool nose
     * radius compensation, interference check): a straight move is interference when its
     * compensated direction differs from the programmed one by 90 to 270 degrees (it runs
     * backwards), an arc when the angle from the compensated start to the compensated end differs
     * from the programmed arc's by more than 180 degrees. A compensated arc a little longer or
     * shorter than the programmed one (a concave corner met beyond its end) passes that check and
     * the control runs it (issue 31).
     */
    public static boolean forward(Element el, Point s, Point t) {
        if (s.distanceTo(t) <= NOTHING) {
            return true;
        }
        if (!el.arc()) {
            double[] dir = el.tangentAt(el.from());
            return (t.x() - s.x()) * dir[0] + (t.z() - s.z()) * dir[1] > 0;
        }
        double programmed = sweep(el, el.from(), el.to());
        return Math.abs(sweep(el, s, t) - programmed) <= Math.PI + 1e-9;
    }

    /** The sweep in radians (0, 2 pi] from {@code s} to {@code t} about the element's centre, in its direction. */
    static double sweep(Element el, Point s, Point t) {
        double a0 = Math.atan2(s.x() - el.centre().x(), s.z() - el.centre().z());
        double a1 = Math.atan2(t.x() - el.centre().x(), t.z() - el.centre().z());
        double sw = el.clockwise() ? a0 - a1 : a1 - a0;
        while (sw <= 0) {
            sw += 2 * Math.PI;
        }
        while (sw > 2 * Math.PI) {
            sw -= 2 * Math.PI;
        }
        return sw;
    }
}
