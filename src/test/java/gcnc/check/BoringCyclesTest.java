package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * The drilling cycles beyond G83/G84 as the lathe controls run them on the spindle centreline
 * (docs/cycles.md, "Boring"; issue 31): Haas G85 bore in and out, G86 bore and stop, G89 bore,
 * dwell, bore out; Fanuc 0i-TF G85 face boring and the Series 15 format G81 spot drilling and G82
 * counter boring, written as the Fusion fanuc post writes them; side drilling G87-G89 on the
 * Fanuc (live tooling) stays a named "not supported yet". Each program's third line is a rapid to
 * Z0 on the centreline, so the moves print as "G00 z" / "G01 z" in the program's unit.
 */
class BoringCyclesTest {
    private static final String HAAS = "G20 G98\nT101\nG00 X0. Z0.\nG97 S300 M03\nG00 Z0.5\n";
    private static final String FANUC = "G21 G99\nT0101\nG00 X0. Z0.\nG97 S500 M03\nG00 Z5.\n";

    /** The moves of the blocks at {@code line}, Z from the Z0 of line 3. */
    private static List<String> zMoves(Run r, String profile, int line) {
        MachineProfile p = Run.profile(profile);
        double perUnit = p.z().countsPerMm() * (profile.equals("haas") ? 25.4 : 1);
        double zero = ((Motion.Linear) r.blocks.stream().filter(b -> b.line() == 3).findFirst().orElseThrow()
                .motions().get(0)).to().z();
        return r.blocks.stream().filter(b -> b.line() == line).flatMap(b -> b.motions().stream())
                .filter(m -> m instanceof Motion.Linear).map(m -> (Motion.Linear) m).map(l -> (l.rapid() ? "G00 " : "G01 ")
                        + gcnc.check.geom.NumberText.plain((l.to().z() - zero) / perUnit, 3)).toList();
    }

    /** The spindle M codes and dwells of the blocks at {@code line}, in order. */
    private static String extras(Run r, int line) {
        return r.blocks.stream().filter(b -> b.line() == line).flatMap(b -> {
            String dwell = b.motions().stream().anyMatch(m -> m instanceof Motion.Dwell) ? "dwell" : null;
            return java.util.stream.Stream.concat(java.util.stream.Stream.concat(b.before().stream(),
                    b.after().stream()).map(MCall::code).map(c -> "M" + c), java.util.stream.Stream.ofNullable(dwell));
        }).collect(Collectors.joining(" "));
    }

    private static Run fanucB(String program) {
        return Run.of(Run.profileWithControl("fanuc", "fanuc-b"), program, Checker.ERROR_CAP);
    }

    @Test
    void haasBoresInAndOutAtTheFeedAndG89DwellsFirst() {
        Run r = Run.of("haas", HAAS + "G85 X0. Z-0.6 R0.1 F0.004\nG80\nG89 X0. Z-0.6 R0.1 P0.5 F0.004\nG80\nM30\n");
        assertEquals("", r.errors());
        assertEquals(List.of("G00 0.1", "G01 -0.6", "G01 0.1", "G00 0.5"), zMoves(r, "haas", 6));
        assertEquals(List.of("G00 0.1", "G01 -0.6", "G01 0.1", "G00 0.5"), zMoves(r, "haas", 8));
        assertEquals("", extras(r, 6));
        assertEquals("dwell", extras(r, 8));
    }

    @Test
    void haasG86StopsTheSpindleAtTheBottomRapidsOutAndStartsItAgain() {
        Run r = Run.of("haas", HAAS + "G86 X0. Z-0.6 R0.1 F0.004\nG80\nM30\n");
        assertEquals("", r.errors());
        assertEquals(List.of("G00 0.1", "G01 -0.6", "G00 0.5"), zMoves(r, "haas", 6));
        assertEquals("M5 M3", extras(r, 6));
        // under M04 it turns back M04
        Run left = Run.of("haas", HAAS.replace("M03", "M04") + "G86 X0. Z-0.6 R0.1 F0.004\nG80\nM30\n");
        assertEquals("M5 M4", extras(left, 6));
    }

