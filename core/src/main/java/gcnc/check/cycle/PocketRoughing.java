package gcnc.check.cycle;

import gcnc.diag.Code;
import gcnc.diag.Phrase;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.List;

/**
 * G71 and G72 type II stock removal (pockets; Haas lathe manual G71 and "Troughs", Fanuc 0i-TF;
 * docs/cycles.md). The contour moves one way along the cutting axis but may go in and out along
 * the depth axis. The contour is moved by its finishing allowance; at each level a depth of cut
 * apart, every stretch where the moved contour lies deeper than the level is cut (a span,
 * {@link Levels}). A span lies inside one span of the level before, so the spans make a tree; they
 * are cut in its order, as the Haas manual describes: the material above the pockets first, then
 * each pocket, nearest the start first. Then one pass along the moved contour, and the rapid
 * return to the start point, as type I; with one span per level the moves are type I's.
 *
 * <p>The tool only travels where the spans above have cleared (at the parent span's level plus
 * the retract, inside the parent's stretch), enters a pocket by a feed along the depth axis at the
 * pocket's wall, and leaves each cut by the 45-degree retract, shortened so that it stays over the
 * span just cut.
 */
public final class PocketRoughing {
    /**
     * The two coordinates type II is planned in, measured from the start point {@code a}: u how
     * far in along the depth axis (toward the contour), v how far along the cut.
     */
    record Frame(Axes axes, Point a, int depthSign, int cutSign) {
        double u(double depth) {
            return (axes.depth(a) - depth) * depthSign;
        }

        double u(Point p) {
            return u(axes.depth(p));
        }

        double v(double cut) {
            return (axes.cut(a) - cut) * cutSign;
        }

        double v(Point p) {
            return v(axes.cut(p));
        }

        Point point(double u, double v) {
            return axes.point(axes.depth(a) - depthSign * u, axes.cut(a) - cutSign * v);
        }

        /** {uMin, uMax, vMin, vMax} of a piece, arcs with their bulge. */
        double[] extent(Contour.Piece p) {
            double[] e = p.extent(axes);
            return new double[] {Math.min(u(e[0]), u(e[1])), Math.max(u(e[0]), u(e[1])),
                Math.min(v(e[2]), v(e[3])), Math.max(v(e[2]), v(e[3]))};
        }
    }

    /** One stretch of one level to cut, lo to hi along v (open: it starts at the contour's start). */
    private static final class Span {
        final double u;
        final double lo;
        final double hi;
        final boolean open;
        final Span parent;
        final List<Span> children = new ArrayList<>();

        Span(double u, double lo, double hi, boolean open, Span parent) {
            this.u = u;
            this.lo = lo;
            this.hi = hi;
            this.open = open;
            this.parent = parent;
        }
    }

    private final Axes axes;
    private final Roughing.Settings s;

    public PocketRoughing(Axes axes, Roughing.Settings s) {
        this.axes = axes;
        this.s = s;
    }

    /** The moves of the cycle, or the first reason it cannot be expanded. */
    public Roughing.Outcome plan(Contour c) {
        int cutSign = cutSign(c);
        if (cutSign == 0) {
            return Fault.atWord(Code.E163_CONTOUR_EMPTY, null, axes.cutName());
        }
        int depthSign = depthSign(c);
        if (depthSign == 0) {
            return Fault.atContour(Code.E160_CYCLE_START_INSIDE, c.approach().line());
        }
        Frame f = new Frame(axes, c.start(), depthSign, cutSign);
        Fault fault = check(c, f);
        if (fault != null) {
            return fault;
        }
        List<Contour.Piece> moved = s.pocketWalls() && pocketLine(c, f) > 0 ? onWalls(c, f) : uniform(c);
        if (moved == null) {
            Letter cutWord = axes == Axes.TURNING ? Letter.W : Letter.U;
            return Fault.atWord(Code.E189_TYPE_TWO_CUT_ALLOWANCE, cutWord, Integer.toString(pocketLine(c, f)),
                    Phrase.POCKET_TOO_NARROW.with(axes.cutName()));
        }
        double deepest = 0;
        for (Contour.Piece m : moved) {
            deepest = Math.max(deepest, f.extent(m)[1]);
        }
        if (deepest <= s.eps()) {
            return Fault.atContour(Code.E160_CYCLE_START_INSIDE, c.approach().line());
        }
        long levels = (long) Math.ceil((deepest - s.eps()) / s.depth()) - 1;
        if (levels > s.maxPasses()) {
            return tooMany(levels + 1);
        }
        Point shapeStart = moved.get(0).from();
        List<Span> order = new ArrayList<>();
        fault = spans(f, moved, shapeStart, levels, order);
        if (fault != null) {
            return fault;
        }
        return new Roughing.Plan(moves(f, c.approach().rapid(), order, shapeStart, moved), order.size() + 1,
                depthSign, cutSign);
    }

