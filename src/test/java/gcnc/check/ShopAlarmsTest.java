package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.check.geom.NoseGeometry;
import gcnc.diag.Diagnostic;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import org.junit.jupiter.api.Test;

/**
 * Issue 31, "an error only where the control alarms": blocks the control runs that gcnc stopped
 * on, each a tiny program as a shop writes it, with its finding (severity included) on the line.
 */
class ShopAlarmsTest {
    /** Lines 1-4 on a Fanuc: metric, feed per revolution, 800 r/min forward, at X30 Z5. */
    private static final String FANUC = "G21 G99\nT0707\nG97 S800 M03\nG00 X30. Z5.\n";
    /** Lines 1-4 on the haas machine: inch, feed per revolution, 700 r/min forward, at X0.6 Z0.2. */
    private static final String HAAS = "G20 G99\nT303\nG97 S700 M03\nG00 X0.6 Z0.2 M24\n";

    private static String found(Run r) {
        StringBuilder sb = new StringBuilder();
        for (Diagnostic d : r.diagnostics.sorted()) {
            sb.append(sb.length() > 0 ? ", " : "").append(d.span().line()).append(':').append(d.span().column())
                    .append(':').append(d.severity().name().toLowerCase()).append(' ').append(d.code().id());
        }
        return sb.toString();
    }

    private static int threads(Run r) {
        int n = 0;
        for (CheckedBlock b : r.blocks) {
            for (Motion m : b.motions()) {
                n += m instanceof Motion.Thread ? 1 : 0;
            }
        }
        return n;
    }

    @Test
    void aThreadDeeperThanTheSharpVIsCutWithAWarningThatSaysWhy() {
        // 1.1 mm on a 1.2 lead: above 0.866 x 1.2 = 1.039; the control cuts it
        Run f = Run.of("fanuc", FANUC + "G76 X22.16 Z-25. P1100 Q350 F1.2\nM30\n");
        assertEquals("5:18:warning E193", found(f));
        assertTrue(threads(f) > 1, "the passes are cut");
        Run h = Run.of("haas", HAAS + "G76 X0.4056 Z-0.75 K0.07 D0.012 F0.07692\nM30\n");
        assertEquals("5:20:warning E193", found(h));
        assertTrue(threads(h) > 1, "the passes are cut");
    }

    @Test
    void aThreadOfNoHeightIsTheControlsAlarm() {
        // Fanuc PS0062: zero or a negative thread height in G76
        assertEquals("5:18:E180", Run.of("fanuc", FANUC + "G76 X22.16 Z-25. P0 Q350 F1.2\nM30\n").errors());
        assertEquals("5:20:E180", Run.of("haas", HAAS + "G76 X0.4056 Z-0.75 K0. D0.012 F0.07692\nM30\n").errors());
    }

    @Test
    void blocksAfterM30AreOneWarningAndAreNotChecked() {
        // line 7 would be E039 (no F) if it were checked as running: it never runs
        Run r = Run.of("fanuc", FANUC + "M30\nG00 X100. Z50.\nG01 Z-5.\n(a note after the end)\nG00 X0\n");
        assertEquals("6:1:warning E053", found(r));
        assertEquals("6:1:warning E053", found(Run.of("haas", HAAS + "M30\nG00 X2.\nG01 Z-5.\n")));
    }

    @Test
    void aCompensatedArcThatRunsALittleLongerPassesTheControlsInterferenceCheck() {
        // an arc of 30 degrees about the centre line; its compensated copy (radius 12) from -5 to
        // 30 degrees runs the same way (Fanuc: interference only past 180 degrees off), one from 40
        // back to 10 degrees has been cut back past its other end: the control's PS0041
        NoseGeometry.Element arc = new NoseGeometry.Element(at(10, 0), at(10, 30), new Point(0, 0), 10, false);
        assertTrue(NoseGeometry.forward(arc, at(12, -5), at(12, 30)));
        assertTrue(NoseGeometry.forward(arc, at(12, 5), at(12, 25)));
        assertFalse(NoseGeometry.forward(arc, at(12, 40), at(12, 10)));
        NoseGeometry.Element line = new NoseGeometry.Element(new Point(0, 0), new Point(0, -10), null, 0, false);
        assertTrue(NoseGeometry.forward(line, new Point(1, 1), new Point(1, -12)));
        assertFalse(NoseGeometry.forward(line, new Point(1, -3), new Point(1, -1)));
    }

