package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.operation.overlayng.OverlayNG;
import org.locationtech.jts.operation.overlayng.OverlayNGRobust;

/**
 * The bore's envelope ({@link LowerEnvelope}) and the top run's floor (issue 35 item 5): cuts from
 * inside raise the bore and keep the upper envelope the part's outline with no polygon work; a
 * sweep in the hole meets nothing; the bore is never above the material.
 */
class LowerEnvelopeTest {
    private static final GeometryFactory F = new GeometryFactory();
    /** A drill 10 mm across, its 118-degree-ish point at the tip, its body 40 mm long (mm, relative to the tip). */
    private static final double[] DZ = {0, 3, 40, 40, 3};
    private static final double[] DR = {0, -5, -5, 5, 5};
    /** A boring insert: its tip at the top, 3 mm tall below it, 2 mm long (relative to the tip). */
    private static final double[] BZ = {0, 2, 2, 0};
    private static final double[] BR = {-3, -3, 0, 0};
    /** The V tip of UpperEnvelopeTest: turning from outside. */
    private static final double[] TZ = {-0.4, 0.4, 0};
    private static final double[] TR = {8, 8, 0};

    private static Geometry polygon(Hull h) {
        Coordinate[] c = new Coordinate[h.z().length + 1];
        for (int i = 0; i < h.z().length; i++) {
            c[i] = new Coordinate(h.z()[i], h.r()[i]);
        }
        c[c.length - 1] = c[0];
        return F.createPolygon(c);
    }

    private static double top(Geometry material, double z) {
        Geometry line = F.createLineString(new Coordinate[] {new Coordinate(z, -1), new Coordinate(z, 1000)});
        double m = 0;
        for (Coordinate c : material.intersection(line).getCoordinates()) {
            m = Math.max(m, c.y);
        }
        return m;
    }

    private static double bottom(Geometry material, double z) {
        Geometry line = F.createLineString(new Coordinate[] {new Coordinate(z, -1), new Coordinate(z, 1000)});
        double m = Double.POSITIVE_INFINITY;
        for (Coordinate c : material.intersection(line).getCoordinates()) {
            m = Math.min(m, c.y);
        }
        return m;
    }

    @Test
    void aDrilledAndBoredPartKeepsItsOutlineOnTheEnvelope() {
        Stock s = new Stock(0, 60, 20);
        Geometry material = F.toGeometry(new Envelope(0, 60, 0, 20));
        Hull[] cuts = {
            Hull.sweep(DZ, DR, 62, 0, 35, 0), // drilled on the centreline to z 35
            Hull.sweep(BZ, BR, 62, 6.5, 45, 6.5), // bored to 13 mm to z 45
            Hull.sweep(BZ, BR, 62, 8, 50, 8), // and to 16 mm to z 50
            Hull.sweep(TZ, TR, 62, 15, 30, 15), // turned outside to 30 mm
            Hull.sweep(TZ, TR, 62, 12, 52, 12), // and to 24 mm
        };
        for (Hull h : cuts) {
            s.cut(h);
            material = OverlayNGRobust.overlay(material, polygon(h), OverlayNG.DIFFERENCE);
        }
        double[][] p = s.profile();
        assertTrue(s.envelopeSolid(), "cuts from outside and from inside");
        assertEquals(0, s.work(), "no polygon work for the drawing");
        for (double z = 0.0123; z < 60; z += 0.0311) {
            assertEquals(top(material, z), StockScrubTest.at(p[0], p[1], z), 1e-9, "at z " + z);
        }
        // a sweep in the bore touches nothing: the boring bar's rapid back out along the wall it cut
        assertFalse(s.mayBite(Hull.sweep(BZ, BR, 50, 8, 62, 8)), "in the hole");
        assertFalse(s.mayBite(Hull.sweep(BZ, BR, 45, 6, 62, 6)), "in the hole");
        assertEquals(6.5, s.boreAt(47), 1e-12);
        // and one that reaches the bore's step is found: the drilled hole is 5 mm in radius before z 45
        assertTrue(s.mayBite(Hull.sweep(BZ, BR, 44, 6, 62, 6)), "into the step at z 44..45");
    }

