package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The virtual Galil without a link, on a clock the test turns ({@link VirtualGalil#advance}): the replies
 * of the command protocol, the program threads, and the vector motion in time (docs/virtual-controller.md).
 */
class VirtualGalilTest {
    private final StringWriter trace = new StringWriter();
    private final VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), trace);

    private String ok(String command) throws GalilException {
        return c.command(command);
    }

    private Tc rejected(String command) {
        GalilException e = assertThrows(GalilException.class, () -> c.command(command), command);
        return e.tc;
    }

    /** The trace's segment lines without the time column. */
    private List<String> segments() {
        return trace.toString().lines().filter(l -> !l.startsWith("#"))
                .map(l -> l.substring(0, l.lastIndexOf(' '))).toList();
    }

    @Test
    void repliesAsAGalil() throws GalilException {
        assertEquals("DMC4040 Rev 1.2d\r\n", ok("\u0012\u0016"));
        assertEquals(" 9.0000\r\n", ok("MG 1+2*3"), "left to right, no precedence (command reference, parentheses)");
        assertEquals(" 7.0000\r\n", ok("MG 1+(2*3)"));
        assertEquals("-2.5000\r\n", ok("MG -5/2"));
        assertEquals("x= 511.0000 free\r\n", ok("MG \"x=\",_LMS,\" free\""));
        assertEquals("0511\r\n", ok("MG _LMS{F4.0}"));
        assertEquals("", ok("SB 3"));
        assertEquals(" 1.0000 0.0000\r\n", ok("MG @OUT[3],@OUT[4]"), "items follow each other, a number with its sign or a space");
        assertEquals("0\r\n", ok("TC1"), "no error yet");
        assertEquals(Tc.UNRECOGNIZED, rejected("XY"));
        assertEquals("1 Unrecognized command\r\n", ok("TC1"));
        assertEquals("0\r\n", ok("TC1"), "TC clears the code once read");
        assertEquals(Tc.UNRECOGNIZED, rejected("bg"), "lower case is not a command");
        assertEquals(Tc.ONLY_IN_PROGRAM, rejected("WT 100"));
        assertEquals(Tc.ONLY_IN_PROGRAM, rejected("AMS"));
        assertEquals(Tc.RANGE, rejected("SB 9"), "a 4-axis model has 8 outputs");
        assertEquals(Tc.OPERAND, rejected("OF ,,10"), "gcnc.dmc reads no offset beyond 9.998 V");
        assertEquals("", ok("OF ,,3.25"));
        assertEquals(3.25, c.offset(2));
        assertEquals(Tc.UNRECOGNIZED, rejected("AO 2,4.5"), "the DMC-40x0 has no general analog outputs (galil_models.csv)");
        assertEquals("", ok("OFC=0"));
        assertEquals(0, c.offset(2));
        assertEquals("", ok("feed=12"));
        assertEquals(" 12.0000\r\n", ok("feed="));
        assertEquals("", ok("DM ring[10]"));
        assertEquals("", ok("ring[3]=feed*2"));
        assertEquals(" 24.0000\r\n", ok("MG ring[3]"));
        assertEquals(Tc.BAD_INDEX, rejected("ring[10]=1"));
        assertEquals(" 23990.0000\r\n", ok("MG _DM"));
        assertEquals("23990\r\n", ok("DM ?"), "what a sender's pre-flight asks");
        assertEquals(" 1.0000 1.0000 1.0000 1.0000\r\n", ok("MG _LFX,_LRX,_HMX,_MOX"), "limits and home inactive, motor off");
        assertEquals(Tc.NO_SEQUENCE, rejected("BGS"));
        assertEquals("0, 0, 0, 0\r\n", ok("TP"));
    }

    @Test
    void downloadKeepsTheBytesAndRefusesWhatTheModelCannotHold() throws GalilException {
        String program = "#A\r\n  x=5 ;'spaces kept\r\nMG \"x;y\",x\r\nEN\r\n";
        c.download(program, false);
        assertEquals(program, c.programText());
        assertEquals(" 509.0000\r\n", ok("MG _DL"), "one label of 510");
        assertEquals(" 254.0000\r\n", ok("MG _UL"), "the variables galil_models.csv gives the model");
        GalilException longLine = assertThrows(GalilException.class, () -> c.download("x=" + "1".repeat(79), false));
        assertEquals(Tc.DOWNLOAD, longLine.tc);
        assertEquals(program, c.programText(), "a refused download leaves the program as it was");
        assertEquals(Tc.BAD_LABEL, assertThrows(GalilException.class, () -> c.download("#A\r#A\r", false)).tc);
        assertEquals(Tc.BAD_LABEL, assertThrows(GalilException.class, () -> c.download("#TOOLONG8\r", false)).tc);
        VirtualGalil small = new VirtualGalil(Model.named("DMC-2143").orElseThrow(), List.of(), null);
        assertEquals(Tc.DOWNLOAD, assertThrows(GalilException.class, () -> small.download("EN\r".repeat(2001), false)).tc);
        small.download("EN\r".repeat(2000), false);
    }

    /**
     * {@code --fault slow-thread=MS}: each step of a thread (a statement, or the move to the next line, as the
     * 20 a millisecond are counted without the fault) takes MS ms of controller time.
     */
    @Test
    void aSlowThreadFaultGivesEveryStatementItsMilliseconds() throws GalilException {
        VirtualGalil slow = new VirtualGalil(Model.standard(), List.of(InjectedFault.parse("slow-thread=10")), null);
        slow.download(String.join("\r", "#A", "a=1", "b=2", "c=3", "EN"), false);
        slow.command("XQ #A,0");
        slow.advance(0.0355); // 3.55 steps: the label, its line's end, a=1
        assertEquals(" 1.0000\r\n", slow.command("MG a"));
        assertThrows(GalilException.class, () -> slow.command("MG b"), "b=2 has not run yet");
        slow.advance(0.0145); // 1.45 steps and the 0.55 owed: a=1's line end, b=2
        assertEquals(" 2.0000\r\n", slow.command("MG b"), "the fraction owed carries over");
        assertThrows(GalilException.class, () -> slow.command("MG c"), "c=3 has not run yet");
        c.download(String.join("\r", "#A", "a=1", "b=2", "c=3", "EN"), false);
        ok("XQ #A,0");
        c.advance(0.001);
        assertEquals(" 3.0000\r\n", ok("MG c"), "without the fault all in a millisecond");
    }

    @Test
    void threadsRunJumpsSubroutinesAndConditions() throws GalilException {
        c.download(String.join("\r", "#MAIN", "i=0;n=0", "#LOOP", "JS #ADD,i<3", "i=i+1", "JP #LOOP,i<5",
                "IF (n=3)", "r=1", "ELSE", "r=2", "ENDIF", "WT 100", "done=1", "EN", "#ADD", "n=n+1", "EN"), false);
        ok("XQ #MAIN,3");
        assertEquals(" 0.0000\r\n", ok("MG _XQ3"));
        c.advance(0.05);
        assertEquals(" 3.0000 1.0000\r\n", ok("MG n,r"));
        assertEquals(Tc.UNRECOGNIZED, rejected("MG done"), "WT 100 has not passed yet");
        assertTrue(c.command("MG _XQ3").startsWith(" 11."), "waiting on line 11, the WT");
        c.advance(0.06);
        assertEquals(" 1.0000\r\n", ok("MG done"));
        assertEquals("-1.0000\r\n", ok("MG _XQ3"), "ended");
        assertEquals(Tc.UNDEFINED_LABEL, rejected("XQ #NONE"));
    }

    @Test
    void anErrorInAProgramRunsCmderrOrStopsEveryThread() throws GalilException {
        c.download(String.join("\r", "#A", "WT 10", "VP 1,2", "EN", "#B", "WT 1000", "EN"), false);
        ok("XQ #A,0");
        ok("XQ #B,1");
        c.advance(0.05);
        assertEquals("-1.0000-1.0000\r\n", ok("MG _XQ0,_XQ1"), "VP before VM stopped all threads");
        c.download(String.join("\r", "#A", "VP 1,2", "EN", "#CMDERR", "line=_ED;code=_TC", "EN"), false);
        ok("XQ #A");
        c.advance(0.01);
        assertEquals(" 1.0000 28.0000\r\n", ok("MG line,code"));
    }

    @Test
    void aSequenceRunsInTimeAndTheTraceIsItsPath() throws GalilException {
        ok("SH XY");
        ok("VM XY");
        ok("DP 1000,-500");
        ok("VA 102400");
        ok("VD 102400");
        ok("VS 10000");
        ok("VP 5000,0");
        ok("CR 2000,270,90");
        ok("VP 7000,6000");
        assertEquals(" 508.0000\r\n", ok("MG _LMS"));
        ok("VE");
        assertEquals(" 507.0000\r\n", ok("MG _LMS"), "VE holds a slot");
        ok("BGS");
        assertEquals(Tc.BEGIN_WHILE_RUNNING, rejected("BGS"));
        assertEquals(Tc.WHILE_RUNNING, rejected("VD 204800"));
        c.advance(0.2);
        assertEquals(" 1.0000 0.0000\r\n", ok("MG _BGS,_CSS"), "in the first segment: the counter starts at zero");
        double t = c.settle(10);
        assertFalse(c.moving());
        assertEquals(List.of("1 1 VP 6000 -500 508", "1 2 CR 8000 1500 509", "1 3 VP 8000 5500 510"), segments());
        assertEquals("8000, 5500, 0, 0\r\n", ok("TP"));
        assertEquals(" 8000.0000 5500.0000 101.0000\r\n", ok("MG _VPX,_VPY,_SCS"));
        // 5000 + pi*1000 + 4000 counts at 10000 counts/s, with 0.1 s to accelerate and to decelerate
        double length = 9000 + Math.PI * 1000;
        assertEquals(length / 10000 + 10000 / 102400.0, t + 0.2, 0.003);
        assertTrue(trace.toString().contains("# end 1 at 8000,5500"), trace.toString());
    }

    @Test
    void withoutVeTheBufferRunsDryAndTheSequenceEnds() throws GalilException {
        ok("SH XY");
        ok("VM XY");
        ok("VP 1000,0");
        ok("BGS");
        c.settle(5);
        assertTrue(trace.toString().contains("# underrun 1 at 1000,0"), trace.toString());
        ok("VP 1000,0");
        ok("VE");
        ok("BGS");
        c.settle(5);
        assertEquals("2000, 0, 0, 0\r\n", ok("TP"), "the next sequence's origin is where the first ended");
    }

    @Test
    void aSegmentSpeedAndAnEndSpeedAreKept() throws GalilException {
        ok("SH XY");
        ok("VM XY");
        ok("VA 1024000");
        ok("VD 1024000");
        ok("VP 20000,0<20000>2000");
        ok("VP 20000,20000<20000");
        ok("VE");
        ok("BGS");
        double atCorner = -1;
        boolean fast = false;
        while (c.moving()) {
            c.advance(0.001);
            double v = c.motion.speed();
            fast |= v > 19_000;
            if (c.motion.css() == 1 && atCorner < 0) { // the second segment (the counter starts at zero)
                atCorner = v;
            }
        }
        assertTrue(fast, "cruises at <20000");
        // the first millisecond of the second segment: 2000 plus at most one millisecond at VA
        assertTrue(atCorner >= 2000 && atCorner < 2000 + 1024 + 1, "came down to >2000 at the corner: " + atCorner);
    }

    @Test
    void stopDeceleratesAndFeedOverrideHolds() throws GalilException {
        ok("SH XY");
        ok("VM XY");
        ok("VS 10000");
        for (int i = 1; i <= 10; i++) {
            ok("VP " + 1000 * i + ",0");
        }
        ok("VE");
        ok("BGS");
        c.advance(0.3);
        ok("VR 0");
        c.advance(0.2);
        long held = c.position(0);
        c.advance(0.5);
        assertEquals(held, c.position(0), "VR 0 holds the axes in the sequence");
        assertTrue(c.moving(), "and the sequence stays alive");
        ok("VR 1");
        c.advance(0.2);
        ok("ST S");
        c.settle(2);
        assertFalse(c.moving());
        assertEquals(" 4.0000\r\n", ok("MG _SCS"));
        assertTrue(trace.toString().contains("# stop 1 at"), trace.toString());
        assertEquals(" 511.0000\r\n", ok("MG _LMS"), "a stopped sequence leaves the buffer empty");
    }

    /** IT is recorded and read back; below 1 it is not modelled, and the trace says so (command reference IT). */
    @Test
    void smoothingIsRecordedAndAValueBelowOneIsReported() throws GalilException {
        assertEquals(" 1.0000\r\n", ok("MG _ITX"), "1 at power-up: no filtering");
        ok("IT 1,1");
        assertFalse(trace.toString().contains("smoothing"), trace.toString());
        ok("IT ,0.5");
        assertEquals(" 1.0000 0.5000\r\n", ok("MG _ITX,_ITY"));
        assertTrue(trace.toString().contains("IT B 0.5000: smoothing not modelled"), trace.toString());
        ok("ITX=0.25");
        assertEquals(" 0.2500\r\n", ok("MG _ITX"));
        assertEquals(Tc.RANGE, rejected("IT 0"), "0.004 to 1");
        assertEquals(Tc.RANGE, rejected("IT 2"));
    }

    @Test
    void theBufferHoldsFiveHundredElevenSegments() throws GalilException {
        ok("SH XY");
        ok("VM XY");
        for (int i = 1; i <= 511; i++) {
            ok("VP " + i + ",0");
        }
        assertEquals(" 0.0000\r\n", ok("MG _LMS"));
        assertEquals(Tc.BUFFER_FULL, rejected("VP 600,0"));
        ok("BGS");
        c.advance(0.001);
        assertEquals(" 1.0000 0.0000\r\n", ok("MG _LMS,_CSS"), "the executing segment gave its slot back; the first is 0");
    }

    /** The ranges are the model's row of tables/galil_models.csv, the compiler's own (COMALL VS, VP, CR). */
    @Test
    void theModelsRangesAreTheTablesOwn() throws GalilException {
        ok("SH XY");
        ok("VM XY");
        assertEquals(Tc.RANGE, rejected("VS 1"));
        assertEquals(Tc.RANGE, rejected("VS 15000002"));
        assertEquals(Tc.RANGE, rejected("VP 8388608,0"), "a segment longer than 8,388,607 counts");
        assertEquals(Tc.RANGE, rejected("CR 9,0,90"), "a radius under 10");
        assertEquals(Tc.RANGE, rejected("CR 5000000,0,90"), "r times the degrees reaches 450,000,000");
        assertEquals(Tc.RANGE, rejected("VA 1000"));
        assertEquals(Tc.RANGE, rejected("VP 1000,0 <1"), "a segment speed under 2");
        ok("VP 8388607,0");
        ok("CR 4999999,0,90");
    }
}
