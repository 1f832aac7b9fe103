package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.ir.ArcGeometry;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.ProgramFrame;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Random type I contours (steps, chamfers, quarter-round corners), outside and inside, roughed by
 * G71 with random depth, retract and allowances: no point of any pass (sampled along each move)
 * is inside the contour moved by its allowance. The contour is taken from the G70 that follows
 * the same blocks, so the test does not share the expansion's geometry. Seeds print on failure.
 */
class CycleRoughingPropertyTest {
    private static final int PROGRAMS = 60;
    /** How far a pass may reach past the moved contour: rounding of six-decimal words, mm. */
    private static final double TOLERANCE = 0.002;

    @ParameterizedTest
    @ValueSource(ints = {1, -1})
    void passesNeverCutBelowTheContourPlusItsAllowance(int side) throws Exception {
        boolean outside = side > 0;
        for (int seed = 1; seed <= PROGRAMS; seed++) {
            Random r = new Random(seed * 7919L + (outside ? 1 : 2));
            double u = r.nextInt(3) * 0.2 * (outside ? 1 : -1);
            double w = r.nextInt(3) * 0.05;
            String program = program(r, outside, u, w);
            String where = "seed " + seed + (outside ? " outside" : " inside") + "\n" + program;
            CycleExpansionTest.Expanded e = CycleExpansionTest.expand("fanuc", new StringReader(program));
            assertTrue(e.diagnostics().sorted().stream().noneMatch(d -> d.severity() == gcnc.diag.Severity.ERROR),
                    () -> where + e.diagnostics().sorted());
            List<double[]> contour = new ArrayList<>();
            List<CheckedBlock> passes = new ArrayList<>();
            ProgramFrame frame = null;
            for (CheckedBlock b : e.blocks()) {
                String seq = b.frame().sequence();
                if (seq.contains("G71 pass")) {
                    passes.add(b);
                    frame = b.frame();
                } else if (seq.contains("G70 pass") && b.line() > 0 && !b.motions().isEmpty()) {
                    for (Motion m : b.motions()) {
                        sample(m, b.frame(), contour, 400);
                    }
                }
            }
            assertTrue(passes.size() > 4 && contour.size() > 10, where);
            // the G70's first move is the approach and its last two are the return: the shape is between
            List<double[]> shape = shape(contour, u, w);
            int s = outside ? 1 : -1;
            for (CheckedBlock b : passes) {
                for (Motion m : b.motions()) {
                    List<double[]> pts = new ArrayList<>();
                    sample(m, frame, pts, 60);
                    for (double[] p : pts) {
                        double limit = boundary(shape, p[1], s);
                        if (!Double.isNaN(limit)) {
                            assertTrue(s * (p[0] - limit) >= -TOLERANCE, () -> String.format(Locale.ROOT,
                                    "%s%s at X%.4f Z%.4f is inside the contour (X%.4f there)", where,
                                    b.frame().sequence(), p[0], p[1], limit));
                        }
                    }
                }
            }
        }
    }

