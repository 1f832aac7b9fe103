package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The virtual Galil replaying what Galil's own documents say a sequence does, on a clock the test turns
 * (docs/virtual-controller.md): the segment counter {@code _CS} of the DMC-40x0 User Manual's worked
 * example (p.86: "during the first segment ... _CS ... will be zero ... at the second segment ... _CS
 * equals 1"; the same in the DMC-2x00 p.93 and DMC-13X8 p.71 manuals), and {@code AV}, "measured from the
 * start of a coordinated move sequence or from the last AV command" (command reference AV; the DMC-40x0
 * User Manual lists it as "Trippoint for After Relative Vector distance"), while {@code _AVS} is "the
 * vector distance from the start of the sequence".
 */
class SegmentCounterAndTripTest {
    private final StringWriter trace = new StringWriter();
    private final VirtualGalil c = new VirtualGalil(Model.standard(), List.of(), trace);

    private String ok(String command) throws GalilException {
        return c.command(command);
    }

    /** Three segments of 1,000 counts along X at 10,000 counts/s (VA and VD high enough to be there in 20 counts). */
    private void threeSegments() throws GalilException {
        ok("SH XY");
        ok("VM XY");
        ok("VA 5120000");
        ok("VD 5120000");
        ok("VS 10000");
        ok("VP 1000,0");
        ok("VP 2000,0");
        ok("VP 3000,0");
        ok("VE");
    }

    @Test
    void theSegmentCounterIsZeroDuringTheFirstSegmentAndOneDuringTheSecond() throws GalilException {
        threeSegments();
        ok("BGS");
        c.advance(0.05); // 0.1 s a segment: half way through the first
        assertTrue(c.motion.position[0] > 0 && c.motion.position[0] < 1000, "in the first segment");
        assertEquals(" 0.0000\r\n", ok("MG _CSS"), "during the first segment _CS is zero");
        c.advance(0.1);
        assertTrue(c.motion.position[0] > 1000 && c.motion.position[0] < 2000, "in the second segment");
        assertEquals(" 1.0000\r\n", ok("MG _CSS"), "at the second segment _CS equals 1");
        c.advance(0.1);
        assertEquals(" 2.0000\r\n", ok("MG _CSS"), "the third");
        c.settle(1);
        assertFalse(c.moving());
        // what it reads after the end the manuals do not say: the three segments finished (our reading)
        assertEquals(" 3.0000\r\n", ok("MG _CSS"));
    }

    /** Two AVs of one sequence: the second trips at the first's distance plus its own. */
    @Test
    void theSecondAvOfASequenceTripsAtTheFirstsDistancePlusItsOwn() throws GalilException {
        threeSegments();
        c.download(String.join("\r", "#AV2", "BGS", "AV 1000", "first=_AVS", "AV 1500", "second=_AVS", "AMS",
                "EN"), false);
        ok("XQ #AV2");
        c.settle(2);
        assertFalse(c.moving());
        // the thread goes on within a millisecond of the trip point: 10 counts at 10,000 counts/s
        double first = c.variable("first");
        double second = c.variable("second");
        assertTrue(first >= 1000 && first <= 1020, "the first trips 1,000 counts from the start: " + first);
        assertTrue(second >= 2500 && second <= 2520, "the second 1,500 counts past the first, not 1,500 from the start: "
                + second);
        assertTrue(trace.toString().contains("# av 1500 tripped at 25"), trace.toString());
    }

    /**
     * An AV whose distance the sequence never reaches: the command reference does not say what follows
     * (AD and AR clear when the profile completes; AV's entry says nothing), so the virtual controller
     * takes the reading a wrong program cannot pass: the thread waits there, and the trace says so.
     */
    @Test
    void anAvPastTheEndOfItsSequenceNeverTrips() throws GalilException {
        threeSegments();
        c.download(String.join("\r", "#AVEND", "BGS", "AV 2000", "AV 1500", "done=1", "EN"), false);
        ok("XQ #AVEND");
        c.settle(2);
        assertFalse(c.motion.running(), "the sequence ran to its end, 3,000 counts");
        assertTrue(c.operand("XQ0") >= 0, "the thread still waits at AV 1500 (3,500 counts from the start)");
        assertTrue(trace.toString().contains("# av 1500 never reached: trip point 3500 past the path's end 3000"),
                trace.toString());
    }
}
