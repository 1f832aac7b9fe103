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
 * Random type I contours (steps, chamfers, quarter-round corners), outside and inside roughed by
 * G71 and faces roughed by G72, with random depth, retract and allowances: no point of any pass
 * (sampled along each move) is inside the contour moved by its allowance. The contour is taken from the G70 that follows
 * the same blocks, so the test does not share the expansion's geometry. Seeds print on failure.
 */
class CycleRoughingPropertyTest {
    private static final int PROGRAMS = 60;
    /** How far a pass may reach past the moved contour: rounding of six-decimal words, mm. */
    private static final double TOLERANCE = 0.002;

    @ParameterizedTest
    @ValueSource(ints = {1, -1})
    void g71PassesNeverCutBelowTheContourPlusItsAllowance(int side) throws Exception {
        boolean outside = side > 0;
        for (int seed = 1; seed <= PROGRAMS; seed++) {
            Random r = new Random(seed * 7919L + (outside ? 1 : 2));
            double u = r.nextInt(3) * 0.2 * (outside ? 1 : -1);
            double w = r.nextInt(3) * 0.05;
            String program = program(r, outside, u, w);
            check("G71", "seed " + seed + (outside ? " outside" : " inside") + "\n" + program, program, u, w, false,
                    side);
        }
    }

    @org.junit.jupiter.api.Test
    void g72PassesNeverCutBelowTheContourPlusItsAllowance() throws Exception {
        for (int seed = 1; seed <= PROGRAMS; seed++) {
            Random r = new Random(seed * 104729L);
            double u = r.nextInt(3) * 0.2;
            double w = r.nextInt(3) * 0.05;
            String program = facing(r, u, w);
            check("G72", "seed " + seed + " facing\n" + program, program, u, w, true, 1);
        }
    }

    /**
     * Expands the program and checks every point of the cycle's passes against the contour of the
     * G70 over the same blocks moved by (u, w): on the start's side of it along the depth axis
     * (X for G71, Z for G72: {@code facing}), {@code s} the side the start is on.
     */
    private static void check(String cycle, String where, String program, double u, double w, boolean facing, int s)
            throws Exception {
        CycleExpansionTest.Expanded e = CycleExpansionTest.expand("fanuc", new StringReader(program));
        assertTrue(e.diagnostics().sorted().stream().noneMatch(d -> d.severity() == gcnc.diag.Severity.ERROR),
                () -> where + e.diagnostics().sorted());
        List<double[]> contour = new ArrayList<>();
        List<CheckedBlock> passes = new ArrayList<>();
        ProgramFrame frame = null;
        for (CheckedBlock b : e.blocks()) {
            String seq = b.frame().sequence();
            if (seq.contains(cycle + " pass")) {
                passes.add(b);
                frame = b.frame();
            } else if (seq.contains("G70 pass") && !b.motions().isEmpty()) {
                for (Motion m : b.motions()) {
                    sample(m, b.frame(), contour, 400);
                }
            }
        }
        assertTrue(passes.size() > 4 && contour.size() > 10, where);
        // the G70's first move is the approach and its last two are the return: the shape is between
        List<double[]> shape = shape(contour, u, w, facing);
        ContourBins bins = new ContourBins(shape, 1);
        for (CheckedBlock b : passes) {
            for (Motion m : b.motions()) {
                List<double[]> pts = new ArrayList<>();
                sample(m, frame, pts, 60);
                for (double[] xz : pts) {
                    double[] p = facing ? new double[] {xz[1], xz[0]} : xz;
                    double limit = boundary(shape, bins, p[1], s);
                    if (!Double.isNaN(limit)) {
                        assertTrue(s * (p[0] - limit) >= -TOLERANCE, () -> String.format(Locale.ROOT,
                                "%s%s at X%.4f Z%.4f is inside the contour (%s%.4f there)", where,
                                b.frame().sequence(), xz[0], xz[1], facing ? "Z" : "X", limit));
                    }
                }
            }
        }
    }

    /** A start point, a G72 first block, the second, a random facing contour N10..N20, a G70. */
    private static String facing(Random r, double u, double w) {
        StringBuilder c = new StringBuilder();
        double x = 40 + 2 * r.nextInt(10);
        double z = -(8 + r.nextInt(10));
        c.append(String.format(Locale.ROOT, "N10 G00 Z%.3f\nG01 X%.3f\n", z, x - 2));
        x -= 2;
        int steps = 2 + r.nextInt(4);
        for (int i = 0; i < steps && z < -2; i++) {
            double dx = 2 + 2 * r.nextInt(4);
            double dz = Math.min(-z - 1, 1 + r.nextInt(3));
            switch (r.nextInt(4)) {
                case 0 -> c.append(String.format(Locale.ROOT, "X%.3f\n", x -= dx));
                case 1 -> c.append(String.format(Locale.ROOT, "X%.3f Z%.3f\n", x -= dx, z += dz));
                case 2 -> {
                    double rad = Math.min(dz, 1 + r.nextInt(2));
                    c.append(String.format(Locale.ROOT, "G0%d X%.3f Z%.3f R%.3f\nG01\n", r.nextBoolean() ? 2 : 3,
                            x -= 2 * rad, z += rad, rad));
                }
                default -> c.append(String.format(Locale.ROOT, "Z%.3f\nX%.3f\n", z += dz, x -= dx));
            }
        }
        c.append(String.format(Locale.ROOT, "Z0.\nN20 X%.3f\n", Math.max(0, x - 10)));
        return String.format(Locale.ROOT, "G21 G99\nT0101\nG97 S800 M03\nG00 X%.3f Z2.\n"
                + "G72 W%.3f R%.3f\nG72 P10 Q20 U%.3f W%.3f F0.2\n%sG70 P10 Q20\nM30\n",
                x + 40, 0.5 + r.nextInt(4) * 0.5, r.nextInt(4) * 0.25, u, w, c);
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
    static void sample(Motion m, ProgramFrame f, List<double[]> out, int n) {
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

    /**
     * The G70's points without its approach and return, moved by the allowance, as {depth, cut}
     * ({X, Z}, or {Z, X} when {@code facing}).
     */
    static List<double[]> shape(List<double[]> g70, double u, double w, boolean facing) {
        List<double[]> s = new ArrayList<>();
        // approach: the first move's samples (401 points); return: the last two moves' (802 points)
        for (int i = 401; i < g70.size() - 802; i++) {
            double x = g70.get(i)[0] + u;
            double z = g70.get(i)[1] + w;
            s.add(facing ? new double[] {z, x} : new double[] {x, z});
        }
        assertEquals(true, s.size() > 2);
        return s;
    }

    /**
     * The contour's depth coordinate at cut coordinate z (X at Z for G71), the lowest (s = 1) or
     * highest within a hair of z, so that a cut ending on a shoulder face is judged by the face's
     * near end; NaN where the contour has no point there (before its start or past its end).
     */
    private static double boundary(List<double[]> shape, ContourBins bins, double z, int s) {
        double best = Double.NaN;
        for (double probe : new double[] {z - 1e-3, z, z + 1e-3}) {
            for (int i : bins.near(probe, 1e-6)) {
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
