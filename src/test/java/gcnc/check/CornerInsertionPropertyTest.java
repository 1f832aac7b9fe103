package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.ProgramFrame;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Property (docs/chamfer.md): on random G01 contours with random Haas chamfers and corner roundings,
 * the path the checker hands on is continuous; what is left of each programmed move lies on it;
 * each inserted element starts and ends the same distance from its corner on the two moves (the
 * chamfer's ,C, or r tan(phi/2) for an arc of radius r, which then touches both moves); and the
 * contour ends where the program ends it.
 */
class CornerInsertionPropertyTest {
    private static final double EPS = 1e-5; // mm: the words are written with six decimals, the arcs centred from them

    /** A programmed point, X a diameter as written, and what the block asks for at its end. */
    private record Step(double x, double z, String corner, double size) {
    }

    @Test
    void chamfersAndRoundsKeepThePathContinuousAndTheRestOfEachMoveOnIt() {
        int clean = 0;
        for (long seed = 1; seed <= 300; seed++) {
            Random rnd = new Random(seed);
            List<Step> steps = contour(rnd);
            StringBuilder p = new StringBuilder("G01 Z0. F0.1\n");
            for (Step s : steps) {
                p.append(String.format(Locale.ROOT, "X%.3f Z%.3f", s.x, s.z));
                if (s.corner != null) {
                    p.append(String.format(Locale.ROOT, " %s%.3f", s.corner, s.size));
                }
                p.append('\n');
            }
            p.append("M30\n");
            CycleExpansionTest.Expanded e = CornerInsertionTest.run("haas", p.toString());
            String errs = CornerInsertionTest.errs(e);
            if (!errs.isEmpty()) {
                assertTrue(errs.matches("(E61[13]@[0-9:]+)(, E61[13]@[0-9:]+)*"), "seed " + seed + ": " + errs + "\n" + p);
                continue; // a corner that does not fit: reported, as the control alarms
            }
            clean++;
            check(seed, steps, e, p.toString());
        }
        assertTrue(clean >= 150, "too few clean contours to judge: " + clean);
    }

    /**
     * The same random contours as a G71's contour (haas): the G70 follows exactly the path the
     * contour makes in the program's flow, and no rough pass ends below it.
     */
    @Test
    void inAG71ContourTheCornersAreTheFlowsAndNoRoughPassCutsBelowThem() {
        int clean = 0;
        for (long seed = 1; seed <= 120; seed++) {
            List<Step> steps = contour(new Random(seed));
            StringBuilder shape = new StringBuilder();
            double top = 20;
            for (Step s : steps) {
                shape.append(String.format(Locale.ROOT, "X%.3f Z%.3f", s.x, s.z));
                if (s.corner != null) {
                    shape.append(String.format(Locale.ROOT, " %s%.3f", s.corner, s.size));
                }
                shape.append('\n');
                top = Math.max(top, s.x);
            }
            String out = String.format(Locale.ROOT, "X%.3f", top + 4);
            // lines 5-7 the cycle, 8 N10, 9 G01 Z0., then the shape; the flow version has the same lines
            String cycle = "G00 " + out + " Z2.\nG71 P10 Q20 U0.5 W0.1 D1. F0.2\nG00 X20. Z2.\nN10 G00 X20.\nG01 Z0.\n"
                    + shape + "N20 " + out + "\nG70 P10 Q20\nM30\n";
            String flow = "G00 " + out + " Z2.\nG00 X20. Z2.\nG00 X20. Z2.\nN10 G00 X20.\nG01 Z0. F0.2\n"
                    + shape + "N20 " + out + "\nM30\n";
            CycleExpansionTest.Expanded c = CornerInsertionTest.run("haas", cycle);
            CycleExpansionTest.Expanded f = CornerInsertionTest.run("haas", flow);
            String errs = CornerInsertionTest.errs(c);
            assertEquals(CornerInsertionTest.errs(f), errs, "seed " + seed + ": the same corners refused\n" + cycle);
            if (!errs.isEmpty()) {
                assertTrue(errs.matches("(E61[13]@[0-9:]+)(, E61[13]@[0-9:]+)*"), "seed " + seed + ": " + errs + "\n" + cycle);
            }
            clean += errs.isEmpty() ? 1 : 0;
            int g70 = 11 + steps.size();
            List<String> finish = new ArrayList<>();
            List<String> rough = new ArrayList<>();
            for (String m : CornerInsertionTest.moves(c, 5)) {
                int line = Integer.parseInt(m.substring(0, m.indexOf(' ')));
                if (line == 6 && m.contains(" G01 ")) {
                    rough.add(m);
                } else if (line > 7 && line < g70) {
                    finish.add(m);
                }
            }
            List<String> same = new ArrayList<>();
            for (String m : CornerInsertionTest.moves(f, 8)) {
                same.add(m);
            }
            assertEquals(same, finish, "seed " + seed + ": the G70 follows the contour as the flow makes it\n" + cycle);
            List<double[]> path = CornerInsertionTest.path(finish);
            for (String m : rough) {
                String[] w = m.split(" ");
                double x = Double.parseDouble(w[2].substring(1));
                double z = Double.parseDouble(w[3].substring(1));
                double floor = CornerInsertionTest.lowest(path, z);
                assertTrue(x >= floor - 1e-3, "seed " + seed + ": a rough cut at X" + x + " Z" + z + " is below X" + floor + "\n" + cycle);
            }
        }
        assertTrue(clean >= 60, "too few clean contours to judge: " + clean);
    }

    /** Three to six moves from X20 Z0, each along X or Z or a taper, going left and out (a turned profile). */
    private static List<Step> contour(Random rnd) {
        List<Step> steps = new ArrayList<>();
        double x = 20;
        double z = 0;
        int n = 3 + rnd.nextInt(4);
        int last = -1;
        for (int i = 0; i < n; i++) {
            int kind;
            do {
                kind = rnd.nextInt(3); // 0 along X, 1 along Z, 2 a taper
            } while (kind == last && kind != 2);
            last = kind;
            double dx = kind == 1 ? 0 : 2 + rnd.nextInt(80) / 10.0;
            double dz = kind == 0 ? 0 : -(1 + rnd.nextInt(100) / 10.0);
            x += dx;
            z += dz;
            String corner = i < n - 1 && rnd.nextInt(3) > 0 ? (rnd.nextBoolean() ? ",C" : ",R") : null;
            steps.add(new Step(x, z, corner, 0.2 + rnd.nextInt(30) / 10.0));
        }
        return steps;
    }

    private static void check(long seed, List<Step> steps, CycleExpansionTest.Expanded e, String program) {
        String where = "seed " + seed + "\n" + program;
        // the programmed points, radius terms; the first is where line 5 leaves the tool
        List<Point> pts = new ArrayList<>();
        pts.add(new Point(10, 0));
        for (Step s : steps) {
            pts.add(new Point(s.x / 2, s.z));
        }
        Point at = null;
        List<List<Motion>> byMove = new ArrayList<>();
        List<ProgramFrame> frames = new ArrayList<>();
        for (CheckedBlock b : e.blocks()) {
            if (b.line() < 6 || b.motions().isEmpty()) {
                continue;
            }
            int i = b.line() - 6; // the block of move i (from pts[i] to pts[i + 1])
            while (byMove.size() <= i) {
                byMove.add(new ArrayList<>());
                frames.add(b.frame());
            }
            for (Motion m : b.motions()) {
                Point from = m instanceof Motion.Linear l ? l.from() : ((Motion.Arc) m).from();
                Point to = m instanceof Motion.Linear l ? l.to() : ((Motion.Arc) m).to();
                if (at != null) {
                    assertEquals(0, at.distanceTo(from), 1e-6, "the path jumps, " + where);
                }
                at = to;
                byMove.get(i).add(m);
            }
        }
        assertEquals(steps.size(), byMove.size(), where);
        double prevTaken = 0;
        for (int i = 0; i < steps.size(); i++) {
            ProgramFrame f = frames.get(i);
            List<Motion> ms = byMove.get(i);
            Point a = pts.get(i);
            Point c = pts.get(i + 1);
            Motion.Linear rest = (Motion.Linear) ms.get(0);
            Point s = mm(rest.from(), f);
            Point t = mm(rest.to(), f);
            assertOn(s, a, c, where);
            assertOn(t, a, c, where);
            assertEquals(prevTaken, s.distanceTo(a), EPS, "the move starts where the corner before left it, " + where);
            Step step = steps.get(i);
            if (step.corner == null) {
                assertEquals(1, ms.size(), where);
                assertEquals(0, t.distanceTo(c), EPS, "an untouched end stays, " + where);
                prevTaken = 0;
                continue;
            }
            assertEquals(2, ms.size(), where);
            Point next = pts.get(i + 2);
            Motion inserted = ms.get(1);
            Point end = mm(inserted instanceof Motion.Linear l ? l.to() : ((Motion.Arc) inserted).to(), f);
            assertOn(end, c, next, where);
            double taken = t.distanceTo(c);
            assertEquals(taken, end.distanceTo(c), EPS, "both ends the same distance from the corner, " + where);
            if (step.corner.equals(",C")) {
                assertTrue(inserted instanceof Motion.Linear, where);
                assertEquals(step.size, taken, EPS, where);
            } else {
                Motion.Arc arc = (Motion.Arc) inserted;
                Point centre = mm(arc.centre(), f);
                assertEquals(step.size, centre.distanceTo(t), EPS, where);
                assertEquals(step.size, centre.distanceTo(end), EPS, where);
                assertEquals(step.size, distanceToLine(centre, a, c), EPS, "the arc touches the first move, " + where);
                assertEquals(step.size, distanceToLine(centre, c, next), EPS, "and the second, " + where);
            }
            prevTaken = taken;
        }
        assertEquals(0, at == null ? 1 : mm(at, frames.get(frames.size() - 1)).distanceTo(pts.get(pts.size() - 1)),
                EPS, "the contour ends where programmed, " + where);
    }

    /** Machine counts to program mm, X as a radius. */
    private static Point mm(Point p, ProgramFrame f) {
        return new Point((p.x() - f.origin().x()) / f.perX() / 2, (p.z() - f.origin().z()) / f.perZ());
    }

    private static void assertOn(Point p, Point a, Point b, String where) {
        assertEquals(0, distanceToLine(p, a, b), EPS, "off its move " + a + "-" + b + ": " + p + ", " + where);
        double len = a.distanceTo(b);
        assertTrue(a.distanceTo(p) <= len + EPS && b.distanceTo(p) <= len + EPS, "beyond its move, " + where);
    }

    private static double distanceToLine(Point p, Point a, Point b) {
        double dx = b.x() - a.x();
        double dz = b.z() - a.z();
        return Math.abs(dz * (p.x() - a.x()) - dx * (p.z() - a.z())) / Math.hypot(dx, dz);
    }
}
