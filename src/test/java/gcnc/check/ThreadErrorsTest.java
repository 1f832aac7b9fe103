package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import org.junit.jupiter.api.Test;

/**
 * One tiny program per thread finding (E190-E199, the chamfered pull-out's E240-E242 and E208, and
 * the cycle codes a thread shares: E160, E161, E167), on the fanuc machine (metric, fanuc-a), the haas machine (inch) and generic with a Fanuc
 * control (no spindle encoder): the code at the word it names.
 */
class ThreadErrorsTest {
    /** Lines 1-4: metric, feed per revolution, G97 800 r/min forward, at X30 Z5 (outside an M24 thread). */
    private static final String START = "G21 G99\nT0707\nG97 S800 M03\nG00 X30. Z5.\n";

    private static String fanuc(String program) {
        return Run.of("fanuc", START + program).errors();
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
    void goodThreadsReportNothingAndCutGearedPasses() {
        Run g32 = Run.of("fanuc", START + "G00 X23.\nG32 Z-25. F1.5\nG00 X30.\nM30\n");
        assertEquals("", g32.errors());
        assertEquals(1, threads(g32));
        Run g92 = Run.of("fanuc", START + "G92 X23.2 Z-25. F1.5\nX22.8\nX22.5\nG00 X40.\nM30\n");
        assertEquals("", g92.errors());
        assertEquals(3, threads(g92));
        Run g76 = Run.of("fanuc", START + "G76 P020060 Q100 R0.05\nG76 X22.16 Z-25. P920 Q350 F1.5\nM30\n");
        assertEquals("", g76.errors());
        assertEquals(8, threads(g76)); // six roughing passes, then two finishing passes at the height
        Run haas = Run.of("haas", "G20 G99\nT303\nG97 S700 M03\nG00 X0.6 Z0.2 M24\n"
                + "G76 X0.4056 Z-0.75 K0.0472 D0.012 F0.07692\nM30\n");
        assertEquals("", haas.errors());
        assertEquals(16, threads(haas));
    }

    @Test
    void e190AMachineWithoutASpindleEncoderAtTheThreadsG() {
        Run r = Run.of(Run.profileWithControl("generic", "fanuc-a"),
                START + "G76 X22.16 Z-25. P920 Q350 F1.5\nG32 Z-25. F1.5\nG92 X23. Z-25. F1.5\nM30\n", Checker.ERROR_CAP);
        assertEquals("5:1:E190, 6:1:E190, 7:1:E190", r.errors());
        // the refused G92 stays in force: its next pass is refused too, not moved as a rapid
        Run again = Run.of(Run.profileWithControl("generic", "fanuc-a"),
                START + "G92 X23. Z-25. F1.5\nX22.5\nG00 X40.\nM30\n", Checker.ERROR_CAP);
        assertEquals("5:1:E190, 6:1:E190", again.errors());
        assertEquals(0, threads(r));
    }

    @Test
    void e191ThreadingUnderG96() {
        assertEquals("8:1:E191", fanuc("G50 S2000\nG96 S150\nG00 X23.\nG32 Z-25. F1.5\nM30\n"));
        assertEquals("", fanuc("G50 S2000\nG96 S150\nG00 X23.\nG97 S800\nG32 Z-25. F1.5\nM30\n"));
    }

    @Test
    void e192ALeadTooFastForTheZAxis() {
        // 10 mm x 1200 r/min = 12000 mm/min; the fanuc machine's Z feeds at most 10000 mm/min
        assertEquals("7:11:E192", fanuc("S1200\nG00 X23.\nG32 Z-25. F10.\nM30\n"));
        assertEquals("", fanuc("S900\nG00 X23.\nG32 Z-25. F10.\nM30\n"));
    }

    @Test
    void e193AHeightThatDoesNotFitThePitch() {
        // above the sharp V (0.866 x 1.2 = 1.039 mm): no 60-degree thread is that deep, but the
        // control cuts it: warning E193 (issue 31; ShopAlarmsTest). Between 0.65 and 0.866 x the
        // lead: warning E640 (issue 17; ShopProgramsTest)
        assertEquals("5:18:E193", fanuc("G76 X22.16 Z-25. P1100 Q350 F1.2\nM30\n"));
        assertEquals("5:20:E193", Run.of("haas", "G20 G99\nT303\nG97 S700 M03\nG00 X0.6 Z0.2 M24\n"
                + "G76 X0.4056 Z-0.75 K0.07 D0.012 F0.07692\nM30\n").errors());
    }

    @Test
    void e194AFirstDepthOfZero() {
        assertEquals("5:23:E194", fanuc("G76 X22.16 Z-25. P920 Q0 F1.5\nM30\n"));
    }

    @Test
    void e195AWordTheThreadNeeds() {
        assertEquals("5:1:E195", fanuc("G76 X22.16 Z-25. P920 Q350\nM30\n"));
        assertEquals("5:1:E195", fanuc("G92 X23. F1.5\nM30\n"));
        assertEquals("5:1:E195", fanuc("G32 F1.5\nM30\n"));
        assertEquals("5:1:E195", fanuc("G76 X22.16 Z-25. Q350 F1.5\nM30\n"));
    }

    @Test
    void e196AThreadAlongX() {
        assertEquals("5:1:E196", fanuc("G32 X80. Z0. F1.5\nM30\n"));
        // a cycle that starts at its own end Z (the tool left at the end of an earlier pass)
        assertEquals("6:1:E196", fanuc("G00 Z-25.\nG76 X22.16 Z-25. P920 Q350 F1.5\nM30\n"));
        assertEquals("6:1:E196", fanuc("G00 Z-25.\nG92 X23. Z-25. F1.5\nM30\n"));
    }

    @Test
    void e197ValuesTheControlDoesNotTake() {
        assertEquals("5:5:E197", fanuc("G76 P001060 Q100 R0.05\nM30\n")); // no finishing pass, with a chamfer
        assertEquals("5:5:E197", fanuc("G76 P010045 Q100 R0.05\nM30\n")); // no 45-degree thread
        assertEquals("5:5:E197", fanuc("G76 P000060 Q100 R0.05\nM30\n")); // no finishing pass
        assertEquals("5:18:E197", fanuc("G76 X22.16 Z-25. P0.92 Q350 F1.5\nM30\n")); // P with a point
        assertEquals("5:35:E197", Run.of("haas", "G21 G99\nT303\nG97 S700 M03\nG00 X30. Z5. M24\n"
                + "G76 X22.16 Z-25. K0.92 D0.35 F1.5 P5\nM30\n").errors()); // P1-P4 only
        // Haas M23 (on at power-up) is no longer one: its chamfered pull-out is cut (ThreadChamferTest)
        String haas = "G21 G99\nT303\nG97 S700 M03\nG00 X30. Z5.\n";
        String g92 = "G92 X23. Z-25. F1.5\nG00 X40.\n";
        assertEquals("", Run.of("haas", haas + g92 + "M30\n").errors());
        assertEquals("", Run.of("haas", haas + "M24\nM23\nG00 X30.\n" + g92 + "M30\n").errors());
        // a G32 right after another thread pass is one continuous thread (ThreadContinuousTest): no
        // longer E197, as the Haas and Fanuc manuals run consecutive G32 blocks as one thread
        assertEquals("", fanuc("G00 X23.\nG32 Z-25. F1.5\nZ-27.\nG00 X30.\nM30\n"));
    }

    @Test
    void e198ALeadOfZero() {
        assertEquals("5:16:E198", fanuc("G92 X23. Z-25. F0\nM30\n"));
    }

    @Test
    void e199ThePassAFindingIsIn() {
        // 3 mm x 4000 r/min is too fast for Z: found in the first pass, which the note names
        assertEquals("6:1:E192, 6:1:E199", fanuc("S4000\nG76 X22.16 Z-25. P920 Q350 F3.\nM30\n"));
    }

    /** Lines 1-4 on the haas machine, metric: M23 (the chamfered pull-out, one lead at 45 degrees) in force from power-up. */
    private static final String HAAS = "G21 G99\nT303\nG97 S700 M03\nG00 X30. Z5.\n";

    /** The haas profile with each {@code pairs[2i]} of its text replaced by {@code pairs[2i + 1]}. */
    static gcnc.machine.MachineProfile haasWith(String... pairs) {
        try {
            String text = java.nio.file.Files.readString(java.nio.file.Path.of("tables/machines/haas.machine"));
            for (int i = 0; i < pairs.length; i += 2) {
                if (!text.contains(pairs[i])) {
                    throw new AssertionError("haas.machine has no '" + pairs[i] + "'");
                }
                text = text.replace(pairs[i], pairs[i + 1]);
            }
            return gcnc.machine.ProfileLoader.read(gcnc.machine.ProfileFile.parse("haas-variant.machine", text),
                    Run.TABLES, gcnc.tables.TableSource.builtIn(), null);
        } catch (java.io.IOException | gcnc.tables.TableException e) {
            throw new AssertionError(e);
        }
    }

    @Test
    void e240AChamferAsLongAsThePassOrLonger() {
        // one lead of 1.5 mm; the pass from Z5. to Z4. is 1 mm long
        assertEquals("5:1:E240", Run.of("haas", HAAS + "G92 X23. Z4. F1.5\nM30\n").errors());
        assertEquals("5:1:E240, 5:1:E199", Run.of("haas", HAAS + "G76 X22.16 Z4. K0.92 D0.35 F1.5\nM30\n").errors());
        // M24 pulls straight out: the short pass is a pass like any other
        assertEquals("", Run.of("haas", HAAS + "M24\nG92 X23. Z4. F1.5\nM30\n").errors());
        assertEquals("", Run.of("haas", HAAS + "G92 X23. Z3. F1.5\nM30\n").errors());
    }

    @Test
    void e241AChamferThatEndsBeyondTheXTravel() {
        // haas X travel: radius -4 .. 212 mm = X-8. .. X424.; the pass at X419. pulls out 3 mm (radius) to X425.
        assertEquals("6:1:E241", Run.of("haas", HAAS + "G00 X423.\nG92 X419. Z-25. F3.\nM30\n").errors());
        assertEquals("", Run.of("haas", HAAS + "G00 X423.\nG92 X417. Z-25. F3.\nM30\n").errors());
    }

    @Test
    void e242AChamferTooSteepForTheXAxissFeed() {
        // at 80 degrees X moves 5.67 times as fast as Z: 1.5 mm x 2000 r/min x 5.67 = 17014 mm/min, the
        // haas machine feeds at most 11938 mm/min
        gcnc.machine.MachineProfile steep = haasWith("thread.chamfer_angle = 45", "thread.chamfer_angle = 80");
        String g92 = "G00 X40.\nG92 X23. Z-25. F1.5\nM30\n";
        assertEquals("6:1:E242", Run.of(steep, HAAS.replace("S700", "S2000") + g92, Checker.ERROR_CAP).errors());
        assertEquals("", Run.of(steep, HAAS + g92, Checker.ERROR_CAP).errors());
    }

    @Test
    void e208AChamferWhoseXRatioIsBeyondGalilsRange() {
        // 16 encoder counts per revolution and an 89-degree chamfer: X needs 1.5 mm x 984 counts/mm x
        // tan 89 / 16 = 5286 counts per encoder count (Z's 92 would do)
        gcnc.machine.MachineProfile coarse = haasWith("thread.chamfer_angle = 45", "thread.chamfer_angle = 89",
                "spindle.encoder = 4096", "spindle.encoder = 16");
        String program = HAAS.replace("S700", "S10") + "G92 X23. Z-25. F1.5\nM30\n";
        assertEquals("5:1:E208", Run.of(coarse, program, Checker.ERROR_CAP).errors());
        assertEquals("", Run.of(coarse, "M24\n" + program, Checker.ERROR_CAP).errors());
    }

    @Test
    void cycleCodesAThreadShares() {
        // at the root's X the control cannot tell an outside thread from a bore: E160. Between the root
        // and the top (X + 2 x P) it runs the cycle: warning E641 (issue 17)
        assertEquals("6:1:E160", fanuc("G00 X22.16\nG76 X22.16 Z-25. P920 Q350 F1.5\nM30\n"));
        assertEquals("6:1:E641", fanuc("G00 X23.\nG76 X22.16 Z-25. P920 Q350 F1.5\nM30\n"));
        assertEquals("5:33:E161", fanuc("G76 X22.16 Z-25. P920 Q350 F1.5 K1\nM30\n"));
        assertEquals("5:23:E167", fanuc("G76 X22.16 Z-25. P920 Q1 F1.5\nM30\n"));
    }
}
