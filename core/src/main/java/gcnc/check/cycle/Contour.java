package gcnc.check.cycle;

import gcnc.check.geom.MotionParts;
import gcnc.ir.ArcGeometry;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.List;

/**
 * A cycle's contour N(P)..N(Q) as the checker followed it from the cycle's start point: the
 * first move (the approach from the start point A to A') and the finished shape A'..B after it,
 * in machine counts. Each piece keeps the source line of its block.
 *
 * @param start    A, where the tool stands at the cycle block
 * @param approach the first move of the contour, A to A'
 * @param shape    the moves after it, A' to B (never empty)
 */
public record Contour(Point start, Piece approach, List<Piece> shape) {
    public Contour {
        shape = List.copyOf(shape);
        if (shape.isEmpty()) {
            throw new IllegalArgumentException("a contour's shape has at least one move");
        }
    }

    /** One move of the contour: a line (rapid or feed) or an arc, from its block at {@code line}. */
    public record Piece(Motion motion, int line) {
        public Piece {
            if (MotionParts.line(motion) == null && MotionParts.arc(motion) == null) {
                throw new IllegalArgumentException("a contour piece is a line or an arc: " + motion);
            }
        }

        /** The piece's arc, or null for a line. */
        public Motion.Arc arc() {
            return MotionParts.arc(motion);
        }

        public Point from() {
            return MotionParts.path(motion).from();
        }

        public Point to() {
            return MotionParts.path(motion).to();
        }

        public boolean rapid() {
            Motion.Linear l = MotionParts.line(motion);
            return l != null && l.rapid();
        }

        /** The piece's feed (null for a rapid). */
        public gcnc.ir.Feed feed() {
            return MotionParts.path(motion).feed();
        }

        /** {depthMin, depthMax, cutMin, cutMax} of the piece, arcs with their bulge. */
        double[] extent(Axes axes) {
            Motion.Arc a = arc();
            if (a != null) {
                return axes.byAxes(ArcGeometry.bounds(a));
            }
            Point f = from();
            Point t = to();
            return axes.byAxes(new double[] {Math.min(f.x(), t.x()), Math.max(f.x(), t.x()),
                Math.min(f.z(), t.z()), Math.max(f.z(), t.z())});
        }

        /** The same piece moved by (dx, dz) counts: the contour with its finishing allowance. */
        Piece shifted(double dx, double dz) {
            Motion m;
            Motion.Arc a = arc();
            if (a != null) {
                m = new Motion.Arc(a.clockwise(), a.from().plus(dx, dz), a.to().plus(dx, dz), a.centre().plus(dx, dz),
                        a.radius(), a.feed(), a.words());
            } else {
                Motion.Linear l = MotionParts.line(motion);
                m = new Motion.Linear(l.rapid(), l.from().plus(dx, dz), l.to().plus(dx, dz), l.feed());
            }
            return new Piece(m, line);
        }
    }

    /** A', where the shape starts. */
    public Point shapeStart() {
        return approach.to();
    }

    /** B, where the contour ends. */
    public Point end() {
        return shape.get(shape.size() - 1).to();
    }
}