    /**
     * A school program in the Haas style (written for this test): a one-block G71 whose P block
     * has Z alone (N1 G01 Z0. then X down to the first diameter), its G70, a G76 and, after M30,
     * a G28 and set-up notes left in the file. The control runs all of it but the blocks after M30,
     * which never run: one warning, nothing else (issue 31).
     */
    @Test
    void aHaasSchoolProgramRunsCleanButForTheBlocksAfterM30() {
        String program =
            "O02468 (BUSHING - OP1)\n"
            + "(STOCK 1.5 DIA 6061)\n"
            + "(T1 CNMG ROUGH/FINISH  T3 THREAD 16 TPI)\n"
            + "G20 G18 G40 G99\n"
            + "G28 U0.\n"
            + "G28 W0.\n"
            + "T101\n"
            + "G50 S3000\n"
            + "G96 S450 M03\n"
            + "G00 X1.6 Z0.1 M08\n"
            + "G71 P1 Q2 U0.02 W0.005 D0.05 F0.008\n"
            + "N1 G01 Z0.\n"
            + "X0.625\n"
            + "X0.75 Z-0.0625\n"
            + "Z-0.875\n"
            + "X1.125\n"
            + "X1.25 Z-0.9375\n"
            + "Z-1.75\n"
            + "N2 X1.6\n"
            + "G70 P1 Q2 F0.004\n"
            + "G00 X3. Z3. M09\n"
            + "T303\n"
            + "G97 S800 M03\n"
            + "G00 X0.85 Z0.2\n"
            + "G76 X0.6733 Z-0.7 K0.0406 D0.012 F0.0625\n"
            + "G00 X3. Z3.\n"
            + "M05\n"
            + "M30\n"
            + "G28 U0. W0.\n"
            + "(EXTRA SETUP NOTES BELOW)\n"
            + "T0100\n";
        Run h = Run.of("haas", program);
        assertEquals("29:1:warning E053", found(h));
        assertTrue(threads(h) > 1, "the thread is cut");
        // on a Fanuc the same P block is alarm PS0065, and the rest still runs
        assertEquals("12:1:error E155, 29:1:warning E053", found(Run.of("fanuc", program)));
    }

    /**
     * A Fanuc shop program (written for this test, in the style of a two-block-cycle post): G71
     * roughing, G42 on its own block before the G70, a two-block G76 cut 1.3 mm deep on a 1.5 lead
     * (past the sharp V's 1.299: the control cuts it) and an old tool change left after M30. The
     * control runs it all but the blocks after M30: two warnings on their lines, nothing else.
     */
    @Test
    void aFanucShopProgramWithADeepThreadAndAFinishUnderG42RunsWithTwoWarnings() {
        String program =
            "O1234 (SHAFT M24X1.5)\n"
            + "G21 G40 G99\n"
            + "G28 U0. W0.\n"
            + "T0101\n"
            + "G50 S2500\n"
            + "G96 S200 M03\n"
            + "G00 X42. Z2. M08\n"
            + "G71 U1.5 R0.5\n"
            + "G71 P100 Q200 U0.4 W0.1 F0.25\n"
            + "N100 G00 X20.\n"
            + "G01 Z0. F0.15\n"
            + "X24. Z-2.\n"
            + "Z-30.\n"
            + "X36.\n"
            + "Z-45.\n"
            + "N200 X42.\n"
            + "G42\n"
            + "G70 P100 Q200\n"
            + "G40 G00 X100. Z100. M09\n"
            + "T0303\n"
            + "G97 S600 M03\n"
            + "G00 X26. Z5.\n"
            + "G76 P020060 Q100 R0.05\n"
            + "G76 X21.4 Z-26. P1300 Q400 F1.5\n"
            + "G00 X100. Z100.\n"
            + "M05\n"
            + "M30\n"
            + "T0202\n";
        Run r = Run.of("fanuc", program);
        assertEquals("24:17:warning E193, 28:1:warning E053", found(r));
        assertTrue(threads(r) > 1, "the thread is cut");
        assertTrue(r.blocks.stream().anyMatch(b -> b.line() == 18 && !b.motions().isEmpty()), "G70 finishes");
    }

    /** A G71 roughing and its G70, metric, on the fanuc machine from X52 Z2 (lines 1-14). */
    private static final String ROUGH_AND_FINISH = "G21 G99\nT0101\nG96 S180 M03\nG50 S2000\nG00 X52. Z2.\n"
            + "G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nG01 Z-20.\nX30.\nZ-35.\nN20 X52.\n"
            + "G00 X100. Z50.\n";

    @Test
    void aG70AfterAG41OrG42BlockFinishesTheContourOfTheG71BeforeIt() {
        // the G70's P and Q are the earlier G71's contour, whatever compensation block comes
        // between them: the control finishes it (E166 is only for blocks that are not there)
        assertEquals("", Run.of("fanuc", ROUGH_AND_FINISH + "G42\nG00 X52. Z2.\nG70 P10 Q20 F0.1\n"
                + "G40 G00 X100. Z50.\nM30\n").errors());
        assertEquals("", Run.of("fanuc", ROUGH_AND_FINISH + "G42 G00 X52. Z2.\nG70 P10 Q20 F0.1\n"
                + "G40 G00 X100. Z50.\nM30\n").errors());
        assertEquals("", Run.of("fanuc", ROUGH_AND_FINISH + "G00 X52. Z2.\nG42 G70 P10 Q20 F0.1\n"
                + "G40 G00 X100. Z50.\nM30\n").errors());
        assertEquals("", Run.of("haas", "G20 G99\nT101\nG97 S800 M03\nG00 X2.1 Z0.1\n"
                + "G71 P1 Q2 U0.02 W0.005 D0.08 F0.01\nN1 G00 X0.8\nG01 Z-0.8\nX1.2\nN2 X2.1\nG00 X4. Z2.\n"
                + "G42 G00 X2.1 Z0.1\nG70 P1 Q2 F0.005\nG40 G00 X4. Z2.\nM30\n").errors());
    }

