package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * Haas G84/G184 tapping on the spindle axis (docs/cycles.md, "G84, G184"): the tap fed in, the
 * spindle reversed at the bottom, fed out to the R plane, the spindle turned back; the golden
 * src/test/resources/cycles/tapping.haas.* has the whole moves and DMC.
 */
class TappingTest {
    private static final String HEAD = "G20 G98\nT101\nG97 S300 M03\nG00 X0. Z0.5\n";
    /** A Fanuc G83 from the initial level Z5 to Z-12, R point Z2, pecks of 5: rapids (G00) and feeds (G01) to these Z. */
    private static final List<String> G83_PECKS = List.of("G00 2", "G01 -3", "G00 2", "G00 -2", "G01 -8", "G00 2",
            "G00 -7", "G01 -12", "G00 5");

    /** The moves of the blocks at {@code line} as "G00 z" or "G01 z", z in mm (the fanuc machine's work Z). */
    private static List<String> zMoves(Run r, int line) {
        return r.blocks.stream().filter(b -> b.line() == line).flatMap(b -> b.motions().stream())
                .map(m -> ((gcnc.ir.Motion.Linear) m)).map(l -> (l.rapid() ? "G00 " : "G01 ")
                        + Math.round((l.to().z() - 50000) / 500.0)).toList();
    }

    private static Run fanucB(String program) {
        return Run.of(Run.profileWithControl("fanuc", "fanuc-b"), program, Checker.ERROR_CAP);
    }

    /** The spindle M functions of the blocks at {@code line}, in order, as thesis numbers (M03 = 3). */
    private static String spindle(Run r, int line) {
        return r.blocks.stream().filter(b -> b.line() == line).flatMap(b -> java.util.stream.Stream.concat(
                b.before().stream(), b.after().stream())).map(MCall::code).map(String::valueOf)
                .collect(Collectors.joining(" "));
    }

    @Test
    void theSpindleReversesAtTheBottomAndTurnsBackAtTheRPlane() {
        Run r = Run.of("haas", HEAD + "G84 X0. Z-0.6 R0.2 P0 F15.\nG80\nM30\n");
        assertEquals("", r.errors());
        assertEquals("4 3", spindle(r, 5)); // M04 at the bottom, M03 once out
        List<CheckedBlock> tap = r.blocks.stream().filter(b -> b.line() == 5 && !b.motions().isEmpty()).toList();
        assertEquals(4, tap.size()); // rapid to R, feed in, feed out, rapid back
        // G184 (left-hand) under M04: M03 at the bottom, M04 back
        Run left = Run.of("haas", "G20 G98\nT101\nG97 S300 M04\nG00 X0. Z0.5\nG184 X0. Z-0.6 R0.2 F15.\nG80\nM30\n");
        assertEquals("", left.errors());
        assertEquals("3 4", spindle(left, 5));
    }

    @Test
    void aTapAgainstTheSpindleWarnsAndPeckTappingIsNotSupportedYet() {
        Run against = Run.of("haas", "G20 G98\nT101\nG97 S300 M04\nG00 X0. Z0.5\nG84 X0. Z-0.6 R0.2 F15.\nG80\nM30\n");
        assertEquals("5:1:E629", against.errors()); // a warning: the control runs it
        assertEquals("", Run.of("haas", HEAD + "G84 X0. Z-0.6 R0.2 F15.\nG80\nM30\n").errors());
        // the Fusion posts' "tapping with chip breaking" writes Q
        assertEquals("5:23:E188", Run.of("haas", HEAD + "G84 X0. Z-0.6 R0.2 P0 Q0.1 F15.\nG80\nM30\n").errors());
        assertEquals("5:20:E180", Run.of("haas", HEAD + "G84 X0. Z-0.6 R0.2 P-1 F15.\nG80\nM30\n").errors());
    }

    /**
     * Fanuc G83/G84 on the centre line (control key cycle.drill_words = fanuc): R is the distance
     * from the initial level to the R point (fanuc-a), Q the peck in least increments without a
     * point, a length with one; what needs live
     * tooling (C, H), W, K repeats and peck tapping are not supported yet (E188).
     */
    @Test
    void fanucG83AndG84OnTheCentreLine() {
        String head = "G21 G99\nT0101\nG97 S300 M03\nG00 X0. Z5.\n";
        Run r = Run.of("fanuc", head + "G83 Z-12. R-3. Q5000 F0.1\nG80\nG84 Z-10. R-3. F1.\nG80\nM30\n");
        assertEquals("", r.errors());
        // the R point at Z2 (3 below the initial Z5), two pecks of 5 and the last 4, the tap reversing
        assertEquals(G83_PECKS, zMoves(r, 5));
        assertEquals("4 3", spindle(r, 7));
        // Q with a point is a length in the program's unit (the Fusion fanuc post writes Q2.5)
        Run point = Run.of("fanuc", head + "G83 Z-12. R-3. Q5. F0.1\nG80\nM30\n");
        assertEquals("", point.errors());
        assertEquals(G83_PECKS, zMoves(point, 5));
        assertEquals("5:5:E188", Run.of("fanuc", head + "G83 C90. Z-12. R-3. F0.1\nM30\n").errors());
        assertEquals("5:5:E188", Run.of("fanuc", head + "G83 W-12. R-3. F0.1\nM30\n").errors());
        // repeats of a whole number are followed (BoringCyclesTest); K2.5 is not a count
        assertEquals("5:21:E188", Run.of("fanuc", head + "G83 Z-12. R-3. F0.1 K2.5\nM30\n").errors());
        assertEquals("5:16:E188", Run.of("fanuc", head + "G84 Z-10. R-3. Q1000 F1.\nM30\n").errors());
    }

