package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.dmc.Command;
import gcnc.machine.ControllerLimits;
import gcnc.machine.GalilModels;
import org.junit.jupiter.api.Test;

/**
 * The compiler's and the simulator's side of Galil's worked examples (tables/galil_conformance.csv; the
 * virtual controller's side is gcnc.controller.ManualExamplesTest): the arc a CR draws, worked out in
 * Command.CircularArc.geometry for the simulator's replay and the virtual controller alike, and VA as the
 * controller takes it.
 */
class ManualGeometryTest {
    /** M40x0-87: VP 0,10000 / CR 10000,180,-90 / VP 20000,20000, the last segment 10000 long. */
    @Test
    void theUserManualsVpCrVpExampleEndsWhereItsFigureDoes() {
        double[] arc = Command.CircularArc.geometry(0, 10000, 10000, 180, -90);
        assertArrayEquals(new double[] {10000, 10000, 10000, 20000}, arc, 1e-9, "centre, then end");
        assertEquals(10000, Math.hypot(20000 - arc[2], 20000 - arc[3]), 1e-9, "C to D");
    }

    /** COMALL CR: "A starting position of zero degrees denotes that the radius lies along a vector following the positive X axis"; CR 1000,0,270. */
    @Test
    void zeroDegreesIsAlongPositiveXAndPositiveSweepIsCounterClockwise() {
        assertArrayEquals(new double[] {-1000, 0, -1000, -1000}, Command.CircularArc.geometry(0, 0, 1000, 0, 270), 1e-9);
        assertArrayEquals(new double[] {-1000, 0, -1000, 1000}, Command.CircularArc.geometry(0, 0, 1000, 0, -270), 1e-9,
                "-n2 denotes clockwise");
    }

    /** COMALL VA: ":VA 20000 ... :VA ? ... 19456": gcnc writes, and the simulator times, the value the controller keeps. */
    @Test
    void vectorAccelerationIsTakenAsTheControllerKeepsIt() {
        ControllerLimits dmc4040 = new ControllerLimits(GalilModels.builtIn().find("DMC-4040").orElseThrow());
        assertEquals(19456, dmc4040.roundAcceleration(20000).taken());
        assertEquals(1024, dmc4040.roundAcceleration(1024).taken());
    }
}
