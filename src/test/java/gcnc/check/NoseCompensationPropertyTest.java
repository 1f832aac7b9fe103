package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import gcnc.machine.Nose;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Random monotone outside contours (lines in any direction between -Z and +X, convex arcs and
 * concave arcs no tighter than the nose), compensated with G42 by the fanuc machine's T0101
 * (R0.8, tip 3). The test's own geometry, not the compensation's: every point of the nose centre's
 * path (the tip moved back by the tip direction) is at least the radius from every element of the
 * programmed contour, and the offset part of each contour block is at exactly the radius from its
 * own element, within a micron; a G70 over the same blocks makes the same path within a micron.
 * The programmed contour is the same program checked with G40. Seeds print on failure.
 */
class NoseCompensationPropertyTest {
    private static final int PROGRAMS = 80;
    private static final MachineProfile FANUC = Run.profile("fanuc");
    private static final double PER_MM = FANUC.x().countsPerMm();
    private static final double MICRON = 0.001 * PER_MM;
    private static final Nose NOSE = FANUC.nose(1);
    private static final double R = NOSE.radius();

    /** A generated contour: the program text of its blocks, the lines they are on, the start point. */
    record Contour(List<String> blocks, double startX, double endX) {
    }

    @Test
    void theNoseCentreKeepsTheRadiusFromTheContourAndFollowsEachElementAtExactlyTheRadius() {
        for (int seed = 1; seed <= PROGRAMS; seed++) {
            Random rnd = new Random(seed * 6151L);
            Contour c = contour(rnd);
            String head = "G21 G18 G40 G99\nT0101\nG97 S500 M03\n" + String.format(Locale.ROOT, "G00 X%.6f Z5.\n",
                    2 * c.endX() + 20);
            String compensated = head + String.format(Locale.ROOT, "G42 G00 X%.6f Z2.\n", 2 * c.startX())
                    + String.join("\n", c.blocks()) + String.format(Locale.ROOT, "\nG40 G00 X%.6f Z5.\nM30\n", 2 * c.endX() + 20);
            String where = "seed " + seed + "\n" + compensated;
            Run comp = Run.of("fanuc", compensated);
            Run plain = Run.of("fanuc", compensated.replace("G42 ", ""));
            assertEquals("", NoseCompensationTest.errs(comp), where);
            assertEquals("", NoseCompensationTest.errs(plain), where);
            int first = 6;
            int last = first + c.blocks().size() - 1;
            List<Motion> contour = new ArrayList<>();
            Map<Integer, Motion> programmed = new HashMap<>();
            for (CheckedBlock b : plain.blocks) {
                if (b.line() >= first && b.line() <= last) {
                    contour.add(b.motions().get(0));
                    programmed.put(b.line(), b.motions().get(0));
                }
            }
            assertEquals(c.blocks().size(), contour.size(), where);
            for (CheckedBlock b : comp.blocks) {
                if (b.line() < first || b.line() > last) {
                    continue;
                }
                for (Motion m : b.motions()) {
                    for (Point tip : samples(m)) {
                        Point centre = centre(tip);
                        double d = Double.POSITIVE_INFINITY;
                        for (Motion e : contour) {
                            d = Math.min(d, distance(centre, e));
                        }
                        assertTrue(d >= R - MICRON, where + "\nline " + b.line() + ": the nose centre comes "
                                + (R - d) / PER_MM + " mm inside the radius");
                    }
                }
                Motion own = b.motions().get(0);
                Motion element = programmed.get(b.line());
                assertEquals(element instanceof Motion.Arc, own instanceof Motion.Arc, where + "\nline " + b.line());
                for (Point tip : samples(own)) {
                    double d = distance(centre(tip), element);
                    assertEquals(R, d, MICRON, where + "\nline " + b.line() + ": the offset element is " + d / PER_MM
                            + " mm from its own element");
                }
            }
        }
    }

    @Test
    void aG70FinishMakesTheCompensatedPathOfItsContourWithinAMicron() {
        for (int seed = 1; seed <= PROGRAMS / 2; seed++) {
            Random rnd = new Random(seed * 92821L);
            Contour c = contour(rnd);
            double start = 2 * c.endX() + 4;
            String head = "G21 G18 G40 G99\nT0101\nG97 S500 M03\n" + String.format(Locale.ROOT, "G00 X%.6f Z2.\n", start);
            List<String> blocks = new ArrayList<>();
            blocks.add(String.format(Locale.ROOT, "N10 G42 G00 X%.6f", 2 * c.startX()));
            blocks.add("G01 Z0. F0.1");
            blocks.addAll(c.blocks().subList(1, c.blocks().size()));
            blocks.add(String.format(Locale.ROOT, "N20 G40 G01 X%.6f", start));
            String contour = String.join("\n", blocks) + "\n";
            String cycle = head + "G71 U1. R0.5\nG71 P10 Q20 U0. W0. F0.2\n" + contour + "G70 P10 Q20\nM30\n";
            String plain = head + contour + "M30\n";
            Run g70 = Run.of("fanuc", cycle);
            Run direct = Run.of("fanuc", plain);
            String where = "seed " + seed + "\n" + cycle;
            assertEquals("", NoseCompensationTest.errs(g70), where);
            assertEquals("", NoseCompensationTest.errs(direct), where);
            List<Motion> finish = new ArrayList<>();
            for (CheckedBlock b : g70.blocks) {
                if (b.frame() != null && b.frame().sequence().contains("G70") && b.line() >= 7 && b.line() < 7 + blocks.size()) {
                    finish.addAll(b.motions());
                }
            }
            List<Motion> path = new ArrayList<>();
            for (CheckedBlock b : direct.blocks) {
                if (b.line() >= 5 && b.line() < 5 + blocks.size()) {
                    path.addAll(b.motions());
                }
            }
            assertEquals(path.size(), finish.size(), where);
            for (int i = 0; i < path.size(); i++) {
                assertTrue(end(path.get(i)).distanceTo(end(finish.get(i))) <= MICRON, where + "\nmove " + i);
                assertTrue(start(path.get(i)).distanceTo(start(finish.get(i))) <= MICRON, where + "\nmove " + i);
            }
        }
    }

