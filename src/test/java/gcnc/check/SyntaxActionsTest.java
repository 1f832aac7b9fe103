package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import java.util.List;
import org.junit.jupiter.api.Test;

/** One tiny program per thesis syntax action (tables/syntax_actions.csv asks for saNN here). */
class SyntaxActionsTest {
    static final String PRE = "G21 G90 G98\nG50 S2500\nM11\nT0101\nS1200 M03\n";

    @Test
    void sa01() {
        Run r = Run.generic("G91 G00 U10.\nM30");
        assertEquals("", r.errors());
        assertEquals(new Point(105000 + 5000, 340000), r.line(1).end());
        assertEquals("1:5:E016", Run.generic("G00 G01 X1.\nM30").errors());
    }

    @Test
    void sa02() {
        assertEquals("", Run.generic("N5 G00 X40.\nN6 M30").errors());
        assertEquals("1:9:E007", Run.generic("G00 X1. X2.\nM30").errors());
        assertEquals("2:1:E043", Run.generic("N5\nN5\nM30").errors());
    }

    @Test
    void sa03() {
        Run r = Run.generic("O7 F100.\nM30");
        assertEquals("", r.errors());
        assertEquals(100, r.checker.state().feed(), 1e-12);
        assertEquals("1:5:E007", Run.generic("F1. F2.\nM30").errors());
        assertEquals("2:1:E034", Run.generic("G21\nO5\nM30").errors());
    }

    @Test
    void sa04() {
        Run r = Run.generic("T0303\nM30");
        assertEquals(3, r.checker.state().tool());
        assertEquals(3, r.checker.state().toolOffset());
        assertEquals(3, r.line(1).tool().getAsInt());
        Run one = Run.generic("T1\nM30");
        assertEquals(1, one.checker.state().toolOffset());
        assertEquals("1:1:E046", Run.generic("T9901\nM30").errors());
    }

    @Test
    void sa05() {
        Run r = Run.generic("G04 P250\nM30");
        assertEquals(List.of(new Motion.Dwell(0.25)), r.line(1).motions());
        assertEquals("1:5:E017", Run.generic("G28 G04 X1.\nM30").errors());
    }

    @Test
    void sa06() {
        Run r = Run.generic("G00 X40. Z0.\nG28 U0.\nM30");
        assertEquals(2, r.line(2).motions().size());
        assertEquals("1:5:E018", Run.generic("G04 G28 U0.\nM30").errors());
    }

    @Test
    void sa07() {
        Run r = Run.generic("G00 X40. Z0.\nG28 U0.\nG29 X30.\nM30");
        assertEquals(new Point(15000, 150000), r.line(3).end());
        assertEquals("1:5:E019", Run.generic("G04 G29 U0.\nM30").errors());
    }

    @Test
    void sa08() {
        Run r = Run.generic("G50 S900\nM30");
        assertEquals(900, r.checker.state().rpmClamp(), 0.0001);
        assertEquals("1:5:E020", Run.generic("G04 G50 S100\nM30").errors());
    }

    @Test
    void sa09() {
        Run r = Run.generic("G92 X10. Z10.\nG00 X10. Z10.\nM30");
        assertEquals(new Point(105000, 340000), r.line(2).end());
        assertEquals("1:5:E020", Run.generic("G28 G92 X1.\nM30").errors());
    }

    @Test
    void sa10() {
        Run r = Run.generic("G00 X40.\nG31 Z5.\nM30");
        assertEquals("", r.errors());
        assertEquals(new Point(20000, 155000), r.line(2).end());
    }

    @Test
    void sa11() {
        Run r = Run.generic("G09 G00 X40.\nM30");
        assertEquals("", r.errors());
        assertEquals(1, r.line(1).motions().size());
    }

    @Test
    void sa12() {
        Run r = Run.generic("G50 S900\nM11\nM08 M03 M09\nM30");
        assertEquals("3:9:E016", r.errors());
        Run ok = Run.generic("G50 S900\nM11\nM05 M03 M08\nM30");
        assertEquals("3:5:E016", ok.errors());
        Run order = Run.generic("M09 M11 M08\nM30");
        assertEquals("1:9:E016", order.errors());
        Run split = Run.generic("M09 M11 M03\nM30");
        assertEquals(List.of(new MCall(11), new MCall(3)), split.line(1).before());
        assertEquals(List.of(new MCall(9)), split.line(1).after());
        assertEquals("6:1:E040", Run.generic(PRE + "M10\nM30").errors());
    }

    @Test
    void sa13() {
        Run r = Run.generic(PRE + "G96 S100\nG97 S800\nM30");
        assertEquals("", r.errors());
        assertTrue(!r.checker.state().css());
        assertEquals(800, r.line(7).spindleRpm().getAsDouble(), 1e-9);
        assertEquals("6:5:E016", Run.generic(PRE + "G96 G97 S800\nM30").errors());
    }

    @Test
    void sa14() {
        Run r = Run.generic(PRE + "G40 G96 S100\nM30");
        assertEquals("", r.errors());
        assertTrue(r.checker.state().css());
        assertEquals("6:5:E016", Run.generic(PRE + "G96 G97 S100\nM30").errors());
    }

    @Test
    void sa15() {
        Run r = Run.generic("M30");
        assertEquals("", r.errors());
        assertTrue(r.checker.state().ended());
        assertEquals("1:1:E052, 1:5:E016", Run.generic("M02 M30").errors());
        assertEquals("2:1:E053", Run.generic("M30\nG21").errors());
    }
}