    /** A start point, a G71 first block, the second, a random contour N10..N20, a G70. */
    private static String program(Random r, boolean outside, double u, double w) {
        StringBuilder c = new StringBuilder();
        double x = outside ? 4 + r.nextInt(8) * 2 : 60 - r.nextInt(6) * 2;
        double z = 0;
        int dir = outside ? 1 : -1;
        c.append(String.format(Locale.ROOT, "N10 G00 X%.3f\nG01 Z0.\n", x));
        int steps = 3 + r.nextInt(5);
        for (int i = 0; i < steps; i++) {
            double dz = 1 + r.nextInt(12);
            double dx = 1 + r.nextInt(4);
            switch (r.nextInt(4)) {
                case 0 -> c.append(String.format(Locale.ROOT, "Z%.3f\n", z -= dz));
                case 1 -> c.append(String.format(Locale.ROOT, "X%.3f Z%.3f\n", x += dir * 2 * dx, z -= dz));
                case 2 -> {
                    double rad = 1 + r.nextInt(3);
                    boolean g2 = r.nextBoolean();
                    c.append(String.format(Locale.ROOT, "G0%d X%.3f Z%.3f R%.3f\nG01\n", g2 ? 2 : 3,
                            x += dir * 2 * rad, z -= rad, rad));
                }
                default -> c.append(String.format(Locale.ROOT, "X%.3f\nZ%.3f\n", x += dir * 2 * dx, z -= dz));
            }
        }
        double end = outside ? x + 2 : x - 2;
        c.append(String.format(Locale.ROOT, "N20 X%.3f\n", end));
        double start = outside ? end + 2 + 2 * r.nextInt(3) : Math.max(2, (outside ? 0 : Math.min(end, 4)) - 2);
        if (!outside) {
            start = Math.max(1, end - 2 - 2 * r.nextInt(2));
        }
        return String.format(Locale.ROOT, "G21 G99\nT0101\nG97 S800 M03\nG00 X%.3f Z2.\n"
                + "G71 U%.3f R%.3f\nG71 P10 Q20 U%.3f W%.3f F0.2\n%sG70 P10 Q20\nM30\n",
                start, 0.5 + r.nextInt(5) * 0.5, r.nextInt(4) * 0.25, u, w, c);
    }

    /** Points along a move, in program terms {X as a diameter, Z}. */
    private static void sample(Motion m, ProgramFrame f, List<double[]> out, int n) {
        if (m instanceof Motion.Linear l) {
            for (int i = 0; i <= n; i++) {
                double t = i / (double) n;
                out.add(program(new Point(l.from().x() + t * (l.to().x() - l.from().x()),
                        l.from().z() + t * (l.to().z() - l.from().z())), f));
            }
        } else if (m instanceof Motion.Arc a) {
            Point c = a.centre();
            double start = Math.atan2(a.from().x() - c.x(), a.from().z() - c.z());
            double sweep = Math.toRadians(ArcGeometry.sweepDegrees(a.from(), a.to(), c, a.clockwise()));
            for (int i = 0; i <= n; i++) {
                double t = start + sweep * i / n;
                out.add(program(new Point(c.x() + a.radius() * Math.sin(t), c.z() + a.radius() * Math.cos(t)), f));
            }
        }
    }

    private static double[] program(Point p, ProgramFrame f) {
        return new double[] {(p.x() - f.origin().x()) / f.perX(), (p.z() - f.origin().z()) / f.perZ()};
    }

    /** The G70's points without its approach and return, moved by the allowance. */
    private static List<double[]> shape(List<double[]> g70, double u, double w) {
        List<double[]> s = new ArrayList<>();
        // approach: the first move's samples (401 points); return: the last two moves' (802 points)
        for (int i = 401; i < g70.size() - 802; i++) {
            s.add(new double[] {g70.get(i)[0] + u, g70.get(i)[1] + w});
        }
        assertEquals(true, s.size() > 2);
        return s;
    }

    /**
     * The contour's X at z, the lowest (outside, s = 1) or highest (inside) within a hair of z, so
     * that a cut ending on a shoulder face is judged by the face's near end; NaN where the contour
     * has no point at that Z (before its start or past its end).
     */
    private static double boundary(List<double[]> shape, double z, int s) {
        double best = Double.NaN;
        for (double probe : new double[] {z - 1e-3, z, z + 1e-3}) {
            for (int i = 0; i + 1 < shape.size(); i++) {
                double[] a = shape.get(i);
                double[] b = shape.get(i + 1);
                if (probe < Math.min(a[1], b[1]) || probe > Math.max(a[1], b[1])) {
                    continue;
                }
                double x = a[1] == b[1] ? (s > 0 ? Math.min(a[0], b[0]) : Math.max(a[0], b[0]))
                        : a[0] + (probe - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if (Double.isNaN(best) || s * (best - x) > 0) {
                    best = x;
                }
            }
        }
        return best;
    }
}
