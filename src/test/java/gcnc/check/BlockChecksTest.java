package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.check.block.BlockCheck;
import gcnc.check.block.BlockChecks;
import gcnc.ir.Point;
import org.junit.jupiter.api.Test;

/** One tiny program per end-of-block operation (tables/block_checks.csv asks for ebNN here). */
class BlockChecksTest {
    static final String PRE = "G21 G90 G98\nG50 S2500\nM11\nT0101\nS1200 M03\n";

    @Test
    void orderIsTheThesisChkParametersOrder() {
        StringBuilder sb = new StringBuilder();
        for (BlockCheck c : BlockChecks.ORDER) {
            for (int n = 1; n <= 8; n++) {
                sb.append(BlockChecks.check(n) == c ? Integer.toString(n) : "");
            }
        }
        assertEquals("51432678", sb.toString());
    }

    @Test
    void eb01() {
        assertEquals("1:1:E044", Run.generic("X10.\nM30").errors());
        assertEquals("1:1:E032", Run.generic("P10\nM30").errors());
        assertEquals("1:5:E022", Run.generic("G04 Z1.\nM30").errors());
        Run modal = Run.generic("G00 X40.\nZ5.\nM30");
        assertEquals(new Point(20000, 155000), modal.line(2).end());
    }

    @Test
    void eb02() {
        Run r = Run.generic("G00 X40. Z0.\nG28 U10. W0.\nM30");
        assertEquals(new Point(25000, 150000), r.checker.state().g28());
        assertEquals("1:5:E015", Run.generic("G28 U500.\nM30").errors());
    }

    @Test
    void eb03() {
        assertEquals("1:1:E042", Run.generic("G29 U0.\nM30").errors());
        assertEquals("", Run.generic("G28 U0.\nG00 X40.\nG29 X40.\nM30").errors());
    }

    @Test
    void eb04() {
        assertEquals("1:1:E030", Run.generic("G04\nM30").errors());
        assertEquals("1:1:E031", Run.generic("G50\nM30").errors());
        assertEquals("6:1:E049", Run.generic(PRE + "G02 X46. F100.\nM30").errors());
    }

    @Test
    void eb05() {
        assertEquals("1:5:E035", Run.generic("G01 G04 X1.\nM30").errors());
    }

    @Test
    void eb06() {
        Run r = Run.generic("G50 S1500\nM30");
        assertEquals(1500, r.checker.state().rpmClamp(), 1e-9);
        assertEquals(false, r.line(1).spindleRpm().isPresent());
    }

    @Test
    void eb07() {
        assertEquals("1:1:E050", Run.generic("S100\nM30").errors());
        assertEquals("2:1:E048", Run.generic("G50 S1000\nS1001\nM30").errors());
        Run ok = Run.generic("G50 S1000\nS1000\nM30");
        assertEquals(1000, ok.line(2).spindleRpm().getAsDouble(), 1e-9);
    }

    @Test
    void eb08() {
        assertEquals("6:1:E039", Run.generic(PRE + "G01 X40.\nM30").errors());
        assertEquals("4:1:E038", Run.generic("G21 G90 G98\nG50 S2500\nS1200 M03\nG01 X40. F100.\nM30").errors());
        assertEquals("3:1:E051", Run.generic("G50 S2500\nM11\nG01 X40. F100.\nM30").errors());
        // a feed per minute with the spindle stopped is a cut only if it meets stock (compile decides: E306)
        assertEquals("4:1:E660", Run.generic("G50 S2500\nM11\nM05\nG01 X40. F100.\nM30").errors());
        // per revolution the axis cannot feed while the spindle stands: E037 as in the thesis
        assertEquals("5:1:E037", Run.generic("G50 S2500\nM11\nM05\nG99\nG01 X40. F0.2\nM30").errors());
        assertEquals("3:1:E041", Run.generic("M11\nM03\nG01 X40. F100.\nM30").errors());
        // M03 and M11 in the cutting block itself are applied before its motion
        assertEquals("", Run.generic("G50 S2500\nG01 X40. F100. M11 M03\nM30").errors());
        // M05 in the cutting block is applied after it
        assertEquals("", Run.generic(PRE + "G01 X40. F100. M05\nM30").errors());
    }
}
