package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * A contour block a cycle reads (G71's N10..N20) makes no block of its own, yet the cycle's passes run
 * with its line's name: its positions are in the frame in force, so that the status line and a refusal
 * (E827) give program terms there too, not Galil counts alone (issue 33).
 */
class CycleLineTermsTest {
    /** Line 7 the G71, lines 8 to 10 its contour (N10 to N20), which the G70 of line 11 follows under their own lines. */
    static final String G71 = String.join("\n", "O1007", "G21 G99", "G50 S2500", "T0101", "G97 S1200 M03",
            "G00 X52. Z2.", "G71 P10 Q20 U0.4 W0.1 D1.5 F0.25", "N10 G00 X40.", "G01 Z-20.", "N20 X52.",
            "G70 P10 Q20 F0.1", "G00 X60. Z5.", "M05", "M30", "");

    @Test
    void aContourLineOfACycleHasTheFrameInForce() throws Exception {
        ResumeTest.Compiled c = ResumeTest.compiled(G71);
        BlockTable.Block cycle = c.blocks().at(7);
        BlockTable.Block contour = c.blocks().at(9); // G01 Z-20.
        assertNotNull(contour.frame(), "the contour line is shown in program terms");
        assertEquals(cycle.frame().origin(), contour.frame().origin());
        assertEquals(cycle.frame().perX(), contour.frame().perX());
        assertTrue(c.program().firstLineOf(9) >= 0, "G70 runs line 9's segment under its name");
        // a refusal there names the axes as the program writes them, the counts after them
        RunFault f = c.refusal(9, c.galil(9, 30, -15));
        assertTrue(f.args().get(1).startsWith("the axes are at X30.000 Z-15.000 (Galil counts "
                + PositionText.counts(c.galil(9, 30, -15)) + ")"), f.args().get(1));
    }
}
