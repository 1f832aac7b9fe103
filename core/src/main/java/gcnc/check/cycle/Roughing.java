package gcnc.check.cycle;

import gcnc.diag.Code;
import gcnc.ir.ArcGeometry;
import gcnc.ir.Letter;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.List;

/**
 * G71 and G72 type I stock removal (Fanuc 0i-TF and Haas lathe manuals, docs/cycles.md): the
 * contour moved by its finishing allowance, then level passes a depth of cut apart from the start
 * point toward the contour, each a feed along the cutting axis from the start's cutting coordinate
 * to the moved contour, a 45-degree rapid retract and a rapid back; then one pass along the moved
 * contour, and a rapid return to the start point. Pure geometry in machine counts: the checker
 * writes the moves as blocks and checks each like any other.
 *
 * <p>Type I: the contour's first move goes along the depth axis only; after it the contour moves
 * one way along the depth axis (back toward the start) and, where it is inside the stock, one way
 * along the cutting axis. A level meets the moved contour once, so each pass is one straight cut.
 */
public final class Roughing {
    /** What planning gives: the moves, or the first reason there are none. */
    public sealed interface Outcome permits Plan, Fault {
    }

    /** The planned moves, how many passes they make, and the contour's two directions. */
    public record Plan(List<Move> moves, int passes, int depthSign, int cutSign) implements Outcome {
        public Plan {
            moves = List.copyOf(moves);
        }
    }

    /**
     * What the cycle block says, in counts: the finishing allowance (dx, dz; dx a radius), the
     * depth of cut along the depth axis, the retract along each axis, the tolerance, and the most
     * passes to expand.
     */
    public record Settings(double dx, double dz, double depth, double retractDepth, double retractCut, double eps,
                           int maxPasses, boolean pocketWalls, boolean anySign) {
        /**
         * The same with the allowance taken whichever way its sign points (after warning E159: the
         * control roughs into the finished shape as written).
         */
        public Settings withAnySign() {
            return new Settings(dx, dz, depth, retractDepth, retractCut, eps, maxPasses, pocketWalls, true);
        }
    }

    private final Axes axes;
    private final Settings s;

    public Roughing(Axes axes, Settings s) {
        this.axes = axes;
        this.s = s;
    }

    /** The moves of the cycle, or the first reason it cannot be expanded. */
    public Outcome plan(Contour c) {
        Point a = c.start();
        Contour.Piece approach = c.approach();
        double eps = s.eps();
        int depthSign = (int) Math.signum(axes.depth(a) - axes.depth(approach.to()));
        boolean alongDepth = Math.abs(axes.cut(approach.to()) - axes.cut(approach.from())) <= eps;
        if (!alongDepth || Math.abs(axes.depth(a) - axes.depth(approach.to())) <= eps) {
            return Fault.atContour(Code.E155_CONTOUR_FIRST_MOVE, approach.line(), axes.depthName());
        }
        int cutSign = 0;
        for (Contour.Piece p : c.shape()) {
            double dc = axes.cut(p.to()) - axes.cut(p.from());
            if (Math.abs(dc) > eps) {
                cutSign = dc < 0 ? 1 : -1;
                break;
            }
        }
        if (cutSign == 0) {
            return Fault.atWord(Code.E163_CONTOUR_EMPTY, null, axes.cutName());
        }
        Point shift = new Point(s.dx(), s.dz());
        if (!s.anySign() && axes.depth(shift) * depthSign < -eps) {
            return allowance(axes == Axes.TURNING ? Letter.U : Letter.W, depthSign);
        }
        if (!s.anySign() && axes.cut(shift) * cutSign < -eps) {
            return allowance(axes == Axes.TURNING ? Letter.W : Letter.U, cutSign);
        }
        Fault f = typeOne(c, depthSign, cutSign);
        if (f != null) {
            return f;
        }
        List<Contour.Piece> moved = new ArrayList<>(c.shape().size());
        for (Contour.Piece p : c.shape()) {
            moved.add(p.shifted(s.dx(), s.dz()));
        }
        Point shapeStart = approach.to().plus(s.dx(), s.dz());
        if ((axes.depth(a) - axes.depth(shapeStart)) * depthSign <= eps) {
            return Fault.atContour(Code.E160_CYCLE_START_INSIDE, approach.line());
        }
        double span = (axes.depth(a) - axes.depth(shapeStart)) * depthSign;
        long levels = (long) Math.ceil((span - eps) / s.depth()) - 1;
        if (levels > s.maxPasses()) {
            return Fault.atWord(Code.E167_CYCLE_TOO_MANY_PASSES, Letter.D, Long.toString(levels + 1),
                    Integer.toString(s.maxPasses()));
        }
        List<double[]> cuts = new ArrayList<>();
        for (int k = 1; k <= levels; k++) {
            double level = axes.depth(a) - depthSign * k * s.depth();
            double[] end = crossing(moved, level, depthSign);
            double length = (axes.cut(a) - end[0]) * cutSign;
            if (length < -eps) {
                return Fault.atContour(Code.E160_CYCLE_START_INSIDE, (int) end[1]);
            }
            if (length > eps) {
                cuts.add(new double[] {level, end[0]});
            }
        }
        return new Plan(moves(a, approach.rapid(), cuts, shapeStart, moved, depthSign, cutSign), cuts.size() + 1,
                depthSign, cutSign);
    }