    /** The way the contour goes along the cut, as type I's sign (+1: toward smaller coordinates); 0: it does not. */
    private int cutSign(Contour c) {
        for (Contour.Piece p : c.shape()) {
            double dc = axes.cut(p.to()) - axes.cut(p.from());
            if (Math.abs(dc) > s.eps()) {
                return dc < 0 ? 1 : -1;
            }
        }
        return 0;
    }

    /** The side of the start the contour reaches farthest to (+1: below along the depth axis); 0: neither. */
    private int depthSign(Contour c) {
        double start = axes.depth(c.start());
        double below = start - axes.depth(c.shapeStart());
        double above = -below;
        for (Contour.Piece p : c.shape()) {
            double[] e = p.extent(axes);
            below = Math.max(below, start - e[0]);
            above = Math.max(above, e[1] - start);
        }
        return Math.max(below, above) <= s.eps() ? 0 : below >= above ? 1 : -1;
    }

    /** The type II rules on the contour and the allowances, in order; the first broken, or null. */
    private Fault check(Contour c, Frame f) {
        double eps = s.eps();
        Point shift = new Point(s.dx(), s.dz());
        Letter depthWord = axes == Axes.TURNING ? Letter.U : Letter.W;
        Letter cutWord = axes == Axes.TURNING ? Letter.W : Letter.U;
        if (!s.anySign() && axes.depth(shift) * f.depthSign() < -eps) {
            return Fault.atWord(Code.E159_CYCLE_ALLOWANCE_SIGN, depthWord, f.depthSign() > 0 ? "positive" : "negative");
        }
        if (!s.anySign() && axes.cut(shift) * f.cutSign() < -eps) {
            return Fault.atWord(Code.E159_CYCLE_ALLOWANCE_SIGN, cutWord, f.cutSign() > 0 ? "positive" : "negative");
        }
        double reached = Double.NEGATIVE_INFINITY;
        int beyond = 0;
        int pocket = 0;
        for (Contour.Piece p : c.shape()) {
            double[] e = f.extent(p);
            double fu = f.u(p.from());
            double tu = f.u(p.to());
            if (e[1] > eps) {
                // inside the start's level: one way along the cut, arcs without a bulge past
                // their ends, and never back over what the contour followed
                double fv = f.v(p.from());
                double tv = f.v(p.to());
                if (tv < fv - eps || e[2] < Math.min(fv, tv) - eps || e[3] > Math.max(fv, tv) + eps
                        || fv < reached - eps) {
                    return Fault.atContour(Code.E154_CONTOUR_NOT_MONOTONIC, p.line(), axes.cutName(), "II");
                }
                reached = Math.max(reached, tv);
                if (beyond > 0) {
                    // past the start's level and back in: the tool, travelling at the start's
                    // level between pockets, would go through the part there
                    return Fault.atContour(Code.E160_CYCLE_START_INSIDE, beyond);
                }
            }
            if (beyond == 0 && e[0] < -eps) {
                beyond = p.line();
            }
            if (pocket == 0 && (tu > fu + eps || e[1] > Math.max(fu, tu) + eps)) {
                pocket = p.line();
            }
        }
        if (pocket > 0 && Math.abs(axes.cut(shift)) > eps && !s.pocketWalls()) {
            return Fault.atWord(Code.E189_TYPE_TWO_CUT_ALLOWANCE, cutWord, Integer.toString(pocket),
                    Phrase.POCKET_UNIFORM.with(axes.cutName(), cutWord.name()));
        }
        return null;
    }

