package gcnc.galil;

import gcnc.machine.Plane;
import static gcnc.galil.Fixtures.motions;
import static gcnc.galil.Fixtures.rapid;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Diagnostics;
import gcnc.ir.ArcGeometry;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Feed;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * CR for arcs in every quadrant, both senses, R > 0 and R < 0 and I/K, on three axis mappings.
 * Working: write a point relative to the centre as the lathe drawing's angle phi (z right, x up,
 * G03 = counter-clockwise). Then
 * <ul>
 * <li>G (generic: Galil X = +Z, Y = +X): u = z, v = x, so the Galil start angle is phi and the
 *     sweep keeps its sign;</li>
 * <li>V (Galil X = -X, Y = +Z): (u, v) = (-sin phi, cos phi) = angle phi + 90, sweep keeps its sign;</li>
 * <li>W (thesis-2004's mapping, Galil X = -X, Y = -Z): (u, v) = (-sin phi, -cos phi) = angle
 *     -90 - phi, and the sweep changes sign (a mirror).</li>
 * </ul>
 * Centre (x 5000, z 5000), r 1000: phi 0 = (x 5000, z 6000), 90 = (6000, 5000), 180 = (5000, 4000),
 * -90 = (4000, 5000). The R &lt; 0 arcs from phi-0 point to phi-90 point go the long way about the
 * other centre (6000, 6000) for G03 (phi -90 to 180, +270), about (5000, 5000) for G02 (0 to 90 the
 * long way, -270). The I/K arc: centre (1000, 2000), start + (x 4000, z 3000) at phi = atan(4/3)
 * = 53.1301, G02 to + (x 0, z 5000) at phi 0, sweep -53.1301, r 5000.
 */
class GalilDialectArcTest {
    private static final MachineProfile GENERIC = Fixtures.profile("generic");
    private static final MachineProfile G = Fixtures.mapped(GENERIC, 'Y', 1, 'X', 1, Point.ORIGIN);
    private static final MachineProfile V = Fixtures.mapped(GENERIC, 'X', -1, 'Y', 1, Point.ORIGIN);
    private static final MachineProfile W = Fixtures.mapped(GENERIC, 'X', -1, 'Y', -1, Point.ORIGIN);
    private static final Feed FEED = new Feed(100, 2000);

    @ParameterizedTest(name = "{0}")
    @CsvSource({
        "Q1 G03 0 to 90,          false, 5000, 6000, 6000, 5000, 5000, 5000, 1000, 'CR 1000,0,90',    'CR 1000,90,90',    'CR 1000,-90,-90'",
        "Q1 G02 90 to 0,          true,  6000, 5000, 5000, 6000, 5000, 5000, 1000, 'CR 1000,90,-90',  'CR 1000,180,-90',  'CR 1000,180,90'",
        "Q2 G03 90 to 180,        false, 6000, 5000, 5000, 4000, 5000, 5000, 1000, 'CR 1000,90,90',   'CR 1000,180,90',   'CR 1000,180,-90'",
        "Q2 G02 180 to 90,        true,  5000, 4000, 6000, 5000, 5000, 5000, 1000, 'CR 1000,180,-90', 'CR 1000,-90,-90',  'CR 1000,90,90'",
        "Q3 G03 180 to 270,       false, 5000, 4000, 4000, 5000, 5000, 5000, 1000, 'CR 1000,180,90',  'CR 1000,-90,90',   'CR 1000,90,-90'",
        "Q3 G02 -90 to -180,      true,  4000, 5000, 5000, 4000, 5000, 5000, 1000, 'CR 1000,-90,-90', 'CR 1000,0,-90',    'CR 1000,0,90'",
        "Q4 G03 -90 to 0,         false, 4000, 5000, 5000, 6000, 5000, 5000, 1000, 'CR 1000,-90,90',  'CR 1000,0,90',     'CR 1000,0,-90'",
        "Q4 G02 0 to -90,         true,  5000, 6000, 4000, 5000, 5000, 5000, 1000, 'CR 1000,0,-90',   'CR 1000,90,-90',   'CR 1000,-90,90'",
        "R<0 G03 the long way,    false, 5000, 6000, 6000, 5000, 6000, 6000, 1000, 'CR 1000,-90,270', 'CR 1000,0,270',    'CR 1000,0,-270'",
        "R<0 G02 the long way,    true,  5000, 6000, 6000, 5000, 5000, 5000, 1000, 'CR 1000,0,-270',  'CR 1000,90,-270',  'CR 1000,-90,270'",
        "I/K G02 3-4-5,           true,  5000, 5000, 1000, 7000, 1000, 2000, 5000, 'CR 5000,53.1301,-53.1301', 'CR 5000,143.1301,-53.1301', 'CR 5000,-143.1301,53.1301'",
    })
    void handWorkedCr(String name, boolean g02, double fx, double fz, double tx, double tz, double cx, double cz,
                      double r, String onG, String onV, String onW) {
        Point from = new Point(fx, fz);
        Point to = new Point(tx, tz);
        Motion.Arc arc = new Motion.Arc(g02, from, to, new Point(cx, cz), r, FEED, new Motion.ArcWords(null, cx - fx, cz - fz));
        assertEquals(onG, crOf(G, from, arc), "generic mapping");
        assertEquals(onV, crOf(V, from, arc), "X first, X negative");
        assertEquals(onW, crOf(W, from, arc), "thesis-2004 mapping");
    }

    /** Rapid from home to the arc's start, then the arc: returns the CR line, after checking the path. */
    private static String crOf(MachineProfile p, Point from, Motion.Arc arc) {
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", p, d, motions(1, from, rapid(Point.ORIGIN, from)),
                motions(2, arc.to(), arc));
        assertEquals(0, d.size(), () -> d.sorted().toString());
        assertEnds(p, out, List.of(from, arc.to()));
        return out.stream().filter(l -> l.startsWith("CR ")).findFirst().orElseThrow();
    }

    /** Every sequence ends within one count (each axis) of its motion's end. */
    private static void assertEnds(MachineProfile p, List<String> out, List<Point> ends) {
        List<long[]> got = new PathReader(0, 0).read(out);
        assertEquals(ends.size(), got.size(), "one sequence per motion");
        Plane f = Plane.of(p);
        for (int i = 0; i < ends.size(); i++) {
            double eu = f.galil1(ends.get(i));
            double ev = f.galil2(ends.get(i));
            long[] g = got.get(i);
            assertTrue(Math.abs(g[0] - eu) <= 1 && Math.abs(g[1] - ev) <= 1,
                    "sequence " + (i + 1) + " ends at " + g[0] + "," + g[1] + ", expected " + eu + "," + ev);
        }
    }

    @Test
    void chainsOfRandomArcsEndWhereTheBlocksEnd() {
        Random rnd = new Random(20041);
        for (MachineProfile p : new MachineProfile[] {G, V, W}) {
            Plane f = Plane.of(p);
            List<CheckedBlock> blocks = new ArrayList<>();
            List<Point> ends = new ArrayList<>();
            Point at = new Point(rnd.nextDouble() * 1000, rnd.nextDouble() * 1000);
            blocks.add(motions(1, at, rapid(Point.ORIGIN, at)));
            ends.add(at);
            for (int i = 0; i < 400; i++) {
                double r = 5 + Math.pow(10, rnd.nextDouble() * 5);         // 5 .. 100005 counts
                double toward = rnd.nextDouble() * 2 * Math.PI;
                Point c = new Point(at.x() + r * Math.sin(toward), at.z() + r * Math.cos(toward));
                double sweep = (rnd.nextDouble() * 2 - 1) * 359;          // degrees in the drawing
                double start = Math.atan2(at.x() - c.x(), at.z() - c.z());
                double end = start + Math.toRadians(sweep);
                Point to = new Point(c.x() + r * Math.sin(end), c.z() + r * Math.cos(end));
                boolean g02 = sweep < 0;
                double radius = at.distanceTo(c);
                blocks.add(motions(i + 2, to, new Motion.Arc(g02, at, to, c, radius, FEED,
                        new Motion.ArcWords(null, c.x() - at.x(), c.z() - at.z()))));
                if (!sameCount(f, at, to) || Math.abs(sweep) > 180) {
                    ends.add(to); // else a short arc within one count: no sequence (next test)
                }
                assertEquals(sweep, ArcGeometry.sweepDegrees(at, to, c, g02), 1e-6);
                at = to;
            }
            Diagnostics d = new Diagnostics();
            List<String> out = Fixtures.run("galil", p, d, blocks.toArray(new CheckedBlock[0]));
            assertEquals(0, d.size(), () -> p.name() + d.sorted());
            assertEnds(p, out, ends);
        }
    }

    private static boolean sameCount(Plane f, Point a, Point b) {
        return GalilNumbers.round(f.galil1(a)) == GalilNumbers.round(f.galil1(b)) && GalilNumbers.round(f.galil2(a)) == GalilNumbers.round(f.galil2(b));
    }

    /**
     * Ends that round to the same count and a sweep of at most half a turn: the arc moves less than
     * a count, and gets no sequence. The same ends the other way round are a whole turn.
     */
    @Test
    void anArcWithinOneCountIsNoMoveButTheLongWayRoundIs() {
        Point from = new Point(5000.2, 6000.1);
        Point to = new Point(5000.3, 5999.9);
        Point c = new Point(3000, 6000);
        for (boolean clockwise : new boolean[] {false, true}) {
            Motion.Arc arc = new Motion.Arc(clockwise, from, to, c, from.distanceTo(c), FEED,
                    new Motion.ArcWords(null, -2000.2, -0.1));
            Diagnostics d = new Diagnostics();
            List<String> out = Fixtures.run("galil", G, d, motions(1, from, rapid(Point.ORIGIN, from)), motions(2, to, arc));
            assertEquals(0, d.size());
            assertEquals(clockwise ? 2 : 1, new PathReader(0, 0).read(out).size(), out.toString());
            assertEquals(clockwise, out.contains("CR 2000,90,-360"), out.toString());
        }
    }

    @Test
    void bishopN240IsATrueArcOfRadius2100() {
        // N240 G03 X+1000 R1400 from X800 Z0 under thesis-2004: machine (x -18800, z -20000) to
        // (-18500, -20000), r 2100. G03 moving +x: centre to the left, at z -20000 - sqrt(2100^2 - 150^2)
        // = -22094.636, x -18650. Galil (u, v) = (-x, -z): start relative to the centre (150, -2094.636),
        // angle atan2(-2094.636, 150) = -85.9040; sweep 2 asin(150/2100) = 8.1921, mirrored: -8.1921.
        MachineProfile thesis = Fixtures.profile("thesis-2004");
        Point from = new Point(-18800, -20000);
        Point to = new Point(-18500, -20000);
        Point c = new Point(-18650, -20000 - Math.sqrt(2100.0 * 2100 - 150 * 150));
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", thesis, d, motions(2, from, rapid(Point.ORIGIN, from)),
                motions(32, to, new Motion.Arc(false, from, to, c, 2100, new Feed(50, 1000),
                        new Motion.ArcWords(2100.0, null, null))));
        assertEquals(0, d.size());
        assertTrue(out.contains("CR 2100,-85.904,-8.1921"), out.toString());
        assertTrue(out.contains("VP 18800,20000"), out.toString());
    }

    /** A circle under a count across (here 0.8) whose ends round to neighbouring counts: one straight count. */
    @Test
    void anArcUnderACountAcrossIsAStraightMove() {
        Point c = new Point(5000.0, 6000.2);
        Point from = new Point(5000.0, 6000.6);                    // counts (5000, 6001)
        double a = Math.toRadians(150);
        Point to = new Point(c.x() + 0.4 * Math.sin(a), c.z() + 0.4 * Math.cos(a)); // counts (5000, 6000)
        Motion.Arc arc = new Motion.Arc(false, from, to, c, 0.4, FEED, new Motion.ArcWords(null, 0.0, -0.4));
        assertEquals(150, ArcGeometry.sweepDegrees(from, to, c, false), 1e-9);
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", G, d, motions(1, from, rapid(Point.ORIGIN, from)), motions(2, to, arc));
        assertEquals(0, d.size(), () -> d.sorted().toString());
        assertTrue(out.stream().noneMatch(l -> l.startsWith("CR")), out.toString());
        assertEnds(G, out, List.of(from, to));
    }

    /** An I/K end 6 counts outside its circle (the checker allows 10): same centre and radius, and a VP closes the gap. */
    @Test
    void anIkEndOffItsCircleWithinToleranceIsClosedByAVp() {
        Point from = new Point(5000, 6000);
        Point c = new Point(5000, 3000);
        double a = Math.toRadians(170);
        Point to = new Point(c.x() + 3006 * Math.sin(a), c.z() + 3006 * Math.cos(a));
        Motion.Arc arc = new Motion.Arc(false, from, to, c, 3000, FEED, new Motion.ArcWords(null, 0.0, -3000.0));
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", G, d, motions(1, from, rapid(Point.ORIGIN, from)), motions(2, to, arc));
        assertEquals(0, d.size(), () -> d.sorted().toString());
        assertEnds(G, out, List.of(from, to));
        int cr = 0;
        while (cr < out.size() && !out.get(cr).startsWith("CR ")) {
            cr++;
        }
        assertTrue(out.get(cr).startsWith("CR 3000,") && out.get(cr + 1).startsWith("VP "), out.toString());
    }

    @Test
    void fullCirclesSweepThreeHundredSixty() {
        // From phi 0 (x 5000, z 6000) round the centre (5000, 5000) back to itself. Generic: start 0,
        // G02 -360, G03 +360. Thesis mapping W: start -90 - 0 = -90, senses mirrored.
        Point p = new Point(5000, 6000);
        Point c = new Point(5000, 5000);
        Motion.Arc cw = new Motion.Arc(true, p, p, c, 1000, FEED, new Motion.ArcWords(null, 0.0, -1000.0));
        Motion.Arc ccw = new Motion.Arc(false, p, p, c, 1000, FEED, new Motion.ArcWords(null, 0.0, -1000.0));
        assertEquals("CR 1000,0,-360", crOf(G, p, cw));
        assertEquals("CR 1000,0,360", crOf(G, p, ccw));
        assertEquals("CR 1000,-90,360", crOf(W, p, cw));
        assertEquals("CR 1000,-90,-360", crOf(W, p, ccw));
    }

    /**
     * A half circle of radius 7600.5 counts on the generic mapping (u = z, v = x), from (0, 0) to
     * (u 15201, v 0), G02. No whole radius reaches both ends without moving the centre about 87
     * counts off the chord (r 7601: h = sqrt(7601^2 - 7600.5^2) = 87.2), so the arc keeps the true
     * centre (7600.5, 0): radius 7601, start angle 180 (S is left of the centre), sweep -180 (clockwise
     * over the top). It ends at u = 7601 - 1 + 7601 = 15202, a count past the target, and a closing
     * VP 15201,0 in the same sequence brings the sequence to the block's end exactly.
     */
    @Test
    void aHalfCircleOfHalfCountRadiusKeepsItsCentreAndClosesWithAVp() {
        Point from = Point.ORIGIN;
        Point to = new Point(0, 15201);
        Motion.Arc arc = new Motion.Arc(true, from, to, new Point(0, 7600.5), 7600.5, FEED, new Motion.ArcWords(7600.5, null, null));
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", G, d, motions(3, to, arc));
        assertEquals(0, d.size(), () -> d.sorted().toString());
        int cr = out.indexOf("CR 7601,180,-180");
        assertTrue(cr > 0, out.toString());
        assertEquals(List.of("VP 15201,0", "VE", "BGS", "AMS"), out.subList(cr + 1, cr + 5));
        List<long[]> ends = new PathReader(0, 0).read(out);
        assertEquals(15201, ends.get(0)[0]);
        assertEquals(0, ends.get(0)[1]);
    }
}
