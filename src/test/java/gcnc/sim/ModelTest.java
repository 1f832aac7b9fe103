package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.io.StringWriter;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

class ModelTest {
    private static SimMachine read(String text) throws TableException {
        return SimMachine.read(ProfileLoader.read(ProfileFile.parse("t.machine", text), Tables.builtIn()));
    }

    @Test
    void stockWithoutAChuckIsALocatedProfileError() {
        String text = SimFixture.PROFILE.replace("chuck.face_z = 0\n", "").replace("chuck.jaw_diameter = 80\n", "")
                .replace("chuck.jaw_length = 20\n", "").replace("chuck.diameter = 120\n", "");
        TableException e = assertThrows(TableException.class, () -> read(text));
        assertEquals(Code.E400_TABLE, e.diagnostic().code());
        assertEquals(text.lines().toList().indexOf("stock.diameter = 40") + 1, e.diagnostic().span().line());
    }

    @Test
    void concaveToolOutlineIsRejected() {
        String text = SimFixture.PROFILE.replace("sim.tool.default.holder = 0, 6; 10, 6; 10, 20; 0, 20",
                "sim.tool.default.holder = 0, 6; 10, 6; 2, 9; 10, 20; 0, 20");
        TableException e = assertThrows(TableException.class, () -> read(text));
        assertTrue(e.english().contains("convex"), e.english());
    }

    @Test
    void unknownToolOutlineKeyIsRejected() {
        String text = SimFixture.PROFILE + "sim.tool.3.shank = 0, 0; 1, 1; 0, 1\n";
        assertThrows(TableException.class, () -> read(text));
    }

    @Test
    void perToolOutlineOverridesTheDefault() throws Exception {
        SimMachine m = read(SimFixture.PROFILE + "sim.tool.4.insert = 0, 0; 5, 0; 5, 5\n");
        assertEquals(5, m.tool(4).insert().z()[1], 1e-12);
        assertEquals(3, m.tool(1).insert().z()[1], 1e-12);
        assertEquals(m.defaultTool().holder(), m.tool(4).holder());
    }

    @Test
    void noTailstockKeysMeansNoTailstock() throws Exception {
        SimMachine m = read(SimFixture.PROFILE.replace("tailstock.centre_z = 200\n", "")
                .replace("tailstock.quill_diameter = 30\n", ""));
        assertEquals(0, m.tailstock().length);
    }

    @Test
    void emcoStockHeaderGivesLengthAndDiameter() {
        assertEquals(Optional.of(new StockSize(22, 120, 100)), StockHeader.parse("(120.00 22.00 5.00 5.00)", 100));
        // never further out of the chuck than the blank is long
        assertEquals(Optional.of(new StockSize(22, 120, 120)), StockHeader.parse("(120.00 22.00 5.00 5.00)", 150));
        assertEquals(Optional.empty(), StockHeader.parse("(ROUGH FACE)", 150));
        assertEquals(Optional.empty(), StockHeader.parse("N10 G00 X1", 150));
        // a Denford / MIRAC first line: X the diameter, Z the length (E261 says it is read as a comment)
        assertEquals(Optional.of(new StockSize(50, 100, 100)), StockHeader.parse("[BILLET X50 Z100", 150));
        assertEquals(Optional.of(new StockSize(30, 65, 40)), StockHeader.parse("[billet x30 z65", 40));
        assertEquals(Optional.empty(), StockHeader.parse("[BILLET X50", 150));
        assertEquals(Optional.empty(), StockHeader.parse("[EDGEMOVE X0 Z-2", 150));
        assertEquals(Optional.empty(), StockHeader.parse("(120)", 150));
    }

    @Test
    void stockOverrideReplacesTheProfilesBlank() throws Exception {
        // Blank r 10 instead of 20: a rapid at r 15 is now in the air.
        SimFixture f = new SimFixture(SimFixture.PROFILE, SimOptions.defaults().withStock(new StockSize(20, 120, 100)));
        f.start();
        f.move(true, 15, 102);
        f.move(true, 15, 50);
        assertEquals(List.of(), f.codes());
    }

    @Test
    void trapezoidAndTriangleTimes() {
        // 1000 counts at 1000 counts/s, 10000 counts/s^2 both ways: 1 s + 0.05 s + 0.05 s.
        assertEquals(1.1, Profiles.time(1000, 1000, 10000, 10000), 1e-12);
        // 10 counts cannot reach 1000 counts/s: accelerate 5, decelerate 5 -> 2 x sqrt(2*5/10000).
        assertEquals(2 * Math.sqrt(0.001), Profiles.time(10, 1000, 10000, 10000), 1e-12);
    }

    @Test
    void arcBoundsIncludeTheQuadrantPointsItPasses() {
        // Quarter circle from angle 45 to 135 about (0,0), r 10: passes 90 (+x) -> x max 10.
        Segment s = new Segment(10 * Math.sin(Math.PI / 4), 10 * Math.cos(Math.PI / 4), 10 * Math.sin(3 * Math.PI / 4),
                10 * Math.cos(3 * Math.PI / 4), true, 0, 0, 10, 45, 90, null);
        double[] b = MotionChecks.bounds(s);
        assertEquals(10, b[1], 1e-12);
        assertEquals(-10 * Math.cos(Math.PI / 4), b[2], 1e-12);
    }

    @Test
    void svgShowsPathStockAndFindings() throws Exception {
        SimFixture f = new SimFixture(SimFixture.PROFILE, SimOptions.defaults().withPath());
        f.start();
        f.move(true, 22, 102);
        f.move(false, 18, 102);
        f.move(false, 18, 50);
        f.move(true, 15, 40); // into the stock: a finding mark
        StringWriter w = new StringWriter();
        SvgWriter.write(f.sim.report(), "t", w);
        String svg = w.toString();
        assertTrue(svg.startsWith("<svg"));
        assertTrue(svg.contains("stroke-dasharray=\"6 4\""), "rapids dashed");
        assertTrue(svg.contains(">E305 line 5</text>"), "finding marked with its line: " + svg);
        assertEquals(4, svg.split("<polyline").length - 1);
        assertTrue(svg.trim().endsWith("</svg>"));
    }

    @Test
    void traceListsEachDirectiveWithPositionAndOutputs() throws Exception {
        StringBuilder trace = new StringBuilder();
        SimFixture f = new SimFixture(SimFixture.PROFILE, SimOptions.defaults().withTrace(trace));
        f.start();
        f.move(true, 22, 102);
        String[] lines = trace.toString().split("\n");
        assertEquals("CB2\t; L1 X90 Z250 T0 outputs all off", lines[6]);
        assertEquals("SB1\t; L1 X90 Z250 T0 outputs on 1", lines[7]);
        assertEquals("BGS\t; L2 X22 Z102 T0 outputs on 1", lines[11]);
        assertFalse(trace.toString().contains("NaN"));
    }
}