    /**
     * Random programs of moves, arcs, blocks without a move and G41/G42/G40 anywhere, errors or not:
     * the checker never throws, every position it sends is a number, and the path it sends is
     * continuous (each move starts where the one before ended), compensated or not.
     */
    @Test
    void anyMixOfMovesAndCompensationGivesAContinuousPath() {
        for (int seed = 1; seed <= 300; seed++) {
            Random rnd = new Random(seed * 31337L);
            StringBuilder p = new StringBuilder("G21 G18 G40 G99\nT0101\nG97 S500 M03\nG00 X60. Z5.\n");
            int n = 5 + rnd.nextInt(25);
            for (int i = 0; i < n; i++) {
                String side = switch (rnd.nextInt(8)) {
                    case 0 -> "G41 ";
                    case 1 -> "G42 ";
                    case 2 -> "G40 ";
                    default -> "";
                };
                double x = 10 + rnd.nextInt(400) / 10.0;
                double z = 3 - rnd.nextInt(400) / 10.0;
                p.append(side).append(switch (rnd.nextInt(7)) {
                    case 0 -> String.format(Locale.ROOT, "G00 X%.1f Z%.1f", x, z);
                    case 1 -> String.format(Locale.ROOT, "G02 X%.1f Z%.1f R%.1f F0.1", x, z, 1 + rnd.nextInt(300) / 10.0);
                    case 2 -> String.format(Locale.ROOT, "G03 X%.1f Z%.1f R%.1f F0.1", x, z, 1 + rnd.nextInt(300) / 10.0);
                    case 3 -> rnd.nextInt(6) == 0 ? "M08\n".repeat(NoseCompensation.STILL_LIMIT + 2) + "M09"
                            : rnd.nextBoolean() ? "M08" : "G04 P100";
                    case 4 -> String.format(Locale.ROOT, "G01 X%.1f F0.1", x);
                    default -> String.format(Locale.ROOT, "G01 X%.1f Z%.1f F0.1", x, z);
                }).append('\n');
            }
            p.append("G40 G00 X80. Z10.\nM30\n");
            String where = "seed " + seed + "\n" + p;
            Run r = Run.of("fanuc", p.toString());
            // a block rejected only for its move (an arc whose R cannot span it) leaves the tool at its
            // end point, as the control would after the operator fixed it (issue 17): the path goes on
            // from there, so continuity is asked for between the blocks on either side of none
            java.util.BitSet rejected = new java.util.BitSet();
            r.diagnostics.sorted().stream().filter(d -> d.severity() == gcnc.diag.Severity.ERROR)
                    .forEach(d -> rejected.set(d.span().line()));
            Point at = null;
            int last = 0;
            for (CheckedBlock b : r.blocks) {
                int next = rejected.nextSetBit(last + 1);
                if (next >= 0 && next < b.line()) {
                    at = null;
                }
                last = Math.max(last, b.line());
                for (Motion m : b.motions()) {
                    if (m instanceof Motion.Dwell) {
                        continue;
                    }
                    Point f = start(m);
                    Point t = end(m);
                    assertTrue(Double.isFinite(f.x()) && Double.isFinite(f.z()) && Double.isFinite(t.x())
                            && Double.isFinite(t.z()), where + "\nline " + b.line() + ": " + m);
                    if (at != null) {
                        assertTrue(at.distanceTo(f) < 1e-6, where + "\nline " + b.line() + " starts " + f + ", not at " + at);
                    }
                    at = t;
                }
            }
        }
    }

