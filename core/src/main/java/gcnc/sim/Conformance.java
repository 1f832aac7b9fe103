package gcnc.sim;

import gcnc.diag.Code;
import gcnc.dmc.Source;
import gcnc.ir.ArcGeometry;
import gcnc.ir.Motion;
import gcnc.ir.Point;

/**
 * Path conformance: does a replayed sequence do what its G-code motion meant? End point within
 * the tolerance; for arcs also the centre and the midpoint (which catches a wrong direction or a
 * long-way/short-way swap); a zero-sweep CR is its own finding (E309).
 */
final class Conformance {
    private final MotionChecks.Reporter out;
    private final PathRecorder path;
    private final double tol;
    /** The tolerance of a geared thread pass ({@link Simulator#threadTolerance}), counts. */
    private final double threadTol;

    Conformance(MotionChecks.Reporter out, PathRecorder path, double tolerance, double threadTolerance) {
        this.out = out;
        this.path = path;
        this.tol = tolerance;
        this.threadTol = threadTolerance;
    }

    /**
     * Compares the sequence with the motion of the block at {@code at} (where its findings go);
     * returns the intended end {x, z} to resynchronise to after a finding (one bad sequence is one
     * finding), else null.
     */
    double[] check(Motion m, java.util.List<Segment> segs, Source at) {
        Segment last = segs.get(segs.size() - 1);
        if (m instanceof Motion.Linear lin) {
            if (segs.size() == 1 && last.arc()) {
                return mismatch(at, "path (an arc for a straight move)", last.length(), lin.to());
            }
            // a move longer than one VP segment is written as pieces: each joint on the programmed line
            for (int i = 0; i < segs.size() - 1; i++) {
                Segment g = segs.get(i);
                double off = g.arc() ? Double.POSITIVE_INFINITY : offLine(g.toX(), g.toZ(), lin.from(), lin.to());
                if (off > tol) {
                    return mismatch(at, "path (a piece of a straight move off its line)", off, lin.to());
                }
            }
            return endPoint(last, lin.to(), at);
        }
        if (m instanceof Motion.Thread t) {
            if (segs.size() != geared(t) || segs.get(0).arc() || last.arc()) {
                return mismatch(at, !t.joints().isEmpty()
                        ? "path (a continuous thread is one straight geared move per block)"
                        : t.chamfered() ? "path (a chamfered thread pass is two straight geared moves)"
                        : "path (a thread pass is one straight geared move)", last.length(), t.to());
            }
            // each corner where the ratios change: a wrong segment and a next one that makes up
            // for it would end right and still cut the wrong thread
            java.util.List<Point> corners = t.corners();
            for (int i = 0; i < corners.size(); i++) {
                double corner = distance(segs.get(i), corners.get(i));
                if (corner > threadTol) {
                    boolean chamfer = t.chamfered() && i == corners.size() - 1;
                    return mismatch(at, chamfer ? "start of the thread's chamfer" : "joint of the continuous thread",
                            corner, threadTol, t.to());
                }
            }
            return endPoint(last, t.to(), at);
        }
        Motion.Arc arc = (Motion.Arc) m; // a dwell has no sequence: the simulator never pairs one
        Point to = arc.to();
        // The arc is the sequence's first segment; a closing VP of a count or two may follow it
        // (the galil dialect's whole-count radius), so the end point is the last segment's.
        Segment first = segs.get(0);
        if (!first.arc() && pointLike(arc, tol)) {
            return endPoint(last, to, at); // a circle within the tolerance: a straight move is as good
        }
        if (!first.arc()) {
            return mismatch(at, "path (a straight move for an arc)", distance(last, to), to);
        }
        if (first.sweepDeg() == 0) {
            out.report(Code.E309_SIM_ZERO_SWEEP_ARC, at, first.text());
            mark("E309", at.line(), to);
            return new double[] {to.x(), to.z()};
        }
        double centre = Geometry.length(first.centreX() - arc.centre().x(), first.centreZ() - arc.centre().z());
        if (centre > tol) {
            return mismatch(at, "arc centre", centre, to);
        }
        double sweep = ArcGeometry.sweepDegrees(arc.from(), to, arc.centre(), arc.clockwise());
        double a = Math.atan2(arc.from().x() - arc.centre().x(), arc.from().z() - arc.centre().z())
                + Math.toRadians(sweep / 2);
        double[] mid = first.at(0.5);
        double off = Geometry.length(mid[0] - (arc.centre().x() + arc.radius() * Math.sin(a)),
                mid[1] - (arc.centre().z() + arc.radius() * Math.cos(a)));
        if (off > tol) {
            return mismatch(at, "arc direction or sweep (midpoint)", off, to);
        }
        return endPoint(last, to, at);
    }

    /** How many geared segments a thread pass replays as: one per block of a continuous thread, and its chamfer (M23). */
    static int geared(Motion.Thread t) {
        return t.corners().size() + 1;
    }

    /**
     * A circle no wider than the tolerance: the backend may write its arc as a straight move, and
     * the simulator pairs and checks it so (one rule for {@code Simulator} and this class).
     */
    /** How far (counts) the point (x, z) is from the straight move from {@code a} to {@code b}. */
    private static double offLine(double x, double z, Point a, Point b) {
        double dx = b.x() - a.x();
        double dz = b.z() - a.z();
        double len2 = dx * dx + dz * dz;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((x - a.x()) * dx + (z - a.z()) * dz) / len2));
        return Geometry.length(x - (a.x() + t * dx), z - (a.z() + t * dz));
    }

    static boolean pointLike(Motion.Arc arc, double tolerance) {
        return 2 * arc.radius() <= tolerance;
    }

    private double[] endPoint(Segment last, Point to, Source at) {
        double d = distance(last, to);
        return d > tol ? mismatch(at, "end point", d, to) : null;
    }

    private static double distance(Segment s, Point p) {
        return Geometry.length(s.toX() - p.x(), s.toZ() - p.z());
    }

    private double[] mismatch(Source at, String what, double by, Point to) {
        return mismatch(at, what, by, tol, to);
    }

    private double[] mismatch(Source at, String what, double by, double tolerance, Point to) {
        out.report(Code.E308_SIM_PATH_MISMATCH, at, what, MotionChecks.mm(by), MotionChecks.mm(tolerance));
        mark("E308", at.line(), to);
        return new double[] {to.x(), to.z()};
    }

    private void mark(String code, int line, Point p) {
        if (path != null) {
            path.mark(code, "line " + line, line, p.x(), p.z());
        }
    }
}
