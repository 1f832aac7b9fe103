package gcnc.check.cycle;

import gcnc.diag.Code;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.List;

/**
 * G71 and G72 type II stock removal (pockets; Fanuc 0i-TF, Haas lathe manual "Troughs",
 * docs/cycles.md). The contour moves one way along the cutting axis but may go in and out along
 * the depth axis. The contour is moved by its finishing allowance; at each level a depth of cut
 * apart, every stretch where the moved contour lies deeper than the level is cut ("spans"). A
 * span at a level lies inside one span of the level before, so the spans make a tree; they are
 * cut in its order, as the Haas manual describes: the material above the pockets first, then
 * each pocket, nearest the start first. Then one pass along the moved contour, and the rapid
 * return to the start point, as type I.
 *
 * <p>Geometry in two coordinates measured from the start point A: {@code u} how far in along the
 * depth axis (toward the contour), {@code v} how far along the cut. The tool only travels where
 * the spans above have cleared (at the parent span's level plus the retract, inside the parent's
 * stretch), enters a pocket by a feed along the depth axis at the pocket's wall, and leaves each
 * cut by the 45-degree retract, shortened so that it stays over the span just cut.
 */
public final class PocketRoughing {
    /** One stretch of one level to cut: from lo to hi along v (open: it starts at the contour's start). */
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
    private Point a;
    private int depthSign;
    private int cutSign;

    public PocketRoughing(Axes axes, Roughing.Settings s) {
        this.axes = axes;
        this.s = s;
    }

    /** The moves of the cycle, or the first reason it cannot be expanded. */
    public Roughing.Outcome plan(Contour c) {
        a = c.start();
        double eps = s.eps();
        cutSign = 0;
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
        double lowest = axes.depth(c.shapeStart());
        double highest = lowest;
        for (Contour.Piece p : c.shape()) {
            double[] e = p.extent(axes);
            lowest = Math.min(lowest, e[0]);
            highest = Math.max(highest, e[1]);
        }
        double below = axes.depth(a) - lowest;
        double above = highest - axes.depth(a);
        if (Math.max(below, above) <= eps) {
            return Fault.atContour(Code.E160_CYCLE_START_INSIDE, c.approach().line());
        }
        depthSign = below >= above ? 1 : -1;
        Point shift = new Point(s.dx(), s.dz());
        Letter depthWord = axes == Axes.TURNING ? Letter.U : Letter.W;
        Letter cutWord = axes == Axes.TURNING ? Letter.W : Letter.U;
        if (axes.depth(shift) * depthSign < -eps) {
            return Fault.atWord(Code.E159_CYCLE_ALLOWANCE_SIGN, depthWord, depthSign > 0 ? "positive" : "negative");
        }
        if (axes.cut(shift) * cutSign < -eps) {
            return Fault.atWord(Code.E159_CYCLE_ALLOWANCE_SIGN, cutWord, cutSign > 0 ? "positive" : "negative");
        }
        Fault f = oneWayAlongTheCut(c);
        if (f != null) {
            return f;
        }
        int beyond = 0;
        for (Contour.Piece p : c.shape()) {
            double[] e = p.extent(axes);
            double in = Math.max(u(e[0]), u(e[1]));
            double out = Math.min(u(e[0]), u(e[1]));
            if (beyond > 0 && in > eps) {
                // the contour reaches past the start's level and comes back: the tool, travelling
                // at the start's level between the pockets, would go through the part there
                return Fault.atContour(Code.E160_CYCLE_START_INSIDE, beyond);
            }
            if (beyond == 0 && out < -eps) {
                beyond = p.line();
            }
        }
        int pocket = pocketLine(c);
        if (pocket > 0 && Math.abs(axes.cut(shift)) > eps) {
            return Fault.atWord(Code.E189_TYPE_TWO_CUT_ALLOWANCE, cutWord, Integer.toString(pocket), axes.cutName(),
                    cutWord.name());
        }
        List<Contour.Piece> moved = new ArrayList<>(c.shape().size());
        double deepest = 0;
        for (Contour.Piece p : c.shape()) {
            Contour.Piece m = p.shifted(s.dx(), s.dz());
            moved.add(m);
            double[] e = m.extent(axes);
            deepest = Math.max(deepest, Math.max(u(e[0]), u(e[1])));
        }
        Point shapeStart = c.shapeStart().plus(s.dx(), s.dz());
        if (deepest <= eps) {
            return Fault.atContour(Code.E160_CYCLE_START_INSIDE, c.approach().line());
        }
        long levels = (long) Math.ceil((deepest - eps) / s.depth()) - 1;
        if (levels > s.maxPasses()) {
            return Fault.atWord(Code.E167_CYCLE_TOO_MANY_PASSES, Letter.D, Long.toString(levels + 1),
                    Integer.toString(s.maxPasses()));
        }
        List<Span> roots = new ArrayList<>();
        List<Span> above2 = List.of();
        int count = 0;
        for (int k = 1; k <= levels; k++) {
            double level = k * s.depth();
            List<Span> here = new ArrayList<>();
            for (double[] r : Levels.spans(moved, level, this)) {
                boolean open = r[0] <= v(shapeStart) + eps && u(shapeStart) > level + eps;
                double lo = open ? 0 : r[0];
                if (open && r[1] < -eps) {
                    return Fault.atContour(Code.E160_CYCLE_START_INSIDE, (int) r[2]);
                }
                if (r[1] - lo <= eps) {
                    continue;
                }
                Span parent = null;
                for (Span p : above2) {
                    if (r[0] >= p.lo - eps && r[1] <= p.hi + eps || open && p.open) {
                        parent = p;
                        break;
                    }
                }
                Span sp = new Span(level, lo, r[1], open, parent);
                (parent == null ? roots : parent.children).add(sp);
                here.add(sp);
                if (++count > s.maxPasses()) {
                    return Fault.atWord(Code.E167_CYCLE_TOO_MANY_PASSES, Letter.D, Integer.toString(count),
                            Integer.toString(s.maxPasses()));
                }
            }
            above2 = here;
        }
        List<Span> order = new ArrayList<>(count);
        for (Span r : roots) {
            depthFirst(r, order);
        }
        return new Roughing.Plan(moves(c.approach().rapid(), order, shapeStart, moved), order.size() + 1, depthSign,
                cutSign);
    }