    @Test
    void haasBoringWordsAreChecked() {
        // G89 without its dwell: the control's format alarm (as G82 without P)
        assertEquals("6:1:E182", Run.of("haas", HAAS + "G89 X0. Z-0.6 R0.1 F0.004\nG80\nM30\n").errors());
        // G85 has no P, no boring cycle a peck
        assertEquals("6:20:E161", Run.of("haas", HAAS + "G85 X0. Z-0.6 R0.1 P0.5 F0.004\nG80\nM30\n").errors());
        assertEquals("6:20:E161", Run.of("haas", HAAS + "G86 X0. Z-0.6 R0.1 Q0.1 F0.004\nG80\nM30\n").errors());
        // modal: a later Z bores again; off the centre it warns as a drill does
        Run again = Run.of("haas", HAAS + "G85 X0. Z-0.6 R0.1 F0.004\nZ-0.8\nG80\nM30\n");
        assertEquals("", again.errors());
        assertEquals(List.of("G00 0.1", "G01 -0.8", "G01 0.1", "G00 0.5"), zMoves(again, "haas", 7));
        assertEquals("6:5:E186", Run.of("haas", HAAS + "G85 X0.5 Z-0.6 R0.1 F0.004\nG80\nM30\n").errors());
    }

    /**
     * Property, over random holes: every boring cycle feeds to the bottom exactly once, never past
     * it nor behind the start, stays on the centre line, and ends at the start's Z.
     */
    @Test
    void boringNeverPassesTheBottomAndEndsWhereItStarted() {
        java.util.Random random = new java.util.Random(31);
        for (int n = 0; n < 60; n++) {
            String g = new String[] {"G85", "G86", "G89"}[n % 3];
            double r = random.nextInt(40) / 100.0;                 // R plane Z0 to Z0.39, below the start Z0.5
            double bottom = -(1 + random.nextInt(200)) / 100.0;    // Z-0.01 to Z-2.00
            String words = g + " X0. Z" + String.format(java.util.Locale.ROOT, "%.2f", bottom) + " R"
                    + String.format(java.util.Locale.ROOT, "%.2f", r) + (g.equals("G89") ? " P0.2" : "") + " F0.004";
            Run run = Run.of("haas", HAAS + words + "\nG80\nM30\n");
            assertEquals("", run.errors(), words);
            List<String> moves = zMoves(run, "haas", 6);
            assertEquals("G00 0.5", moves.get(moves.size() - 1), words + ": back at the start");
            long atBottom = moves.stream().filter(m -> m.equals("G01 " + gcnc.check.geom.NumberText.plain(bottom, 3)))
                    .count();
            assertEquals(1, atBottom, words + ": " + moves);
            for (String m : moves) {
                double z = Double.parseDouble(m.substring(4));
                org.junit.jupiter.api.Assertions.assertTrue(z >= bottom - 1e-9 && z <= 0.5 + 1e-9, words + ": " + m);
            }
        }
    }

    @Test
    void fanucSeries15DrillingAsTheFusionPostWritesIt() {
        // system A: R from the initial level Z5 (cycle.drill_r = incremental): R-3. is the R point Z2
        Run a = Run.of("fanuc", FANUC + "G81 X0. Z-12. R-3. F0.1\nG80\nG82 X0. Z-12. R-3. P500 F0.1\nG80\nM30\n");
        assertEquals("", a.errors());
        assertEquals(List.of("G00 2", "G01 -12", "G00 5"), zMoves(a, "fanuc", 6));
        assertEquals(List.of("G00 2", "G01 -12", "G00 5"), zMoves(a, "fanuc", 8));
        assertEquals("dwell", extras(a, 8));
        // system B, as the post writes it: G90 G98 in front, R the R point's Z (parameter RAB)
        Run b = fanucB(FANUC.replace("G99", "G95") + "G90 G98 G81 X0. Z-12. R2. F0.1\nG80\nM30\n");
        assertEquals("", b.errors());
        assertEquals(List.of("G00 2", "G01 -12", "G00 5"), zMoves(b, "fanuc", 6));
        // G99: back to the R point only
        Run r = fanucB(FANUC.replace("G99", "G95") + "G90 G99 G81 X0. Z-12. R2. F0.1\nG80\nM30\n");
        assertEquals(List.of("G00 2", "G01 -12", "G00 2"), zMoves(r, "fanuc", 6));
    }

