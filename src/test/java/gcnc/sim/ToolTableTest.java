package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Diagnostic;
import gcnc.diag.GnuRenderer;
import gcnc.machine.MachineModel;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.ErrorMessages;
import gcnc.tables.Tables;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The tool table's stations in the simulator (docs/simulator.md, "Tool"): drills, centre drills
 * and taps on the centreline, a tool on the -X side of a gang lathe, and a station the profile does
 * not describe, which is warned of once and whose findings say what they rest on. The tiny machine
 * of {@link SimFixture}: 1 count per mm, X a radius, the blank r 20 from z -20 to its face at z 100.
 */
class ToolTableTest {
    private static final String TOOLS = """
            station.1 = turn C 12.7
            station.4 = drill 10
            station.5 = drill 8.5
            station.6 = centre 4
            station.7 = tap 10
            station.8 = turn C 6.35, side -x
            """;

    private static SimFixture fixture(String tools) throws Exception {
        // no tailstock: the tools on the centreline work where its centre would be
        return new SimFixture(SimFixture.PROFILE.replace("x.travel = -2, 100", "x.travel = -60, 100")
                .replace("tailstock.centre_z = 200\n", "").replace("tailstock.quill_diameter = 30\n", "") + tools,
                SimOptions.defaults());
    }

    private static MachineModel.ToolOutline tool(String line) throws Exception {
        return ProfileLoader.read(ProfileFile.parse("t.machine", SimFixture.PROFILE + line + "\n"), Tables.builtIn())
                .model().tools().get(Integer.parseInt(line.replaceAll("^station\\.([0-9]+).*", "$1")));
    }

    @Test
    void aDrillIsOnTheCentrelineWithA118DegreePoint() throws Exception {
        MachineModel.ToolOutline d = tool("station.4 = drill 10");
        assertEquals(MachineModel.ToolKind.DRILL, d.kind());
        // the point: 5 mm radius over 5 / tan(59°) = 3.004 mm of Z, symmetric about the centreline
        assertEquals(0, d.insert().dz()[0]);
        assertEquals(0, d.insert().dx()[0]);
        assertEquals(5 / Math.tan(Math.toRadians(59)), d.insert().dz()[1], 1e-9);
        assertEquals(5, d.insert().dx()[1], 1e-9);
        assertEquals(-5, d.insert().dx()[4], 1e-9);
        assertEquals(50, d.insert().dz()[2], 1e-9, "the flutes: 5 x the diameter unless a reach is given");
        assertEquals(80, tool("station.4 = drill 10, reach 80").insert().dz()[2], 1e-9);
        assertEquals(5 / Math.tan(Math.toRadians(70)), tool("station.4 = drill 10, angle 140").insert().dz()[1], 1e-9);
    }

    @Test
    void aCentreDrillAndATapHaveTheirShapes() throws Exception {
        MachineModel.ToolOutline c = tool("station.6 = centre 4");
        assertEquals(MachineModel.ToolKind.CENTRE_DRILL, c.kind());
        // the body behind the 60° countersink is 2.5 x the pilot: 5 mm in radius
        assertEquals(5, c.insert().dx()[2], 1e-9);
        MachineModel.ToolOutline t = tool("station.7 = tap 10");
        assertEquals(MachineModel.ToolKind.TAP, t.kind());
        // its end, 8 mm across, is at the tip; the full 10 mm from 3 mm behind it
        assertEquals(4, t.insert().dx()[1], 1e-9);
        assertEquals(5, t.insert().dx()[2], 1e-9);
        assertEquals(3, t.insert().dz()[2], 1e-9);
    }

    @Test
    void drillingOnTheCentrelineIsCleanAndDeeperThanTheFlutesPutsTheHolderIn() throws Exception {
        SimFixture f = fixture(TOOLS);
        f.start();
        f.block(List.of(), "TOOL=4");
        f.move(true, 0, 105);
        f.move(false, 0, 70);                // line 4: 30 mm deep, the flutes are 50
        f.move(true, 0, 105);
        assertEquals(List.of(), f.codes());
        f.move(false, 0, 40);                // line 6: 60 mm deep: the collet meets the face
        assertEquals(List.of("E315@6"), f.codes());
    }

    @Test
    void aDrillMovedSidewaysInThePartIsFound() throws Exception {
        SimFixture f = fixture(TOOLS);
        f.start();
        f.block(List.of(), "TOOL=4");
        f.move(true, 0, 105);
        f.move(false, 0, 80);
        f.move(false, 8, 80);                // line 5: sideways 8 mm, its margin into the wall
        assertEquals(List.of("E323@5"), f.codes());
    }