    private static void depthFirst(Span sp, List<Span> out) {
        out.add(sp);
        for (Span ch : sp.children) {
            depthFirst(ch, out);
        }
    }

    /**
     * Type II along the cutting axis: one way (as Fanuc and Haas require), arcs without a bulge
     * past their end points, wherever the contour reaches inside the start's level; outside it the
     * contour may come back, but not to enter again over what it followed.
     */
    private Fault oneWayAlongTheCut(Contour c) {
        double eps = s.eps();
        double reached = Double.NEGATIVE_INFINITY;
        for (Contour.Piece p : c.shape()) {
            double[] e = p.extent(axes);
            if (Math.max(u(e[0]), u(e[1])) <= eps) {
                continue;
            }
            double fv = v(p.from());
            double tv = v(p.to());
            double vMin = Math.min(v(axes.point(0, e[2])), v(axes.point(0, e[3])));
            double vMax = Math.max(v(axes.point(0, e[2])), v(axes.point(0, e[3])));
            if (tv < fv - eps || vMin < Math.min(fv, tv) - eps || vMax > Math.max(fv, tv) + eps || fv < reached - eps) {
                return Fault.atContour(Code.E154_CONTOUR_NOT_MONOTONIC, p.line(), axes.cutName(), "II");
            }
            reached = Math.max(reached, tv);
        }
        return null;
    }

    /** The line of the first piece after the first move that goes in along the depth axis (a pocket), or 0. */
    private int pocketLine(Contour c) {
        double eps = s.eps();
        for (Contour.Piece p : c.shape()) {
            double[] e = p.extent(axes);
            double deepest = Math.max(u(e[0]), u(e[1]));
            if (deepest > Math.max(u(axes.depth(p.from())), u(axes.depth(p.to()))) + eps
                    || u(axes.depth(p.to())) > u(axes.depth(p.from())) + eps) {
                return p.line();
            }
        }
        return 0;
    }

    private List<Move> moves(boolean rapidIn, List<Span> order, Point shapeStart, List<Contour.Piece> moved) {
        List<Move> out = new ArrayList<>();
        double eD = s.retractDepth();
        double eC = s.retractCut();
        Point at = a;
        int pass = 0;
        Span last = null;
        for (Span sp : order) {
            double travel = sp.parent == null ? 0 : sp.parent.u - eD;
            at = travel(out, at, travel, sp.open ? 0 : sp.lo, Math.max(pass, 1));
            pass++;
            if (sp.open) {
                at = Roughing.add(out, at, Move.line(rapidIn, point(sp.u, 0), pass));
            } else {
                at = Roughing.add(out, at, Move.line(false, point(sp.u, sp.lo), pass));
            }
            at = Roughing.add(out, at, Move.line(false, point(sp.u, sp.hi), pass));
            double back = sp.open ? eC : Math.min(eC, sp.hi - sp.lo);
            at = Roughing.add(out, at, Move.line(true, point(sp.u - eD, sp.hi - back), pass));
            last = sp;
        }
        Span open = last;
        while (open != null && !open.open) {
            open = open.parent;
        }
        at = travel(out, at, open == null ? 0 : open.u - eD, 0, Math.max(pass, 1));
        int passes = order.size() + 1;
        at = Roughing.add(out, at, Move.line(rapidIn, shapeStart, passes));
        at = Roughing.follow(out, at, moved, passes);
        Roughing.back(out, at, a, axes, depthSign, passes);
        return out;
    }

    /**
     * Rapid from {@code at} out along the depth axis to {@code u} (when deeper), then along the cut
     * to {@code v} at that depth (or at the tool's own, when it is already further out).
     */
    private Point travel(List<Move> out, Point at, double u, double v, int pass) {
        double here = u(axes.depth(at));
        if (here > u) {
            at = Roughing.add(out, at, Move.line(true, point(u, v(at)), pass));
            here = u;
        }
        return Roughing.add(out, at, Move.line(true, point(here, v), pass));
    }

    /** How far in from the start's level a depth coordinate is (toward the contour: positive). */
    double u(double depth) {
        return (axes.depth(a) - depth) * depthSign;
    }

    /** How far along the cut from the start a point is. */
    double v(Point p) {
        return (axes.cut(a) - axes.cut(p)) * cutSign;
    }

    double u(Point p) {
        return u(axes.depth(p));
    }

    Point point(double u, double v) {
        return axes.point(axes.depth(a) - depthSign * u, axes.cut(a) - cutSign * v);
    }

    Axes axes() {
        return axes;
    }

    double eps() {
        return s.eps();
    }
}
