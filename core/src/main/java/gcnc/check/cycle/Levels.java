package gcnc.check.cycle;

import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

/**
 * Where a type II contour lies deeper than a level: the stretches along the cut (v) over which
 * there is material between the level and the contour. The contour moves one way along the cut
 * (checked before), so over each piece its depth is a function of v: lines are interpolated,
 * arcs solved exactly (a circle meets a level at most twice). A piece along the depth axis only
 * (a wall) that reaches above the level splits a stretch there.
 */
final class Levels {
    private Levels() {
    }

    /** The stretches {lo, hi, line of the piece where it ends} at {@code level}, in order along the cut. */
    static List<double[]> spans(PocketRoughing.Frame g, List<Contour.Piece> moved, double level, double eps) {
        List<double[]> ranges = new ArrayList<>();
        List<Double> walls = new ArrayList<>();
        for (Contour.Piece p : moved) {
            double v0 = g.v(p.from());
            double v1 = g.v(p.to());
            double u0 = g.u(p.from());
            double u1 = g.u(p.to());
            if (Math.abs(v1 - v0) <= eps) {
                if (g.extent(p)[0] < level - eps) {
                    walls.add((v0 + v1) / 2);
                }
                continue;
            }
            List<Double> cuts = new ArrayList<>(List.of(Math.min(v0, v1), Math.max(v0, v1)));
            Depth depth;
            Motion.Arc arc = p.arc();
            if (arc != null) {
                depth = arcDepth(arc, p, g, eps);
                Point c = arc.centre();
                double uc = g.u(c);
                double vc = g.v(c);
                double off = level - uc;
                if (Math.abs(off) <= arc.radius()) {
                    double h = Math.sqrt(arc.radius() * arc.radius() - off * off);
                    cuts.add(vc - h);
                    cuts.add(vc + h);
                }
            } else {
                depth = v -> u0 + (v - v0) / (v1 - v0) * (u1 - u0);
                if ((u0 - level) * (u1 - level) < 0) {
                    cuts.add(v0 + (level - u0) / (u1 - u0) * (v1 - v0));
                }
            }
            double lo = cuts.get(0);
            double hi = cuts.get(1);
            List<Double> at = cuts.stream().filter(x -> x >= lo && x <= hi).sorted().toList();
            for (int i = 0; i + 1 < at.size(); i++) {
                double x0 = at.get(i);
                double x1 = at.get(i + 1);
                if (x1 - x0 > 1e-12 && depth.at((x0 + x1) / 2) > level + eps) {
                    ranges.add(new double[] {x0, x1, p.line()});
                }
            }
        }
        ranges.sort(Comparator.comparingDouble(r -> r[0]));
        List<double[]> merged = new ArrayList<>();
        for (double[] r : ranges) {
            double[] last = merged.isEmpty() ? null : merged.get(merged.size() - 1);
            if (last != null && r[0] <= last[1] + eps && !wallBetween(walls, last[1], r[0], eps)) {
                if (r[1] > last[1]) {
                    last[1] = r[1];
                    last[2] = r[2];
                }
            } else {
                merged.add(r.clone());
            }
        }
        return merged;
    }

    /** Whether a wall reaching above the level stands where two stretches meet. */
    private static boolean wallBetween(List<Double> walls, double end, double start, double eps) {
        for (double w : walls) {
            if (w >= Math.min(end, start) - eps && w <= Math.max(end, start) + eps) {
                return true;
            }
        }
        return false;
    }

    /** The depth (u) of a piece at a cut position (v). */
    private interface Depth {
        double at(double v);
    }

    /**
     * An arc's depth as a function of v: the arc moves one way along the cut, so it lies on one
     * side of its centre's level; which side, from its bulge or its end points.
     */
    private static Depth arcDepth(Motion.Arc arc, Contour.Piece p, PocketRoughing.Frame g, double eps) {
        double uc = g.u(arc.centre());
        double vc = g.v(arc.centre());
        double u0 = g.u(arc.from());
        double u1 = g.u(arc.to());
        double[] e = g.extent(p);
        double uMin = e[0];
        double uMax = e[1];
        int side;
        if (uMax > Math.max(u0, u1) + eps) {
            side = 1;
        } else if (uMin < Math.min(u0, u1) - eps) {
            side = -1;
        } else {
            double far = Math.abs(u0 - uc) >= Math.abs(u1 - uc) ? u0 : u1;
            side = far >= uc ? 1 : -1;
        }
        double r = arc.radius();
        return v -> uc + side * Math.sqrt(Math.max(0, r * r - (v - vc) * (v - vc)));
    }
}