    /** The contour moved by its allowances as a whole (Fanuc; any contour without a pocket). */
    private List<Contour.Piece> uniform(Contour c) {
        List<Contour.Piece> moved = new ArrayList<>(c.shape().size());
        for (Contour.Piece p : c.shape()) {
            moved.add(p.shifted(s.dx(), s.dz()));
        }
        return moved;
    }

    /**
     * The contour moved by its allowances the Haas way ("Troughs"): the depth allowance everywhere,
     * the one along the cut away from every wall, so that it stays on both walls of a pocket. A
     * piece going back out (a pocket's far wall, and every wall of a type I contour) moves as the
     * allowance says, a piece going in (a pocket's near wall) the other way along the cut; a piece
     * along the cut (a pocket's floor, a ridge's top) is stretched or shortened between its
     * neighbours, and a ridge without a top gets one. Without an allowance along the cut this is
     * {@link #uniform}. Null when a pocket is too narrow for its two walls' allowance, or its walls
     * meet without a floor between them, or an arc runs along the cut.
     */
    private List<Contour.Piece> onWalls(Contour c, Frame f) {
        double eps = s.eps();
        double depthShift = axes.depth(new Point(s.dx(), s.dz()));
        double cutShift = axes.cut(new Point(s.dx(), s.dz()));
        if (Math.abs(cutShift) <= eps) {
            return uniform(c);
        }
        List<Contour.Piece> shape = c.shape();
        int n = shape.size();
        int[] way = new int[n];
        for (int i = 0; i < n; i++) {
            double du = f.u(shape.get(i).to()) - f.u(shape.get(i).from());
            way[i] = du > eps ? 1 : du < -eps ? -1 : 0;
            if (way[i] == 0 && shape.get(i).arc() != null) {
                return null;
            }
        }
        List<Contour.Piece> moved = new ArrayList<>(n + 2);
        Point at = c.shapeStart().plus(axes.point(depthShift, 0).x(), axes.point(depthShift, 0).z());
        for (int i = 0; i < n; i++) {
            Contour.Piece p = shape.get(i);
            if (way[i] == 0) {
                Point to = p.to().plus(axes.point(depthShift, 0).x(), axes.point(depthShift, 0).z());
                if (i + 1 < n && way[i + 1] != 0) {
                    to = start(shape.get(i + 1), way[i + 1], depthShift, cutShift);
                }
                if (f.u(to) > eps && f.v(to) < f.v(at) - eps) {
                    return null; // the floor between the walls' allowances is gone: a trough too narrow
                }
                moved.add(line(p, at, to));
                at = to;
                continue;
            }
            Point from = start(p, way[i], depthShift, cutShift);
            if (from.distanceTo(at) > eps) {
                if (Math.abs(f.u(from) - f.u(at)) > eps || f.v(from) < f.v(at) - eps) {
                    return null; // a wall straight after another the other way: no floor to stretch
                }
                moved.add(line(p, at, from)); // the top of a ridge, widened by its two walls' allowance
            }
            Contour.Piece m = p.shifted(axes.point(depthShift, way[i] < 0 ? cutShift : -cutShift).x(),
                    axes.point(depthShift, way[i] < 0 ? cutShift : -cutShift).z());
            moved.add(m);
            at = m.to();
        }
        return moved;
    }

    /** Where a wall going in ({@code way} 1) or out (-1) starts once moved. */
    private Point start(Contour.Piece p, int way, double depthShift, double cutShift) {
        Point d = axes.point(depthShift, way < 0 ? cutShift : -cutShift);
        return p.from().plus(d.x(), d.z());
    }

    /** A straight piece from {@code from} to {@code to}, fed as {@code like} is, at its line. */
    private static Contour.Piece line(Contour.Piece like, Point from, Point to) {
        boolean rapid = like.rapid();
        return new Contour.Piece(new gcnc.ir.Motion.Linear(rapid, from, to, rapid ? null : like.feed()), like.line());
    }

