package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The drawing's path within its budget (issue 35 item 4): what goes when it must, what never goes. */
class PathBudgetTest {
    private static final MachineProfile GENERIC = generic();
    private static final double K = GENERIC.x().countsPerMm();
    private static final double KZ = GENERIC.z().countsPerMm();

    private static MachineProfile generic() {
        try {
            return ProfileLoader.load("generic", TableSource.builtIn(), Tables.builtIn());
        } catch (gcnc.tables.TableException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A move through points given as {x radius mm, z mm} (the centre at 0 counts). */
    private static List<double[]> pts(double... xz) {
        List<double[]> out = new ArrayList<>();
        for (int i = 0; i < xz.length; i += 2) {
            out.add(new double[] {xz[i] * K, xz[i + 1] * KZ});
        }
        return out;
    }

    private static Drawing drawing(PathRecorder p) {
        return p.drawing(SimMachine.read(GENERIC), null, null);
    }

    private static long points(Drawing d) {
        return d.moves().stream().mapToLong(m -> m.z().length).sum();
    }

    @Test
    void aPathWithinTheBudgetIsKeptAsRecorded() {
        PathRecorder p = new PathRecorder(GENERIC, 0);
        p.move(true, pts(26, 2, 25, 2), 7, null, 1);
        p.move(false, pts(25, 2, 25, -40, 25.0005, -40.5, 27, -40.5), 8, null, 1); // a point a count off the line stays
        p.move(true, pts(27, -40.5, 27, 2), 9, null, 1);
        Drawing d = drawing(p);
        assertEquals(0, p.tolerance());
        assertEquals(3, d.moves().size(), "one polyline per line, as before");
        assertEquals(4, d.moves().get(1).z().length);
        assertEquals(8, d.moves().get(1).line());
    }

    @Test
    void aLongPathIsCompactedToWhatItsDrawingShows() {
        PathRecorder p = new PathRecorder(GENERIC, 0);
        int passes = 200_000;
        for (int i = 0; i < passes; i++) {
            double d = 25 - (i % 14_000) * 0.0005; // passes half a micrometre apart: below any pixel
            p.move(true, pts(d + 1, 2, d, 2), 10 * i, null, 1);
            // a feed of 20 points on a straight line, then up a shoulder
            List<double[]> feed = new ArrayList<>();
            for (int k = 0; k <= 20; k++) {
                feed.add(new double[] {d * K, (2 - 2.1 * k) * KZ});
            }
            feed.add(new double[] {(d + 1) * K, -40 * KZ});
            p.move(false, feed, 10 * i + 1, null, 1);
        }
        Drawing d = drawing(p);
        assertTrue(p.tolerance() > 0, "compacted");
        assertTrue(points(d) <= PathRecorder.MOST_POINTS, points(d) + " points");
        // the straight feed is its ends and the shoulder: 3 points, however many it was recorded with
        for (Drawing.Move m : d.moves()) {
            if (!m.rapid()) {
                assertTrue(m.z().length <= 3, m.z().length + " points in a straight feed");
            }
        }
        // rapids and feeds alternate: two moves of one kind never became one polyline
        for (int i = 1; i < d.moves().size(); i++) {
            Drawing.Move a = d.moves().get(i - 1);
            Drawing.Move b = d.moves().get(i);
            if (a.rapid() == b.rapid()) {
                double az = a.z()[a.z().length - 1];
                double ar = a.r()[a.r().length - 1];
                assertTrue(az != b.z()[0] || ar != b.r()[0], "two " + (a.rapid() ? "rapids" : "feeds")
                        + " that join were not joined");
            }
        }
    }

    @Test
    void aToolChangeAndEveryFindingStayThroughACompaction() {
        PathRecorder p = new PathRecorder(GENERIC, 0);
        for (int i = 0; i < 150_000; i++) {
            // two tools' feeds joining end to end: never one polyline
            p.move(false, pts(20 + i % 1000 * 0.01, 0, 20 + i % 1000 * 0.01, -10), 2 * i, null, 1);
            p.move(false, pts(20 + i % 1000 * 0.01, -10, 30, -10), 2 * i + 1, null, 2);
            if (i % 1000 == 0) {
                p.mark("E305", "line " + i, i, 20 * K, -5 * KZ);
            }
        }
        Drawing d = drawing(p);
        assertTrue(p.tolerance() > 0, "compacted");
        assertEquals(150, d.marks().size(), "every finding");
        for (Drawing.Move m : d.moves()) {
            // a polyline of tool 1 is a single pass down Z; one of tool 2 runs along Z-10
            boolean down = m.z()[0] == 0;
            for (int k = 1; k < m.z().length; k++) {
                if (down) {
                    assertTrue(m.r()[k] == m.r()[0], "tool 1's pass and tool 2's were joined");
                } else {
                    assertEquals(-10, m.z()[k], 1e-9);
                }
            }
        }
    }

    @Test
    void decimationKeepsWhatIsFurtherThanTheTolerance() {
        double[][] d = PathDecimation.decimate(new double[] {0, 1, 2, 3, 4}, new double[] {0, 0.001, 0, -0.001, 0}, 0.01);
        assertEquals(2, d[0].length, "points 0.001 off the line go");
        d = PathDecimation.decimate(new double[] {0, 1, 2}, new double[] {0, 0.5, 0}, 0.01);
        assertEquals(3, d[0].length, "a point 0.5 off stays");
        // a path that turns back on itself along one line keeps its turns
        d = PathDecimation.decimate(new double[] {0, 5, 1, 4}, new double[] {0, 0, 0, 0}, 0.01);
        assertEquals(4, d[0].length);
    }
}