    @Test
    void aTapCutsIntoItsDrilledHoleAndNotIntoSolidMaterial() throws Exception {
        SimFixture f = fixture(TOOLS);
        f.start();
        f.block(List.of(), "TOOL=5");        // the tap drill, 8.5 mm
        f.move(true, 0, 105);
        f.move(false, 0, 80);
        f.move(true, 0, 105);
        f.block(List.of(), "TOOL=7");        // line 6: M10 tap
        f.move(true, 0, 102);
        f.move(false, 0, 85);                // line 8: into the hole
        f.move(true, 0, 105);
        assertEquals(List.of(), f.codes());
        SimFixture solid = fixture(TOOLS);
        solid.start();
        solid.block(List.of(), "TOOL=7");
        solid.move(true, 0, 105);
        solid.move(false, 0, 90);            // line 4: no hole: its end meets the face
        assertEquals(List.of("E323@4"), solid.codes());
    }

    @Test
    void aCentreDrillCutsItsPilotAndCountersinkOnly() throws Exception {
        SimFixture f = fixture(TOOLS);
        f.start();
        f.block(List.of(), "TOOL=6");
        f.move(true, 0, 103);
        f.move(false, 0, 94);                // line 4: 6 mm into the face: pilot and countersink
        f.move(true, 0, 103);
        f.move(true, 0, 95);                 // line 6: a rapid back into the centre hole: clean
        assertEquals(List.of(), f.codes());
        f.move(true, 3, 95);                 // line 7: sideways out of it: the countersink's edge in the face
        assertEquals(List.of("E305@7"), f.codes());
    }

    @Test
    void aToolOnTheMinusXSideCutsThePartMirrored() throws Exception {
        SimFixture f = fixture(TOOLS);
        f.start();
        f.block(List.of(), "TOOL=8");
        f.move(true, -25, 102);
        f.move(true, -18, 102);
        f.move(false, -18, 80);              // line 5: a 2 mm pass from the -X side: clean
        f.move(true, -25, 80);
        f.move(true, -25, 102);
        f.move(true, -18, 102);
        f.move(true, -18, 80);               // line 9: a rapid back along the cut: clean
        assertEquals(List.of(), f.codes());
        f.move(true, -18, 60);               // line 10: a rapid on into uncut material
        assertEquals(List.of("E305@10"), f.codes());
    }

    @Test
    void aTurningInsertPlungedDeeperThanItStandsMeetsTheWallWithItsHolderHead() throws Exception {
        // the C 12.7 stands 15.1 mm above its tip; its holder's head reaches 3 mm past it toward the tailstock
        SimFixture f = fixture(TOOLS);
        f.start();
        f.block(List.of(), "TOOL=1");
        f.move(true, 25, 60);
        f.move(false, 10, 60);               // line 4: 10 mm into the r 20 bar: the insert cuts it all
        f.move(true, 25, 60);
        assertEquals(List.of(), f.codes());
        f.move(false, 2, 60);                // line 6: 18 mm: the head meets the wall on the tailstock side
        assertEquals(List.of("E315@6"), f.codes());
    }

    @Test
    void anUndescribedStationIsWarnedOnceAndItsFindingsSaySo() throws Exception {
        SimFixture f = fixture(TOOLS);
        f.start();
        f.block(List.of(), "TOOL=9");        // line 2: not in the table
        f.move(true, 30, 102);
        f.block(List.of(), "TOOL=1");
        f.block(List.of(), "TOOL=9");        // again: no second warning
        f.move(true, 17, 102);
        f.move(false, 17, 60);               // line 7: 3 mm deep: the default insert (6 tall) cuts it
        f.move(false, 5, 60);                // line 8: 12 mm more: the default's holder in the stock
        assertEquals(List.of("E321@2", "E315@8"), f.codes());
        GnuRenderer en = new GnuRenderer(Tables.builtIn().messages().in(ErrorMessages.Lang.EN));
        Diagnostic e315 = f.diagnostics.sorted().get(1);
        assertTrue(en.render("p.nc", e315).contains("tool 9 (assumed: the default outline; station 9 is not described)"),
                en.render("p.nc", e315));
        GnuRenderer es = new GnuRenderer(Tables.builtIn().messages().in(ErrorMessages.Lang.ES));
        assertTrue(es.render("p.nc", e315).contains("(supuesta: la predeterminada outline; la estación 9 no está descrita)"),
                es.render("p.nc", e315));
    }

    @Test
    void withNoDefaultToolAnUndescribedStationIsCheckedAtItsTipOnly() throws Exception {
        String noDefault = SimFixture.PROFILE.replaceAll("(?m)^sim\\.tool\\.default.*$", "") + TOOLS;
        SimFixture f = new SimFixture(noDefault, SimOptions.defaults());
        f.start();
        f.block(List.of(), "TOOL=3");        // line 2
        f.move(true, 30, 102);
        f.move(false, 15, 102);
        f.move(false, 15, 60);               // the tip cuts; no holder to check
        assertEquals(List.of("E322@2"), f.codes());
    }
}
