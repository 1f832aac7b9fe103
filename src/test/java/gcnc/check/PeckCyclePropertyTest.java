package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.check.cycle.Drilling;
import gcnc.check.cycle.Move;
import gcnc.check.cycle.Pecking;
import gcnc.ir.Point;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Random grooves, face grooves and peck-drilled holes (seeded; the seed is in every message): the
 * expanded moves never go past the programmed bottom nor behind the start along the peck axis,
 * stay between the start and the end (less the relief) along the step axis, feed no more than a
 * peck into new material at a time, reach the bottom in every cut, and end where they started.
 */
class PeckCyclePropertyTest {
    private static final double EPS = 1e-6;

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6, 7, 8})
    void grooves(long seed) {
        Random r = new Random(seed);
        for (int n = 0; n < 300; n++) {
            String at = "seed " + seed + " case " + n;
            boolean alongX = r.nextBoolean();
            Point a = new Point(1000 + r.nextInt(50_000), -r.nextInt(80_000));
            double depth = 1 + r.nextInt(30_000);
            double peckDir = r.nextBoolean() ? -1 : 1;
            double aPeck = alongX ? a.x() : a.z();
            double aStep = alongX ? a.z() : a.x();
            double peckEnd = aPeck + peckDir * depth;
            boolean steps = r.nextBoolean();
            double span = steps ? 1 + r.nextInt(20_000) : 0;
            double stepEnd = aStep + (r.nextBoolean() ? -span : span);
            double peck = r.nextBoolean() ? Double.NaN : 1 + r.nextInt((int) depth);
            double step = steps ? 1 + r.nextInt(5000) : Double.NaN;
            double retract = r.nextInt(2000);
            double relief = steps ? r.nextInt((int) step + 1) : r.nextInt(500) - 250;
            Pecking p = new Pecking(alongX, a, peckEnd, stepEnd, peck, step, retract, relief);
            Pecking.Plan plan = p.plan();
            List<Move> moves = plan.moves();
            assertEquals(p.cuts(), plan.passes(), at);
            double lowStep = Math.min(aStep, stepEnd) - Math.abs(relief);
            double highStep = Math.max(aStep, stepEnd) + Math.abs(relief);
            double reached = 0;
            int bottoms = 0;
            int cut = 0;
            for (Move m : moves) {
                double pk = alongX ? m.to().x() : m.to().z();
                double st = alongX ? m.to().z() : m.to().x();
                double into = (pk - aPeck) * peckDir;
                assertTrue(into >= -EPS && into <= depth + EPS, at + ": past the bottom or behind the start: " + m);
                assertTrue(st >= lowStep - EPS && st <= highStep + EPS, at + ": outside the step's span: " + m);
                if (m.pass() != cut) {
                    cut = m.pass();
                    reached = 0;
                }
                if (m.kind() == Move.Kind.FEED) {
                    double fresh = into - reached;
                    assertTrue(Double.isNaN(peck) || fresh <= peck + EPS, at + ": more than a peck at once: " + m);
                    assertTrue(fresh > 0, at + ": a feed into nothing new: " + m);
                    reached = into;
                    if (Math.abs(into - depth) <= EPS) {
                        bottoms++;
                    }
                } else {
                    assertTrue(into <= reached + EPS, at + ": a rapid into the material: " + m);
                }
            }
            assertEquals(p.cuts(), bottoms, at + ": every cut reaches the bottom once");
            assertTrue(moves.get(moves.size() - 1).to().distanceTo(a) <= EPS, at + ": ends at the start");
        }
    }

    @ParameterizedTest
    @ValueSource(longs = {11, 12, 13, 14})
    void peckDrilledHoles(long seed) {
        Random r = new Random(seed);
        for (int n = 0; n < 300; n++) {
            String at = "seed " + seed + " case " + n;
            Point a = new Point(r.nextBoolean() ? 0 : r.nextInt(5000), 1000 + r.nextInt(20_000));
            double plane = a.z() - r.nextInt(1000);
            double bottom = plane - 1 - r.nextInt(60_000);
            boolean pecks = r.nextBoolean();
            double first = pecks ? 1 + r.nextInt(10_000) : Double.NaN;
            double reduce = r.nextBoolean() ? 0 : r.nextInt(3000);
            double least = pecks ? 1 + r.nextInt((int) first) : 1;
            double clearance = r.nextInt(1500);
            Drilling d = new Drilling(a, 0, plane, bottom, first, reduce, least, clearance);
            List<Double> reachedAt = d.pecks(HoleDrilling.MAX_PECKS);
            assertEquals(plane - bottom, reachedAt.get(reachedAt.size() - 1), EPS, at + ": the pecks add up to the depth");
            double before = 0;
            for (double v : reachedAt) {
                assertTrue(v > before, at + ": each peck goes deeper");
                assertTrue(Double.isNaN(first) || v - before <= first + EPS, at + ": no peck more than the first");
                before = v;
            }
            double deepest = 0;
            for (Move m : d.plan(HoleDrilling.MAX_PECKS)) {
                double z = m.to().z();
                assertTrue(z >= bottom - EPS && z <= a.z() + EPS, at + ": past the bottom or behind the start: " + m);
                assertEquals(0, m.to().x(), EPS, at + ": the drill stays on centre");
                if (m.kind() == Move.Kind.FEED) {
                    deepest = Math.max(deepest, plane - z);
                } else {
                    assertTrue(plane - z <= deepest + EPS, at + ": a rapid into the material: " + m);
                }
            }
            List<Move> moves = d.plan(HoleDrilling.MAX_PECKS);
            assertTrue(moves.get(moves.size() - 1).to().distanceTo(new Point(0, a.z())) <= EPS, at + ": back at the start");
        }
    }
}
