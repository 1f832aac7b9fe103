package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A thread pass on the virtual Galil, on a clock the test turns: the spindle encoder turns at OF ×
 * the drive's rate, the pass waits for the next whole revolution ({@code MF} on the sync variable),
 * Z follows the encoder at its gear ratio ({@code GA}, {@code GR}), the ratios change at a trippoint
 * ({@code MR}), {@code GR 0,0} disengages and {@code PA}/{@code BG}/{@code AM} settle on the end counts.
 */
class VirtualThreadTest {
    /** 600 r/min at 410 r/min a volt on a 4,096-count encoder: 40,960 counts/s. */
    static final double VOLTS = 600 / 410.0;

    private final StringWriter trace = new StringWriter();
    private final VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), trace);

    private String ok(String command) throws GalilException {
        return c.command(command);
    }

    private double operand(String name) throws GalilException {
        return c.operand(name);
    }

    @Test
    void theSpindleEncoderTurnsAtTheOffsetsSpeed() throws GalilException {
        ok("SH XYC");
        ok("VM XY");
        ok(String.format(java.util.Locale.ROOT, "OF ,,%.4f", VOLTS));
        c.advance(1.0);
        assertEquals(40_960, operand("TPC"), 2, "one second at 600 r/min: 10 revolutions of 4,096 counts");
        ok("OF ,,0");
        double stopped = operand("TPC");
        c.advance(0.5);
        assertEquals(stopped, operand("TPC"), "0 V: the spindle stands");
    }

    @Test
    void aPassIsGearedToTheSpindleFromAWholeRevolutionAndSettlesOnItsEnd() throws GalilException {
        ok("SH XYC");
        ok("VM XY");
        ok(String.format(java.util.Locale.ROOT, "OF ,,%.4f", VOLTS));
        c.advance(0.0123); // the spindle somewhere in a revolution
        c.download(String.join("\r", "#PASS", "GA C,C", "gsp=(@INT[_TPC/4096]+1)*4096", "MF ,,gsp",
                "GR -0.3604,0.0000", "MR -8000", "GR -0.3604,0.3604", "MR -10000", "GR 0,0", "PA -10000,700",
                "BG XY", "AM XY", "EN"), false);
        ok("XQ #PASS");
        c.advance(0.001);
        double gsp = c.variable("gsp");
        assertEquals(0, gsp % 4096, "the next whole revolution");
        assertTrue(gsp > operand("TPC"), "ahead of the encoder");
        assertEquals(0, operand("TPX"), "not geared before the sync point");
        boolean followed = false;
        while (operand("XQ0") >= 0) {
            c.advance(0.001);
            double x = c.motion.position[0];
            double y = c.motion.position[1];
            if (x < -100 && x > -7900) {
                // Z (X here) moves -0.3604 counts per encoder count from the sync point, within the
                // travel of the sample past it and the 2 samples the MF trip may be late (COMALL MF)
                assertEquals(-0.3604 * (c.motion.position[2] - gsp), x, 0.3604 * 41 * 3 + 1);
                assertEquals(0, y, "X (Y here) waits for the pull-out's corner");
                followed = true;
            }
            assertTrue(c.time() < 5, "the pass ends");
        }
        assertTrue(followed);
        assertEquals("-10000, 700", ok("TP XY").strip());
        assertEquals(0, operand("BGX"));
        assertTrue(trace.toString().contains("\n1 1 PA -10000 700 511 "), trace.toString());
        assertTrue(trace.toString().contains("# pass 1 at -10000,700"), trace.toString());
        assertEquals("0\r\n", ok("TC1"), "without an error");
    }

    @Test
    void gearingWithoutAMasterAndABeginOnAGearedAxisAreRefused() throws GalilException {
        ok("SH XYC");
        ok("VM XY");
        assertEquals(Tc.OPERAND, assertThrows(GalilException.class, () -> ok("GR 0.5,0.5")).tc, "GR before GA");
        ok("GA C,C");
        ok("GR 0.5,0.5");
        assertEquals(Tc.WHILE_RUNNING, assertThrows(GalilException.class, () -> ok("BG XY")).tc, "a geared axis is moving");
        ok("ST");
        ok("PA 10,10");
        ok("BG XY");
        c.settle(1);
        assertFalse(c.moving());
        assertEquals("10, 10", ok("TP XY").strip());
    }
}