    /**
     * fanuc-b (cycle.drill_r = absolute, parameter RAB): in G90 R is the R point's Z, as the Fusion
     * fanuc post writes "G90 G98 G83 X0. Z-12. R2. Q5."; in G91 Z is the distance from the R point
     * (not supported yet, E188). G98 returns to the initial level, G99 to the R point (drill and tap).
     */
    @Test
    void fanucBReadsRAsTheRPointsZAndReturnsToTheLevelOfG98OrG99() {
        String head = "G21 G95\nT0101\nG97 S300 M03\nG90 G00 X0. Z5.\n";
        Run g98 = fanucB(head + "G90 G98 G83 X0. Z-12. R2. Q5. F0.1\nG80\nM30\n");
        assertEquals("", g98.errors());
        assertEquals(G83_PECKS, zMoves(g98, 5));
        // in G91 Z is the distance from the R point to the bottom, which gcnc does not read yet (as W on fanuc-a)
        assertEquals("5:13:E188", fanucB(head + "G91 G98 G83 Z-17. R-3. Q5. F0.1\nM30\n").errors());
        Run g99 = fanucB(head + "G99 G83 X0. Z-12. R2. Q5000 F0.1\nG80\nM30\n");
        assertEquals("", g99.errors());
        List<String> toR = new java.util.ArrayList<>(G83_PECKS);
        toR.set(toR.size() - 1, "G00 2");
        assertEquals(toR, zMoves(g99, 5));
        // a hole drilled again after G99 starts at the R point; under G98 it returns to the initial
        // level the cycle was commanded at (Z5), not to where it started (Z2)
        Run again = fanucB(head + "G99 G83 X0. Z-12. R2. Q5000 F0.1\nG98\nZ-14.\nG80\nM30\n");
        assertEquals("", again.errors());
        assertEquals(List.of("G01 -3", "G00 2", "G00 -2", "G01 -8", "G00 2", "G00 -7", "G01 -13", "G00 2", "G00 -12",
                "G01 -14", "G00 5"), zMoves(again, 7));
        // the tap: in to the bottom, out to the R point, then to the initial level only under G98
        Run tap98 = fanucB(head + "G98 G84 X0. Z-10. R2. P0 F1.25\nG80\nM30\n");
        assertEquals("", tap98.errors());
        assertEquals(List.of("G00 2", "G01 -10", "G01 2", "G00 5"), zMoves(tap98, 5));
        Run tap99 = fanucB(head + "G99 G84 X0. Z-10. R2. P0 F1.25\nG80\nM30\n");
        assertEquals(List.of("G00 2", "G01 -10", "G01 2"), zMoves(tap99, 5));
        // the R point beyond the bottom is still E187 in absolute R
        assertEquals("5:23:E187", fanucB(head + "G90 G98 G83 X0. Z-12. R-13. Q5. F0.1\nM30\n").errors());
    }

    /** Fanuc M29 S (rigid tapping, the Fusion fanuc post's startSpindle tappingMode): accepted with note E720 on both systems. */
    @Test
    void fanucM29IsRigidTappingWithANote() {
        String tap = "M29 S300\nG84 Z-10. R-3. P0 F1.25\nG80\nM30\n";
        Run a = Run.of("fanuc", "G21 G99\nT0101\nG97 S300 M03\nG00 X0. Z5.\n" + tap);
        assertEquals("5:1:E720", a.errors());
        assertEquals(gcnc.diag.Severity.NOTE, a.diagnostics.sorted().get(0).severity());
        Run b = fanucB("G21 G95\nT0101\nG97 S300 M03\nG90 G00 X0. Z5.\n" + tap.replace("R-3.", "R2."));
        assertEquals("5:1:E720", b.errors());
        // haas has no M29: an undefined M code stays an error there
        assertEquals("5:1:E012", Run.of("haas", HEAD + "M29 S300\nM30\n").errors());
    }
}