    @Test
    void repeatsDrillTheSameHoleAgainAndKZeroDrillsNothing() {
        // K2 (L2 in the Series 15 format): the hole twice, the second from the initial level
        Run twice = Run.of("fanuc", FANUC + "G81 X0. Z-12. R-3. K2 F0.1\nG80\nM30\n");
        assertEquals("", twice.errors());
        assertEquals(List.of("G00 2", "G01 -12", "G00 5", "G00 2", "G01 -12", "G00 5"), zMoves(twice, "fanuc", 6));
        assertEquals(zMoves(twice, "fanuc", 6),
                zMoves(Run.of("fanuc", FANUC + "G81 X0. Z-12. R-3. L2 F0.1\nG80\nM30\n"), "fanuc", 6));
        // K0 keeps the cycle's data and drills nothing; the next block drills with it
        Run stored = Run.of("fanuc", FANUC + "G81 X0. Z-12. R-3. K0 F0.1\nZ-10.\nG80\nM30\n");
        assertEquals("", stored.errors());
        assertEquals(List.of(), zMoves(stored, "fanuc", 6));
        assertEquals(List.of("G00 2", "G01 -10", "G00 5"), zMoves(stored, "fanuc", 7));
        // G99 (system B): the repeat starts at the R point
        Run r = fanucB(FANUC.replace("G99", "G95") + "G90 G99 G83 X0. Z-12. R2. Q7. K2 F0.1\nG80\nM30\n");
        assertEquals("", r.errors());
        assertEquals(List.of("G00 2", "G01 -5", "G00 2", "G00 -4", "G01 -12", "G00 2",
                "G01 -5", "G00 2", "G00 -4", "G01 -12", "G00 2"), zMoves(r, "fanuc", 6));
        // Haas L: a tap twice, the spindle reversed in each
        Run tap = Run.of("haas", HAAS + "G84 X0. Z-0.6 R0.1 L2 F15.\nG80\nM30\n");
        assertEquals("", tap.errors());
        assertEquals("M4 M3 M4 M3", extras(tap, 6));
        // stepped by U, or not a whole number: not followed (holes off the centre line need live tools)
        assertEquals("6:21:E188", Run.of("fanuc", FANUC + "G81 U10. Z-12. R-3. K2 F0.1\nG80\nM30\n").errors());
        assertEquals("6:20:E188", Run.of("fanuc", FANUC + "G81 X0. Z-12. R-3. K2.5 F0.1\nG80\nM30\n").errors());
        assertEquals("6:20:E188", Run.of("haas", HAAS + "G81 X0. Z-0.6 R0.1 L-1 F0.004\nG80\nM30\n").errors());
    }

    @Test
    void fanucFaceBoringFeedsOutAfterItsDwell() {
        Run a = Run.of("fanuc", FANUC + "G85 X0. Z-12. R-3. P200 F0.1\nG80\nM30\n");
        assertEquals("", a.errors());
        assertEquals(List.of("G00 2", "G01 -12", "G01 2", "G00 5"), zMoves(a, "fanuc", 6));
        assertEquals("dwell", extras(a, 6));
        Run noDwell = Run.of("fanuc", FANUC + "G85 X0. Z-12. R-3. F0.1\nG80\nM30\n");
        assertEquals("", extras(noDwell, 6));
    }

    @Test
    void fanucSideDrillingNeedsLiveToolingAndIsNamed() {
        Run side = Run.of("fanuc", FANUC + "G87 X40. R2. F0.1\nG80\nM30\n");
        assertEquals("6:1:E110", side.errors());
        assertEquals("6:1:E110", fanucB(FANUC.replace("G99", "G95") + "G89 X40. R2. P500 F0.1\nG80\nM30\n").errors());
    }

    @Test
    void aMillsToolLengthCodeIsNamedOnEveryLatheControl() {
        assertEquals("4:1:E262", Run.of("haas", "G20\nT101\nG00 X2. Z1.\nG49\nM30\n").errors());
        assertEquals("1:5:E262", Run.of("fanuc", "G21 G49 G40\nT0101\nM30\n").errors());
        assertEquals("1:1:E262", fanucB("G43 H1\nM30\n").errors());
    }
}
