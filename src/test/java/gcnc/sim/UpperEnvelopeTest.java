package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.operation.overlayng.OverlayNG;
import org.locationtech.jts.operation.overlayng.OverlayNGRobust;

/**
 * The stock's upper envelope ({@link UpperEnvelope}) against the material it stands for, kept here
 * as one JTS polygon with every cut taken from it: never below the material, exact where a sweep
 * covers everything above its lower edge, a "no" from {@link UpperEnvelope#dips} certain, and the
 * rebuild from the polygons' edges the material's outline.
 */
class UpperEnvelopeTest {
    private static final GeometryFactory F = new GeometryFactory();
    /** A 60 degree V tip on a tall shank: 0.8 mm wide at 8 mm above its tip (mm, relative to the tip). */
    private static final double[] TZ = {-0.4, 0.4, 0};
    private static final double[] TR = {8, 8, 0};

    /** The largest radius of material on the line at z (0 where there is none). */
    private static double top(Geometry material, double z) {
        Geometry line = F.createLineString(new Coordinate[] {new Coordinate(z, -1), new Coordinate(z, 1000)});
        double m = 0;
        for (Coordinate c : material.intersection(line).getCoordinates()) {
            m = Math.max(m, c.y);
        }
        return m;
    }

    /** The V tip swept between two random points over a blank {@code length} long (and a little beyond), r up to {@code rMax}. */
    private static Hull randomSweep(Random rnd, double length, double rMax) {
        double over = length / 12;
        return Hull.sweep(TZ, TR, rnd.nextDouble() * (length + 2 * over) - over, rnd.nextDouble() * rMax,
                rnd.nextDouble() * (length + 2 * over) - over, rnd.nextDouble() * rMax);
    }

    private static Geometry polygon(Hull h) {
        Coordinate[] c = new Coordinate[h.z().length + 1];
        for (int i = 0; i < h.z().length; i++) {
            c[i] = new Coordinate(h.z()[i], h.r()[i]);
        }
        c[c.length - 1] = c[0];
        return F.createPolygon(c);
    }

    @Test
    void aLevelPassLeavesItsStepAndTheInsertsFlank() {
        Stock s = new Stock(0, 100, 25);
        s.cut(Hull.sweep(TZ, TR, 110, 20, 40, 20)); // tip at r 20 from beyond the face to z 40
        double[][] p = s.profile();
        // the flank from (39.6, 28) to the tip (40, 20) crosses r 25 at z 39.75
        assertArrayEquals(new double[] {0, 39.75, 40, 100}, p[0], 1e-5);
        assertArrayEquals(new double[] {25, 25, 20, 20}, p[1], 1e-5);
    }

    @Test
    void aSweepLowerThanTheStockIsTopAndBottomOnlyLeavesTheEnvelope() {
        // a shank 2 mm tall cannot cut a ring of material off above it: the envelope stays
        UpperEnvelope e = new UpperEnvelope(0, 100, 0, 25);
        assertFalse(e.lower(Hull.sweep(TZ, new double[] {2, 2, 0}, 110, 20, 40, 20)));
        assertEquals(25, e.max(0, 100));
        assertEquals(1, e.size());
    }

    @Test
    void roughingPassesKeepTheEnvelopeExactAndSmall() {
        UpperEnvelope e = new UpperEnvelope(0, 100, 0, 25);
        Geometry material = F.toGeometry(new Envelope(0, 100, 0, 25));
        for (int pass = 0; pass < 40; pass++) {
            double r = 24.75 - pass * 0.25;
            Hull h = Hull.sweep(TZ, TR, 102, r, 30 + pass * 0.5, r);
            e.lower(h);
            material = OverlayNGRobust.overlay(material, polygon(h), OverlayNG.DIFFERENCE);
        }
        for (double z = 0.05; z < 100; z += 0.37) {
            assertEquals(top(material, z), e.max(z, z), 1e-9, "at z " + z);
        }
        assertTrue(e.size() < 100, "pieces: " + e.size());
    }

