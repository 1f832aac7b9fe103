package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.galil.Dialect;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * The scrub ({@link SimOptions#withScrub}): the stock before and after the first run of one line's
 * moves. Material is only ever taken away, so for every block that moves, what stands after it is
 * within what stood before it, what stands after one block is what the next one meets, and the
 * finished part is within all of them.
 */
class StockScrubTest {
    private static final Tables TABLES = Tables.builtIn();
    /** Generic machine, blank D44: two passes (lines 9 and 13), a rapid in the air (line 10), a block without motion (line 6). */
    private static final String PROGRAM = "O1\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\n"
            + "N60 G00 X46. Z2.\nN70 G00 X41.\nN80 G01 Z-30. F100.\nN90 G00 X46.\nN100 G00 Z2.\nN105 G00 X37.\nN110 G01 Z-15.\n"
            + "N120 G00 X60.\nM05\nM30\n";

    static Drawing simulate(SimOptions options) throws Exception {
        Compiler.Result r = Compiler.compile(new StringReader(PROGRAM), new Compiler.Settings(TABLES,
                ProfileLoader.load("generic", TableSource.builtIn(), TABLES), Dialect.Kind.GALIL, Optional.of(options)), l -> { });
        assertTrue(r.ok(), r.diagnostics().sorted().toString());
        return r.simulation().orElseThrow().drawing();
    }

    @Test
    void withoutAScrubTheDrawingHasNone() throws Exception {
        assertNull(simulate(SimOptions.defaults().withPath()).scrub());
        assertNull(simulate(SimOptions.defaults().withScrub(6)).scrub(), "S1000 M03 moves nothing");
    }

    @Test
    void eachBlockTakesMaterialAwayAndTheNextMeetsWhatItLeft() throws Exception {
        Drawing plain = simulate(SimOptions.defaults().withPath());
        Set<Integer> lines = new LinkedHashSet<>();
        plain.moves().forEach(m -> lines.add(m.line()));
        List<Drawing.Scrub> scrubs = new ArrayList<>();
        for (int line : lines) {
            Drawing d = simulate(SimOptions.defaults().withScrub(line));
            Drawing.Scrub s = d.scrub();
            assertNotNull(s, "line " + line);
            assertEquals(line, s.line());
            assertEquals(line, d.moves().get(s.first()).line());
            assertEquals(line, d.moves().get(s.last()).line());
            assertArrayEquals(plain.finalR(), d.finalR(), 1e-12, "a scrub changes nothing of the run");
            assertArrayEquals(plain.finalZ(), d.finalZ(), 1e-12, "a scrub changes nothing of the run");
            for (double z : probes(plain)) {
                double before = at(s.beforeZ(), s.beforeR(), z);
                double after = at(s.afterZ(), s.afterR(), z);
                assertTrue(after <= before + 1e-9, "line " + line + " at z " + z);
                assertTrue(at(plain.finalZ(), plain.finalR(), z) <= after + 1e-9, "line " + line + " at z " + z);
            }
            assertNotNull(s.insert());
            scrubs.add(s);
        }
        for (int k = 1; k < scrubs.size(); k++) {
            assertArrayEquals(scrubs.get(k - 1).afterZ(), scrubs.get(k).beforeZ(), 1e-9, "line " + scrubs.get(k).line());
            assertArrayEquals(scrubs.get(k - 1).afterR(), scrubs.get(k).beforeR(), 1e-9, "line " + scrubs.get(k).line());
        }
        // the first pass (N80, line 9: X41 to Z-30) took the bar from radius 22 to 20.5 along it; the rapid after it took nothing
        Drawing.Scrub n80 = scrubs.get(new ArrayList<>(lines).indexOf(9));
        double mid = plain.stockFace() - 15;
        assertEquals(22, at(n80.beforeZ(), n80.beforeR(), mid), 1e-6);
        assertEquals(20.5, at(n80.afterZ(), n80.afterR(), mid), 1e-5);
        Drawing.Scrub n90 = scrubs.get(new ArrayList<>(lines).indexOf(10));
        assertArrayEquals(n90.beforeZ(), n90.afterZ(), 1e-12);
        assertArrayEquals(n90.beforeR(), n90.afterR(), 1e-12);
        // the insert where N80 ended: its tip at Z-30 X41 (radius 20.5)
        double tipZ = plain.stockFace() - 30;
        double best = Double.MAX_VALUE;
        for (int i = 0; i < n80.insert().size(); i++) {
            best = Math.min(best, Math.hypot(n80.insert().z()[i] - tipZ, n80.insert().r()[i] - 20.5));
        }
        assertTrue(best < 1.0, "the insert's nose at the pass's end: " + best);
    }

    /** Where the outlines are compared: 2,000 points along the blank. */
    private static double[] probes(Drawing d) {
        double[] z = new double[2000];
        for (int i = 0; i < z.length; i++) {
            z[i] = d.stockBack() + (d.stockFace() - d.stockBack()) * (i + 0.5) / z.length;
        }
        return z;
    }

    /** An outline's radius at z: the points joined by straight lines, the highest where a face stands at z. */
    static double at(double[] zs, double[] rs, double z) {
        double m = Double.NaN;
        for (int i = 0; i + 1 < zs.length; i++) {
            if (zs[i] <= z && z <= zs[i + 1]) {
                double r = zs[i] == zs[i + 1] ? Math.max(rs[i], rs[i + 1])
                        : rs[i] + (rs[i + 1] - rs[i]) * (z - zs[i]) / (zs[i + 1] - zs[i]);
                m = Double.isNaN(m) ? r : Math.max(m, r);
            }
        }
        return m;
    }
}