    /** The line of the contour's first pocket (where it first goes back in), or 0 when it has none. */
    private int pocketLine(Contour c, Frame f) {
        double eps = s.eps();
        for (Contour.Piece p : c.shape()) {
            double[] e = f.extent(p);
            double fu = f.u(p.from());
            double tu = f.u(p.to());
            if (tu > fu + eps || e[1] > Math.max(fu, tu) + eps) {
                return p.line();
            }
        }
        return 0;
    }

    /** The spans of every level, in the order they are cut, into {@code order}; a fault, or null. */
    private Fault spans(Frame f, List<Contour.Piece> moved, Point shapeStart, long levels, List<Span> order) {
        double eps = s.eps();
        List<Span> roots = new ArrayList<>();
        List<Span> before = List.of();
        int count = 0;
        for (int k = 1; k <= levels; k++) {
            double level = k * s.depth();
            List<Span> here = new ArrayList<>();
            for (double[] r : Levels.spans(f, moved, level, eps)) {
                boolean open = r[0] <= f.v(shapeStart) + eps && f.u(shapeStart) > level + eps;
                double lo = open ? 0 : r[0];
                if (open && r[1] < -eps) {
                    return Fault.atContour(Code.E160_CYCLE_START_INSIDE, (int) r[2]);
                }
                if (r[1] - lo <= eps) {
                    continue;
                }
                Span parent = null;
                for (Span p : before) {
                    if (open && p.open || r[0] >= p.lo - eps && r[1] <= p.hi + eps) {
                        parent = p;
                        break;
                    }
                }
                Span sp = new Span(level, lo, r[1], open, parent);
                (parent == null ? roots : parent.children).add(sp);
                here.add(sp);
                if (++count > s.maxPasses()) {
                    return tooMany(count);
                }
            }
            before = here;
        }
        for (Span r : roots) {
            depthFirst(r, order);
        }
        return null;
    }

    private Fault tooMany(long passes) {
        return Fault.atWord(Code.E167_CYCLE_TOO_MANY_PASSES, Letter.D, Long.toString(passes),
                Integer.toString(s.maxPasses()));
    }

    private static void depthFirst(Span sp, List<Span> out) {
        out.add(sp);
        for (Span ch : sp.children) {
            depthFirst(ch, out);
        }
    }

    private List<Move> moves(Frame f, boolean rapidIn, List<Span> order, Point shapeStart,
                             List<Contour.Piece> moved) {
        List<Move> out = new ArrayList<>();
        double eD = s.retractDepth();
        double eC = s.retractCut();
        Point at = f.a();
        int pass = 0;
        Span last = null;
        for (Span sp : order) {
            double travel = sp.parent == null ? 0 : sp.parent.u - eD;
            at = travel(f, out, at, travel, sp.open ? 0 : sp.lo, Math.max(pass, 1));
            pass++;
            at = Roughing.add(out, at, Move.line(sp.open && rapidIn, f.point(sp.u, sp.open ? 0 : sp.lo), pass));
            at = Roughing.add(out, at, Move.line(false, f.point(sp.u, sp.hi), pass));
            double back = sp.open ? eC : Math.min(eC, sp.hi - sp.lo);
            at = Roughing.add(out, at, Move.line(true, f.point(sp.u - eD, sp.hi - back), pass));
            last = sp;
        }
        Span open = last;
        while (open != null && !open.open) {
            open = open.parent;
        }
        at = travel(f, out, at, open == null ? 0 : open.u - eD, 0, Math.max(pass, 1));
        int passes = order.size() + 1;
        at = Roughing.add(out, at, Move.line(rapidIn, shapeStart, passes));
        at = Roughing.follow(out, at, moved, passes);
        Roughing.back(out, at, f.a(), axes, f.depthSign(), passes);
        return out;
    }

    /**
     * Rapid from {@code at} out along the depth axis to {@code u} (when deeper), then along the cut
     * to {@code v} at that depth (or at the tool's own, when it is already further out).
     */
    private static Point travel(Frame f, List<Move> out, Point at, double u, double v, int pass) {
        double here = f.u(at);
        if (here > u) {
            at = Roughing.add(out, at, Move.line(true, f.point(u, f.v(at)), pass));
            here = u;
        }
        return Roughing.add(out, at, Move.line(true, f.point(here, v), pass));
    }
}
