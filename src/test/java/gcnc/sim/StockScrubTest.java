package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
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
                ProfileLoader.load("generic", TableSource.builtIn(), TABLES), "galil", Optional.of(options)), l -> { });
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
            for (int i = 0; i < s.afterR().length; i++) {
                assertTrue(s.afterR()[i] <= s.beforeR()[i] + 1e-9, "line " + line + " slice " + i);
                assertTrue(plain.finalR()[i] <= s.afterR()[i] + 1e-9, "line " + line + " slice " + i);
            }
            assertNotNull(s.insert());
            scrubs.add(s);
        }
        for (int k = 1; k < scrubs.size(); k++) {
            assertArrayEquals(scrubs.get(k - 1).afterR(), scrubs.get(k).beforeR(), 1e-9, "line " + scrubs.get(k).line());
        }
        // the first pass (N80, line 9: X41 to Z-30) took the bar from radius 22 to 20.5 along it; the rapid after it took nothing
        Drawing.Scrub n80 = scrubs.get(new ArrayList<>(lines).indexOf(9));
        int mid = nearest(n80.afterZ(), plain.stockFace() - 15);
        assertEquals(22, n80.beforeR()[mid], 1e-6);
        assertEquals(20.5, n80.afterR()[mid], 0.02);
        Drawing.Scrub n90 = scrubs.get(new ArrayList<>(lines).indexOf(10));
        assertArrayEquals(n90.beforeR(), n90.afterR(), 1e-12);
        // the insert where N80 ended: its tip at Z-30 X41 (radius 20.5)
        double tipZ = plain.stockFace() - 30;
        double best = Double.MAX_VALUE;
        for (int i = 0; i < n80.insert().size(); i++) {
            best = Math.min(best, Math.hypot(n80.insert().z()[i] - tipZ, n80.insert().r()[i] - 20.5));
        }
        assertTrue(best < 1.0, "the insert's nose at the pass's end: " + best);
    }

    private static int nearest(double[] zs, double z) {
        int best = 0;
        for (int i = 1; i < zs.length; i++) {
            if (Math.abs(zs[i] - z) < Math.abs(zs[best] - z)) {
                best = i;
            }
        }
        return best;
    }
}