    @Test
    void aG70WhosePNamesTheG42BlockBeforeTheContourRunsFromThere() {
        // N5 G42 sits between the G71 and its contour N10..N20: the G71 passes over it (E644) but
        // G70 P5 Q20 finds N5 in the program and finishes N5..N20, compensated (was E166)
        Run r = Run.of("fanuc", "G21 G99\nT0101\nG96 S180 M03\nG50 S2000\nG00 X52. Z2.\n"
                + "G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN5 G42 G00 X20. Z2.\nN10 G00 X20.\nG01 Z-20.\n"
                + "X30.\nZ-35.\nN20 X52.\nG70 P5 Q20 F0.1\nG40 G00 X100. Z50.\nM30\n");
        assertEquals("8:1:warning E644", found(r));
        assertTrue(r.blocks.stream().anyMatch(b -> b.line() == 8 && !b.motions().isEmpty()), "G70 runs N5");
        // a P that is nowhere in the program stays the control's alarm (PS0063)
        assertEquals("14:1:E166", Run.of("fanuc", "G21 G99\nT0101\nG96 S180 M03\nG50 S2000\nG00 X52. Z2.\n"
                + "G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN5 G42 G00 X20. Z2.\nN10 G00 X20.\nG01 Z-20.\n"
                + "X30.\nZ-35.\nN20 X52.\nG70 P4 Q20 F0.1\nG40 G00 X100. Z50.\nM30\n").errors().replace("8:1:E644, ", ""));
    }

    @Test
    void aToolOnTheMinusXSideRoughsAsItsMirrorDoes() throws Exception {
        // a gang lathe's tool on the -X side of the centreline: the program is the +X program with
        // X negated (and the finishing allowance U toward -X); both rough and finish clean
        java.nio.file.Path dir = java.nio.file.Files.createTempDirectory("gcnc-gang");
        java.nio.file.Path gang = dir.resolve("gang.machine");
        java.nio.file.Files.writeString(gang, java.nio.file.Files.readString(
                java.nio.file.Path.of("tables/machines/fanuc.machine")).replaceAll("(?m)^x\\.travel = .*$",
                "x.travel = -215, 215"));
        gcnc.machine.MachineProfile p = gcnc.machine.ProfileLoader.load(gang.toString(),
                gcnc.tables.TableSource.builtIn(), Run.TABLES);
        String plus = "G21 G99\nT0101\nG96 S180 M03\nG50 S2000\nG00 X52. Z2.\n"
                + "G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nG01 X24. Z-2.\nZ-20.\n"
                + "G02 X32. Z-24. R4.\nG01 X48.\nN20 Z-40.\nG70 P10 Q20 F0.1\nG00 X100. Z50.\n"
                + "G72 W2. R0.5\nG72 P30 Q40 U0.4 W0.1 F0.25\nN30 G00 Z-15.\nG01 X60.\nZ-10.\nX30. Z-5.\nX0.\n"
                + "N40 Z2.\nG00 X100. Z50.\nM30\n";
        String minus = plus.replaceAll("X([0-9])", "X-$1").replace("U0.4", "U-0.4").replace("G02", "G03");
        Run pr = Run.of(p, plus.replace("G00 X100. Z50.\nG72", "G00 X82. Z2.\nG72"), Checker.ERROR_CAP);
        Run mr = Run.of(p, minus.replace("G00 X-100. Z50.\nG72", "G00 X-82. Z2.\nG72"), Checker.ERROR_CAP);
        assertEquals("", pr.errors());
        assertEquals("", mr.errors());
        assertEquals(cutCount(pr), cutCount(mr), "the same passes, mirrored");
        assertTrue(cutCount(pr) > 10);
        // the +X program's U0.4 copied to the -X tool: the control roughs into the part as written
        // (a wrong sign gouges it): warning E159 on the U, and the cycle is expanded, not refused
        Run copied = Run.of(p, minus.replace("G00 X-100. Z50.\nG72", "G00 X-82. Z2.\nG72").replace("U-0.4 W0.1 F0.25\nN10",
                "U0.4 W0.1 F0.25\nN10"), Checker.ERROR_CAP);
        assertEquals("7:13:warning E159", found(copied));
        assertTrue(cutCount(copied) > cutCount(mr), "expanded, the passes going the allowance deeper");
    }

    private static int cutCount(Run r) {
        int n = 0;
        for (CheckedBlock b : r.blocks) {
            n += b.motions().size();
        }
        return n;
    }

    /** The point at {@code degrees} on the circle of {@code radius} about X0 Z0 (the angle from +Z toward +X). */
    private static Point at(double radius, double degrees) {
        double a = Math.toRadians(degrees);
        return new Point(radius * Math.sin(a), radius * Math.cos(a));
    }
}