    /** Random sweeps of every direction: the envelope is never below the material, and its "no" is certain. */
    @Test
    void randomSweepsNeverLeaveTheEnvelopeBelowTheMaterial() {
        Random rnd = new Random(23);
        for (int trial = 0; trial < 20; trial++) {
            UpperEnvelope e = new UpperEnvelope(0, 60, 0, 20);
            Geometry material = F.toGeometry(new Envelope(0, 60, 0, 20));
            for (int cut = 0; cut < 60; cut++) {
                Hull h = randomSweep(rnd, 60, 24);
                if (h == null) {
                    continue;
                }
                e.lower(h);
                material = OverlayNGRobust.overlay(material, polygon(h), OverlayNG.DIFFERENCE);
            }
            for (int k = 0; k < 300; k++) {
                double z = rnd.nextDouble() * 60;
                assertTrue(e.max(z, z) >= top(material, z) - 1e-9, "trial " + trial + " at z " + z);
            }
            for (int k = 0; k < 100; k++) {
                Hull q = randomSweep(rnd, 60, 24);
                if (q != null && !e.dips(q.zMin(), q.zMax(), q, 0)) {
                    assertEquals(0, material.intersection(polygon(q)).getArea(), 1e-9, "trial " + trial);
                }
                double a = rnd.nextDouble() * 60;
                double b = a + rnd.nextDouble() * 10;
                double floor = rnd.nextDouble() * 22;
                if (!e.dips(a, b, null, floor)) {
                    assertEquals(0, material.intersection(F.toGeometry(new Envelope(a, b, floor, 1000))).getArea(),
                            1e-9, "trial " + trial);
                }
            }
        }
    }

    /** Rebuilt from a material's edges, the envelope is that material's outline, point for point. */
    @Test
    void aRebuildFromThePolygonsIsTheirOutline() {
        Random rnd = new Random(5);
        Geometry material = F.toGeometry(new Envelope(0, 60, 4, 20)); // a tube: its bore's edges do not count
        for (int cut = 0; cut < 40; cut++) {
            Hull h = Hull.sweep(TZ, TR, rnd.nextDouble() * 70 - 5, 6 + rnd.nextDouble() * 18,
                    rnd.nextDouble() * 70 - 5, 6 + rnd.nextDouble() * 18);
            if (h != null) {
                material = OverlayNGRobust.overlay(material, polygon(h), OverlayNG.DIFFERENCE);
            }
        }
        EdgeEnvelope r = new EdgeEnvelope(10, 50);
        List<Coordinate[]> rings = new ArrayList<>();
        for (int n = 0; n < material.getNumGeometries(); n++) {
            rings.add(material.getGeometryN(n).getCoordinates());
        }
        for (Coordinate[] c : rings) {
            for (int k = 1; k < c.length; k++) {
                r.edge(c[k - 1], c[k]);
            }
        }
        UpperEnvelope e = new UpperEnvelope(0, 60, 0, 20);
        e.replace(10, 50, r.pieces());
        for (double z = 10.003; z < 50; z += 0.0917) {
            assertEquals(top(material, z), e.max(z, z), 1e-9, "at z " + z);
        }
        assertEquals(20, e.max(0, 9.99)); // outside the rebuilt stretch, the envelope as it was
        assertEquals(20, e.max(50.01, 60));
    }

    /** A ragged outline stays bounded: past the limit the envelope becomes level steps, only higher. */
    @Test
    void aRaggedOutlineIsCoarsenedNeverLowered() {
        UpperEnvelope e = new UpperEnvelope(0, 100, 0, 25);
        int n = 40_000;
        double[] at = new double[n];
        double[] deep = new double[n];
        boolean coarsened = false;
        for (int i = 0; i < n; i++) {
            at[i] = 0.5 + i * 0.0024; // V notches 0.0024 mm apart, each to its own depth
            deep[i] = 24 - (i % 7) * 0.01;
            int before = e.size();
            e.lower(Hull.sweep(TZ, TR, at[i], 30, at[i], deep[i]));
            assertTrue(e.size() <= UpperEnvelope.MAX_PIECES, "pieces: " + e.size());
            coarsened |= e.size() < before - 1000;
        }
        assertTrue(coarsened, "the notches made more pieces than the limit");
        // the material: under each notch its V (20 mm of radius per mm of z), at most the blank
        for (double z = 0.01; z < 100; z += 0.0173) {
            double top = 25;
            for (int i = 0; i < n; i++) {
                if (Math.abs(z - at[i]) <= 0.4) {
                    top = Math.min(top, deep[i] + 20 * Math.abs(z - at[i]));
                }
            }
            assertTrue(e.max(z, z) >= top - 1e-9, "at z " + z);
        }
    }

