package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Severity;
import gcnc.galil.Dialect;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.ProgramFrame;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.TreeMap;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Random G71 type II contours on the haas machine (inch, one-block form), outside and inside: Z
 * always toward the chuck, X going in and out (pockets with sloped walls, steps, quarter rounds),
 * random depth of cut and X allowance. For each: no point of a roughing pass is inside the part,
 * beyond the contour moved by its allowance (within a micron and the rounding of six-decimal
 * words); each level's cuts cover exactly the Z stretches where the moved contour lies beyond the
 * level; and an outside program (cycle and G70) compiles and replays in the simulator over the
 * machine's 2 in bar without a finding (the shipped blanks have no bore for the inside ones). The
 * contour is taken from the G70 over the same blocks, not from the expansion. X is judged as
 * {@code side * X}, so that "in" is down on both sides. Seeds print on failure.
 */
class TypeTwoPropertyTest {
    /**
     * Programs per side: 60 in the default run (20 while the contour was scanned whole for every
     * sampled point; ContourBins made that cheap); a campaign sets more (-PtypeTwoCount=500).
     */
    private static final int PROGRAMS = Integer.getInteger("gcnc.typeTwo.count", 60);
    /** Inch: a micron plus the six-decimal rounding of the written words. */
    private static final double TOLERANCE = 0.001 / 25.4 + 2e-6;

    @ParameterizedTest
    @ValueSource(ints = {1, -1})
    void typeTwoPassesStayOutOfThePartCoverEveryLevelAndSimulateClean(int side) throws Exception {
        for (int seed = 1; seed <= PROGRAMS; seed++) {
            Random r = new Random(seed * 6151L + side);
            double u = side * r.nextInt(3) * 0.01;
            String program = program(r, u, side);
            String where = "seed " + seed + "\n" + program;
            CycleExpansionTest.Expanded e = CycleExpansionTest.expand("haas", new StringReader(program));
            assertTrue(e.diagnostics().sorted().stream().noneMatch(d -> d.severity() == Severity.ERROR),
                    () -> where + e.diagnostics().sorted());
            List<double[]> g70 = new ArrayList<>();
            List<CheckedBlock> passes = new ArrayList<>();
            String last = null;
            for (CheckedBlock b : e.blocks()) {
                String seq = b.frame().sequence();
                if (seq.contains("G71 pass")) {
                    passes.add(b);
                    last = seq.substring(seq.indexOf("G71 pass"));
                } else if (seq.contains("G70 pass")) {
                    for (Motion m : b.motions()) {
                        CycleRoughingPropertyTest.sample(m, b.frame(), g70, 400);
                    }
                }
            }
            List<double[]> shape = new ArrayList<>();
            for (double[] p : CycleRoughingPropertyTest.shape(g70, u, 0, false)) {
                shape.add(new double[] {side * p[0], p[1]});
            }
            ContourBins bins = new ContourBins(shape, 1);
            Map<Double, List<double[]>> levels = new TreeMap<>();
            for (CheckedBlock b : passes) {
                boolean finishing = b.frame().sequence().endsWith(last);
                for (Motion m : b.motions()) {
                    List<double[]> pts = new ArrayList<>();
                    CycleRoughingPropertyTest.sample(m, b.frame(), pts, 60);
                    for (double[] xz : pts) {
                        xz[0] *= side;
                        double floor = bottom(shape, bins, xz[1]);
                        assertTrue(Double.isNaN(floor) || xz[0] >= floor - TOLERANCE, () -> String.format(Locale.ROOT,
                                "%s%s at X%.5f Z%.5f is below the contour (X%.5f there)", where,
                                b.frame().sequence(), xz[0], xz[1], floor));
                    }
                    if (!finishing && m instanceof Motion.Linear l && !l.rapid()) {
                        double[] a = pts.get(0);
                        double[] z = pts.get(pts.size() - 1);
                        if (Math.abs(a[0] - z[0]) < 1e-7 && Math.abs(a[1] - z[1]) > 1e-7) {
                            levels.computeIfAbsent(Math.rint(a[0] * 1e5) / 1e5, k -> new ArrayList<>())
                                    .add(new double[] {Math.min(a[1], z[1]), Math.max(a[1], z[1])});
                        }
                    }
                }
            }
            assertTrue(!levels.isEmpty(), where);
            for (Map.Entry<Double, List<double[]>> level : levels.entrySet()) {
                covers(where, shape, bins, level.getKey(), level.getValue());
            }
            if (side > 0) {
                assertEquals("", simulated(program), where);
            }
        }
    }

    /**
     * Along the contour's Z, a point is cut at this level exactly where the moved contour lies
     * below it (points within a hair of where the contour crosses the level, or of a wall, are not judged).
     */
    private static void covers(String where, List<double[]> shape, ContourBins bins, double level, List<double[]> cuts) {
        double zTop = shape.get(0)[1];
        double zEnd = shape.get(shape.size() - 1)[1];
        for (double z = zTop; z >= zEnd; z -= 0.002) {
            double here = top(shape, bins, z, 0);
            double before = top(shape, bins, z, 0.004);
            double after = top(shape, bins, z, -0.004);
            double margin = 0.0005;
            boolean below = here < level - margin && before < level - margin && after < level - margin;
            boolean above = here > level + margin && before > level + margin && after > level + margin;
            if (!below && !above || nearWall(shape, bins, z)) {
                continue;
            }
            boolean cut = false;
            for (double[] c : cuts) {
                cut |= z >= c[0] - 1e-6 && z <= c[1] + 1e-6;
            }
            double zz = z;
            assertEquals(below, cut, () -> String.format(Locale.ROOT, "%slevel X%.5f at Z%.4f: contour X%.5f, %s",
                    where, level, zz, here, below ? "not cut" : "cut"));
        }
    }