    @Test
    void theFullModelTakesThePolygonsWay() {
        Stock s = new Stock(0, 60, 0, 20, true);
        s.cut(Hull.sweep(DZ, DR, 62, 0, 35, 0));
        s.cut(Hull.sweep(TZ, TR, 62, 15, 30, 15));
        s.profile();
        assertTrue(s.work() > 0, "the reference reads its outline from the polygons");
        assertTrue(s.mayBite(Hull.sweep(BZ, BR, 50, 4, 62, 4)), "its bore stays the blank's: only a may");
    }

    @Test
    void aCutFromAboveIntoWhatADrillLeftEndsTheShortcut() {
        // a drill 0.5 mm off the centre leaves a pip under its point: material from r 0 up to its lower side
        Stock s = new Stock(0, 60, 20);
        Geometry material = F.toGeometry(new Envelope(0, 60, 0, 20));
        Hull drill = Hull.sweep(DZ, DR, 62, 0.5, 40, 0.5);
        s.cut(drill);
        material = OverlayNGRobust.overlay(material, polygon(drill), OverlayNG.DIFFERENCE);
        assertTrue(s.envelopeSolid(), "the pip is under the floor: the outline is still the envelope");
        // a parting blade from outside down to r 0.1 across the pip: what is left below it is not known
        Hull part = Hull.sweep(new double[] {-1, 0, 0, -1}, new double[] {0, 0, 30, 30}, 41, 25, 41, 0.1);
        s.cut(part);
        material = OverlayNGRobust.overlay(material, polygon(part), OverlayNG.DIFFERENCE);
        assertFalse(s.envelopeSolid(), "a cut from above ending under the floor");
        double[][] p = s.profile();
        for (double z = 0.0123; z < 60; z += 0.0311) {
            assertEquals(top(material, z), StockScrubTest.at(p[0], p[1], z), 1e-4, "at z " + z);
        }
    }

    /** Random sweeps from inside and outside: the bore is never above the material, the envelope never below. */
    @Test
    void randomSweepsNeverLeaveTheBoreAboveTheMaterial() {
        Random rnd = new Random(35);
        for (int trial = 0; trial < 20; trial++) {
            UpperEnvelope e = new UpperEnvelope(0, 60, 2, 20);
            Geometry material = F.toGeometry(new Envelope(0, 60, 2, 20));
            for (int cut = 0; cut < 40; cut++) {
                boolean inside = rnd.nextBoolean();
                double r = rnd.nextDouble() * 22;
                Hull h = inside
                        ? Hull.sweep(BZ, BR, 62 + rnd.nextDouble() * 5, r, rnd.nextDouble() * 60, r + rnd.nextDouble() - 0.5)
                        : Hull.sweep(TZ, TR, 62 + rnd.nextDouble() * 5, r, rnd.nextDouble() * 60, r + rnd.nextDouble() - 0.5);
                if (h == null) {
                    continue;
                }
                e.lower(h);
                material = OverlayNGRobust.overlay(material, polygon(h), OverlayNG.DIFFERENCE);
            }
            for (int k = 0; k < 300; k++) {
                double z = rnd.nextDouble() * 60;
                double low = bottom(material, z);
                if (low != Double.POSITIVE_INFINITY) {
                    assertTrue(e.bore().at(z) <= low + 1e-9, "trial " + trial + " at z " + z + ": bore " + e.bore().at(z)
                            + " above the material at " + low);
                }
                assertTrue(e.max(z, z) >= top(material, z) - 1e-9, "trial " + trial + " at z " + z);
            }
            if (e.solid()) {
                for (double z = 0.0123; z < 60; z += 0.0311) {
                    assertEquals(top(material, z), e.max(z, z), 1e-7, "trial " + trial + ", solid, at z " + z);
                }
            }
        }
    }
}