    /**
     * A monotone outside contour from (x0, Z2) toward the chuck: the first block down to Z0, then
     * 4 to 8 elements, each long enough for the nose, ending with a step out along +X.
     */
    static Contour contour(Random rnd) {
        double x0 = 5 + rnd.nextInt(50) / 10.0;
        List<String> blocks = new ArrayList<>();
        blocks.add("G01 Z0. F0.1");
        double x = x0;
        double z = 0;
        int n = 4 + rnd.nextInt(5);
        for (int i = 0; i < n; i++) {
            if (rnd.nextInt(3) < 2) {
                double a = Math.toRadians(switch (rnd.nextInt(4)) {
                    case 0 -> 90;
                    case 1 -> 180;
                    default -> 100 + rnd.nextInt(71);
                });
                double len = 3 + rnd.nextInt(50) / 10.0;
                x += len * Math.sin(a);
                z += len * Math.cos(a);
                blocks.add(String.format(Locale.ROOT, "G01 X%.6f Z%.6f", 2 * x, z));
            } else {
                double a0 = Math.toRadians(90 + rnd.nextInt(91));
                double a1;
                do {
                    a1 = Math.toRadians(90 + rnd.nextInt(91));
                } while (Math.abs(a1 - a0) < Math.toRadians(40));
                boolean cw = a1 < a0; // turning right: concave under G42
                double radius = 4 + rnd.nextInt(40) / 10.0;
                double[] r0 = {-Math.cos(a0), Math.sin(a0)}; // right of the tangent (sin a, cos a) as {x, z}
                double[] r1 = {-Math.cos(a1), Math.sin(a1)};
                double cx;
                double cz;
                double ex;
                double ez;
                if (cw) {
                    cx = x + radius * r0[0];
                    cz = z + radius * r0[1];
                    ex = cx - radius * r1[0];
                    ez = cz - radius * r1[1];
                } else {
                    cx = x - radius * r0[0];
                    cz = z - radius * r0[1];
                    ex = cx + radius * r1[0];
                    ez = cz + radius * r1[1];
                }
                x = ex;
                z = ez;
                blocks.add(String.format(Locale.ROOT, "%s X%.6f Z%.6f R%.6f", cw ? "G02" : "G03", 2 * x, z, radius));
            }
        }
        blocks.add(String.format(Locale.ROOT, "G01 X%.6f", 2 * (x + 3)));
        return new Contour(blocks, x0, x + 3);
    }

    private static Point centre(Point tip) {
        double[] v = NOSE.tipVector();
        return new Point(tip.x() - v[0] * R, tip.z() - v[1] * R);
    }

    private static Point start(Motion m) {
        return m instanceof Motion.Arc a ? a.from() : ((Motion.Linear) m).from();
    }

    private static Point end(Motion m) {
        return m instanceof Motion.Arc a ? a.to() : ((Motion.Linear) m).to();
    }

    /** 21 points along a move, its ends included. */
    static List<Point> samples(Motion m) {
        List<Point> out = new ArrayList<>();
        if (m instanceof Motion.Arc a) {
            double a0 = Math.atan2(a.from().x() - a.centre().x(), a.from().z() - a.centre().z());
            double sweep = sweep(a);
            for (int i = 0; i <= 20; i++) {
                double t = a0 + (a.clockwise() ? -1 : 1) * sweep * i / 20;
                out.add(new Point(a.centre().x() + a.radius() * Math.sin(t), a.centre().z() + a.radius() * Math.cos(t)));
            }
        } else {
            Point f = start(m);
            Point t = end(m);
            for (int i = 0; i <= 20; i++) {
                out.add(new Point(f.x() + (t.x() - f.x()) * i / 20, f.z() + (t.z() - f.z()) * i / 20));
            }
        }
        return out;
    }

    /** The arc's sweep in radians, in its direction, (0, 2 pi]. */
    private static double sweep(Motion.Arc a) {
        double a0 = Math.atan2(a.from().x() - a.centre().x(), a.from().z() - a.centre().z());
        double a1 = Math.atan2(a.to().x() - a.centre().x(), a.to().z() - a.centre().z());
        double s = a.clockwise() ? a0 - a1 : a1 - a0;
        while (s <= 0) {
            s += 2 * Math.PI;
        }
        return s;
    }

    /** The distance from {@code p} to a line segment or an arc of the contour. */
    static double distance(Point p, Motion m) {
        if (m instanceof Motion.Arc a) {
            double ang = Math.atan2(p.x() - a.centre().x(), p.z() - a.centre().z());
            double a0 = Math.atan2(a.from().x() - a.centre().x(), a.from().z() - a.centre().z());
            double along = a.clockwise() ? a0 - ang : ang - a0;
            while (along < 0) {
                along += 2 * Math.PI;
            }
            while (along >= 2 * Math.PI) {
                along -= 2 * Math.PI;
            }
            if (along <= sweep(a)) {
                return Math.abs(p.distanceTo(a.centre()) - a.radius());
            }
            return Math.min(p.distanceTo(a.from()), p.distanceTo(a.to()));
        }
        Point f = start(m);
        Point t = end(m);
        double dx = t.x() - f.x();
        double dz = t.z() - f.z();
        double len2 = dx * dx + dz * dz;
        double u = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((p.x() - f.x()) * dx + (p.z() - f.z()) * dz) / len2));
        return p.distanceTo(new Point(f.x() + u * dx, f.z() + u * dz));
    }
}