    /** Whether a wall (a move along X only) stands within 0.005 of z: a cut may end on it either side. */
    private static boolean nearWall(List<double[]> shape, ContourBins bins, double z) {
        for (int i : bins.near(z, 0.005)) {
            double[] a = shape.get(i);
            double[] b = shape.get(i + 1);
            if (Math.abs(a[1] - b[1]) < 1e-12 && Math.abs(a[0] - b[0]) > 1e-9 && Math.abs(a[1] - z) < 0.005) {
                return true;
            }
        }
        return false;
    }

    /** The lowest X of the contour at z (on a wall a point is on the part's face, not in it); NaN where it has none. */
    private static double bottom(List<double[]> shape, ContourBins bins, double z) {
        return -extreme(shape, bins, z, -1);
    }

    /** The highest X of the contour at z + dz (walls count by their top); NaN where it has none. */
    private static double top(List<double[]> shape, ContourBins bins, double z, double dz) {
        return extreme(shape, bins, z + dz, 1);
    }

    /** s = 1: the highest X at z; s = -1: minus the lowest. */
    private static double extreme(List<double[]> shape, ContourBins bins, double probe, int s) {
        double best = Double.NaN;
        for (int i : bins.near(probe, 1e-6)) {
            double[] a = shape.get(i);
            double[] b = shape.get(i + 1);
            if (probe < Math.min(a[1], b[1]) - 1e-9 || probe > Math.max(a[1], b[1]) + 1e-9) {
                continue;
            }
            double x = s * (Math.abs(a[1] - b[1]) < 1e-12 ? (s > 0 ? Math.max(a[0], b[0]) : Math.min(a[0], b[0]))
                    : a[0] + (probe - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
            if (Double.isNaN(best) || x > best) {
                best = x;
            }
        }
        return best;
    }

    /**
     * Outside: at X2.1 Z0.1 before the 2 in bar's face, a type II contour (X and Z in its first
     * block) from X1.0-1.8 at the face; inside: at X0.4, from X0.7-1.5. Then 4 to 8 moves down Z
     * between X0.6 and X1.9: straight or sloped into and out of pockets (a slope at least as long
     * in Z as it is deep), steps, quarter rounds; out past the start's X at the end; G70.
     */
    private static String program(Random r, double u, int side) {
        StringBuilder c = new StringBuilder();
        double x = (side > 0 ? 1.0 : 0.7) + r.nextInt(9) * 0.1;
        double z = 0;
        c.append(String.format(Locale.ROOT, "N10 G00 X%.4f Z0.1\nG01 Z0. F0.005\n", x));
        int moves = 4 + r.nextInt(5);
        for (int i = 0; i < moves; i++) {
            double nx = 0.6 + r.nextInt(14) * 0.1;
            double depth = Math.abs(nx - x) / 2;
            switch (r.nextInt(4)) {
                case 0 -> c.append(String.format(Locale.ROOT, "Z%.4f\n", z -= 0.1 + r.nextInt(4) * 0.1));
                case 1 -> {
                    double dz = depth + 0.05 + r.nextInt(3) * 0.1;
                    c.append(String.format(Locale.ROOT, "X%.4f Z%.4f\n", x = nx, z -= dz));
                }
                case 2 -> {
                    double rad = 0.05 + r.nextInt(3) * 0.05;
                    double to = x + (r.nextBoolean() ? 2 : -2) * rad;
                    if (to < 0.6 || to > 1.9) {
                        to = x + 2 * rad * (to < 0.6 ? 1 : -1);
                    }
                    c.append(String.format(Locale.ROOT, "G0%d X%.4f Z%.4f R%.4f\nG01\n", r.nextBoolean() ? 2 : 3,
                            x = to, z -= rad, rad));
                }
                default -> c.append(String.format(Locale.ROOT, "X%.4f\nZ%.4f\n", x = nx, z -= 0.1 + r.nextInt(3) * 0.1));
            }
        }
        c.append(side > 0 ? "N20 X2.2\n" : "N20 X0.3\n");
        return String.format(Locale.ROOT, "G20 G18 G40 G99\nT0101\nG50 S2000\nG97 S600 M03\nG00 X%s Z0.1\n"
                + "G71 P10 Q20 U%.3f D%.3f F0.01\n%sG70 P10 Q20\nG00 X3. Z1.\nM30\n", side > 0 ? "2.1" : "0.4", u,
                0.02 + r.nextInt(4) * 0.02, c);
    }

    /** Compiles and simulates on the haas machine (its 2 in bar); the findings by code. */
    private static String simulated(String program) throws Exception {
        gcnc.Compiler.Settings settings = new gcnc.Compiler.Settings(Run.TABLES, Run.profile("haas"), Dialect.Kind.GALIL,
                java.util.Optional.of(gcnc.sim.SimOptions.defaults()), true);
        gcnc.Compiler.Result r = gcnc.Compiler.compile(new StringReader(program), settings, l -> { });
        java.util.Set<String> codes = new java.util.TreeSet<>();
        r.diagnostics().sorted().forEach(d -> codes.add(d.code().id() + "@" + d.span().line() + " " + d.args()));
        return String.join("\n", codes);
    }
}
