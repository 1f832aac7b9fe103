package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/**
 * The Haas one-block G76's A and P as the Fusion Haas post writes them (docs/threading.md): the
 * tool angle with a decimal point ({@code A60.}) is 60 degrees, as {@code A60}; P2 and P4 cut both
 * flanks in turn, P1 and P3 one flank. On the haas machine, metric, under M24 (straight pull-out) so
 * that each pass is one straight geared move.
 */
class HaasThreadWordsTest {
    private static final String START = "G21 G99\nT303\nG97 S700 M03\nG00 X30. Z5. M24\n";

    /** How far each thread pass ends back from Z-25. (mm, positive away from the chuck) and its diameter. */
    private static List<String> passEnds(Run r) {
        List<String> out = new ArrayList<>();
        for (CheckedBlock b : r.blocks) {
            for (Motion m : b.motions()) {
                if (m instanceof Motion.Thread t) {
                    double z = (t.to().z() - b.frame().origin().z()) / b.frame().perZ();
                    double x = (t.to().x() - b.frame().origin().x()) / b.frame().perX();
                    out.add(String.format(Locale.ROOT, "%.4f@X%.4f", z + 25, x));
                }
            }
        }
        return out;
    }

    private static Run g76(String words) {
        return Run.of("haas", START + "G76 X22.16 Z-25. K0.92 D0.35 " + words + " F1.5\nM30\n");
    }

    @Test
    void aToolAngleWithADecimalPointIsTheSameAngle() {
        Run point = g76("A60. P1");
        assertEquals("", point.errors());
        assertEquals(passEnds(g76("A60 P1")), passEnds(point));
        assertEquals("", g76("A0. P1").errors());
        assertEquals("", g76("A29.000 P3").errors());
        // a fraction of a degree, or more than 120, is not an angle the control takes
        assertEquals("5:30:E197", g76("A59.5 P1").errors());
        assertEquals("5:30:E197", g76("A121. P1").errors());
    }

    @Test
    void p1CutsOneFlankEveryPassBackByDepthTimesTanHalfTheAngle() {
        List<String> ends = passEnds(g76("A60 P1"));
        // 0.92 / 0.35: depths 0.35, 0.495, 0.606, 0.7, 0.783, 0.857, 0.92 (constant area)
        assertEquals(7, ends.size());
        assertEquals("0.2021@X23.3000", ends.get(0)); // 0.35 tan 30, X 22.16 + 2 (0.92 - 0.35)
        assertEquals("0.5312@X22.1600", ends.get(6)); // 0.92 tan 30 at the root
    }

    @Test
    void p2CutsBothFlanksInTurnAtConstantArea() {
        List<String> ends = passEnds(g76("A60 P2"));
        assertEquals(7, ends.size());
        // even passes on the front flank (back 0.35 tan 30), odd ones on the back flank (back (1.84 - 0.495) tan 30)
        assertEquals("0.2021@X23.3000", ends.get(0));
        assertEquals(String.format(Locale.ROOT, "%.4f@X%.4f", (1.84 - 0.35 * Math.sqrt(2)) * Math.tan(Math.toRadians(30)),
                22.16 + 2 * (0.92 - 0.35 * Math.sqrt(2))), ends.get(1));
        // the last pass at the full height, at the apex of the one-flank infeed's form: never past Z-25.
        assertEquals("0.5312@X22.1600", ends.get(6));
        for (String e : ends) {
            assertEquals(true, Double.parseDouble(e.substring(0, e.indexOf('@'))) > 0, e);
        }
    }

    @Test
    void p4CutsBothFlanksInTurnAtConstantDepth() {
        List<String> ends = passEnds(g76("A60 P4"));
        // 0.35, 0.70, 0.92: the front, the back, the apex
        assertEquals(List.of("0.2021@X23.3000", String.format(Locale.ROOT, "%.4f@X22.6000", 1.14 * Math.tan(Math.toRadians(30))),
                "0.5312@X22.1600"), ends);
        assertEquals(passEnds(g76("A60 P3")).size(), ends.size());
    }

    @Test
    void anotherInfeedIsNotOneTheControlTakes() {
        assertEquals("5:34:E197", g76("A60 P5").errors());
        assertEquals("5:34:E197", g76("A60 P0").errors());
    }
}