    /**
     * Through the stock (its tiles of exact polygons, the cuts pending until asked for): random
     * sweeps, the polygons made to catch up now and then as a rapid's check does, and at the end
     * the drawing's outline is the material's own, within the polygons' grid.
     */
    @Test
    void theStocksOutlineIsTheMaterialsOnceThePolygonsCatchUp() {
        Random rnd = new Random(11);
        for (int trial = 0; trial < 6; trial++) {
            Stock s = new Stock(0, 30, 12);
            Geometry material = F.toGeometry(new Envelope(0, 30, 0, 12));
            for (int cut = 0; cut < 80; cut++) {
                Hull h = randomSweep(rnd, 30, 14);
                if (h == null) {
                    continue;
                }
                s.cut(h);
                material = OverlayNGRobust.overlay(material, polygon(h), OverlayNG.DIFFERENCE);
                if (cut % 9 == 0) { // a rapid's check: the pending cuts go into the polygons
                    s.biting(List.of(new Stock.Sweep(h, h)));
                }
            }
            double[][] p = s.profile();
            assertTrue(p[0].length < 4096, "trial " + trial + ": the outline's own points, " + s.envelopePieces() + " pieces");
            for (double z = 0.0123; z < 30; z += 0.0311) {
                // within the grid both ways: on a steep flank a corner moved 0.00001 mm along z moves r 20 times that
                double a = StockScrubTest.at(p[0], p[1], z - 2e-5);
                double b = StockScrubTest.at(p[0], p[1], z + 2e-5);
                double truth = top(material, z);
                assertTrue(truth >= Math.min(a, b) - 2e-5 && truth <= Math.max(a, b) + 2e-5,
                        "trial " + trial + " at z " + z + ": " + truth + " against " + a + ".." + b);
            }
        }
    }

    /**
     * Roughing and finishing from outside keep every column of material one run up to the
     * envelope: the drawing is the envelope, with no polygon work, and it is the material's outline.
     * A sweep under material leaves it so; a cut from above that ends under such a sweep's top
     * (what is left below it is not known) ends it, and so does a cut that leaves a cavity in the
     * wall of a bore.
     */
    @Test
    void cutsFromOutsideKeepTheEnvelopeTheOutlineAndACutFromAboveUnderTheFloorEndsIt() {
        Stock s = new Stock(0, 60, 20);
        Geometry material = F.toGeometry(new Envelope(0, 60, 0, 20));
        for (int pass = 0; pass < 30; pass++) {
            double r = 19.5 - pass * 0.5;
            Hull h = Hull.sweep(TZ, TR, 62, r, 20 + pass, r - pass * 0.05); // a slight taper
            s.cut(h);
            material = OverlayNGRobust.overlay(material, polygon(h), OverlayNG.DIFFERENCE);
        }
        double[][] p = s.profile();
        assertTrue(s.envelopeSolid(), "cuts from outside");
        assertEquals(0, s.work(), "no polygon work for the drawing");
        for (double z = 0.0123; z < 60; z += 0.0311) {
            assertEquals(top(material, z), StockScrubTest.at(p[0], p[1], z), 1e-9, "at z " + z);
        }
        // a 2 mm shank passing at r 5 under the material from z 62 to 5: material stays above it, and
        // the outline is still the envelope (the top run's floor comes up to the shank's top, issue 35)
        s.cut(Hull.sweep(TZ, new double[] {2, 2, 0}, 62, 5, 5, 5));
        assertTrue(s.envelopeSolid(), "a sweep under material leaves the top run");
        // a cut from above whose lower edge ends under that floor cannot tell what is left below it
        s.cut(Hull.sweep(TZ, TR, 62, 6, 30, 6));
        assertFalse(s.envelopeSolid(), "a cut from above ending under the floor");
        // through a tube's wall at r 8: nothing is left where the tip passed, a ring of the wall under
        // the V's flank; the outline is still the envelope, 0 where the wall is gone
        Stock tube = new Stock(0, 60, 8, 20);
        Hull through = Hull.sweep(TZ, TR, 62, 6, 40, 6);
        tube.cut(through);
        Geometry wall = OverlayNGRobust.overlay(F.toGeometry(new Envelope(0, 60, 8, 20)), polygon(through),
                OverlayNG.DIFFERENCE);
        assertTrue(tube.envelopeSolid(), "through the bore");
        double[][] t = tube.profile();
        for (double z = 0.0123; z < 60; z += 0.0311) {
            assertEquals(top(wall, z), StockScrubTest.at(t[0], t[1], z), 1e-9, "the tube at z " + z);
        }
    }
}