    private Fault allowance(Letter word, int sign) {
        return Fault.atWord(Code.E159_CYCLE_ALLOWANCE_SIGN, word, sign > 0 ? "positive" : "negative");
    }

    /**
     * The type I rule on the contour as programmed: along the depth axis always one way (toward
     * the start), along the cutting axis one way wherever the piece reaches inside the start's
     * level (a contour may run back along the cutting axis outside the stock, as a last block that
     * returns to the start's Z often does).
     */
    private Fault typeOne(Contour c, int depthSign, int cutSign) {
        double eps = s.eps();
        double startDepth = axes.depth(c.start());
        for (Contour.Piece p : c.shape()) {
            double[] e = p.extent(axes);
            double fd = axes.depth(p.from());
            double td = axes.depth(p.to());
            if ((td - fd) * depthSign < -eps || e[0] < Math.min(fd, td) - eps || e[1] > Math.max(fd, td) + eps) {
                return Fault.atContour(Code.E154_CONTOUR_NOT_MONOTONIC, p.line(), axes.depthName(), "I");
            }
            double innermost = depthSign > 0 ? e[0] : e[1];
            if ((innermost - startDepth) * depthSign >= -eps) {
                continue;
            }
            double fc = axes.cut(p.from());
            double tc = axes.cut(p.to());
            if ((tc - fc) * cutSign > eps || e[2] < Math.min(fc, tc) - eps || e[3] > Math.max(fc, tc) + eps) {
                return Fault.atContour(Code.E154_CONTOUR_NOT_MONOTONIC, p.line(), axes.cutName(), "I");
            }
        }
        return null;
    }

    /**
     * Where a level meets the moved contour first along it: {cut coordinate, source line}. A level
     * the contour never reaches (it ends inside it) ends at the contour's last point.
     */
    private double[] crossing(List<Contour.Piece> moved, double level, int depthSign) {
        double eps = s.eps();
        for (Contour.Piece p : moved) {
            double fd = axes.depth(p.from());
            double td = axes.depth(p.to());
            if ((td - level) * depthSign < -eps) {
                continue;
            }
            Motion.Arc arc = p.arc();
            if (arc != null) {
                return new double[] {arcCrossing(arc, level), p.line()};
            }
            double fc = axes.cut(p.from());
            double tc = axes.cut(p.to());
            if (Math.abs(td - fd) <= eps) {
                return new double[] {fc, p.line()};
            }
            double t = Math.max(0, Math.min(1, (level - fd) / (td - fd)));
            return new double[] {fc + t * (tc - fc), p.line()};
        }
        Contour.Piece last = moved.get(moved.size() - 1);
        return new double[] {axes.cut(last.to()), last.line()};
    }

    /** The cut coordinate where an arc meets a level, the first such point along the arc. */
    private double arcCrossing(Motion.Arc arc, double level) {
        Point c = arc.centre();
        double off = level - axes.depth(c);
        double h = Math.sqrt(Math.max(0, arc.radius() * arc.radius() - off * off));
        double total = Math.abs(ArcGeometry.sweepDegrees(arc.from(), arc.to(), c, arc.clockwise()));
        double best = Double.NaN;
        double bestSweep = Double.MAX_VALUE;
        for (double cut : new double[] {axes.cut(c) + h, axes.cut(c) - h}) {
            Point p = axes.point(level, cut);
            double sweep = p.distanceTo(arc.from()) <= s.eps() ? 0
                    : Math.abs(ArcGeometry.sweepDegrees(arc.from(), p, c, arc.clockwise()));
            if (sweep <= total + 1e-6 && sweep < bestSweep) {
                best = cut;
                bestSweep = sweep;
            }
        }
        return Double.isNaN(best) ? axes.cut(arc.to()) : best;
    }

    private List<Move> moves(Point a, boolean rapidIn, List<double[]> cuts, Point shapeStart,
                             List<Contour.Piece> moved, int depthSign, int cutSign) {
        List<Move> out = new ArrayList<>();
        int passes = cuts.size() + 1;
        Point at = a;
        for (int i = 0; i < cuts.size(); i++) {
            int pass = i + 1;
            double level = cuts.get(i)[0];
            double end = cuts.get(i)[1];
            double away = level + depthSign * s.retractDepth();
            at = add(out, at, Move.line(rapidIn, axes.point(level, axes.cut(a)), pass));
            at = add(out, at, Move.line(false, axes.point(level, end), pass));
            at = add(out, at, Move.line(true, axes.point(away, end + cutSign * s.retractCut()), pass));
            at = add(out, at, Move.line(true, axes.point(away, axes.cut(a)), pass));
        }
        at = add(out, at, Move.line(rapidIn, shapeStart, passes));
        at = follow(out, at, moved, passes);
        back(out, at, a, axes, depthSign, passes);
        return out;
    }

    /** The moved contour's pieces as moves of {@code pass}, each as its block wrote it; where the tool ends. */
    static Point follow(List<Move> out, Point at, List<Contour.Piece> moved, int pass) {
        for (Contour.Piece p : moved) {
            Motion.Arc arc = p.arc();
            if (arc != null) {
                at = add(out, at, new Move(arc.clockwise() ? Move.Kind.ARC_CW : Move.Kind.ARC_CCW, arc.to(),
                        arc.centre(), pass));
            } else {
                at = add(out, at, Move.line(p.rapid(), p.to(), pass));
            }
        }
        return at;
    }

    /**
     * Back to the start point {@code a} by rapid, first along the axis that leaves the part: out
     * along the depth axis when the tool is inside the start's level, else back along the cutting
     * axis; then the other (moves of zero length left out).
     */
    public static List<Move> back(Point at, Point a, Axes axes, int depthSign, int pass) {
        List<Move> out = new ArrayList<>(2);
        back(out, at, a, axes, depthSign, pass);
        return out;
    }

    static void back(List<Move> out, Point at, Point a, Axes axes, int depthSign, int pass) {
        boolean endsOutside = (axes.depth(at) - axes.depth(a)) * depthSign >= 0;
        Point corner = endsOutside ? axes.point(axes.depth(at), axes.cut(a)) : axes.point(axes.depth(a), axes.cut(at));
        at = add(out, at, Move.line(true, corner, pass));
        add(out, at, Move.line(true, a, pass));
    }

    /** Adds a move unless it goes nowhere (a line of zero length); returns where the tool is. */
    static Point add(List<Move> out, Point at, Move m) {
        if (m.kind() != Move.Kind.ARC_CW && m.kind() != Move.Kind.ARC_CCW && m.to().distanceTo(at) <= 1e-9) {
            return at;
        }
        out.add(m);
        return m.to();
    }
}
