package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The virtual controller over its two links, loopback TCP and a socat pty pair with jSerialComm on the
 * host's end: the protocol's replies, DL then UL byte for byte, and each fault of {@code --fault} doing
 * what docs/virtual-controller.md says (issue 20's fault matrix, the controller's half of it).
 */
class ControllerLinkTest {
    private Path tmp;

    @BeforeEach
    void folder() throws IOException {
        tmp = Files.createTempDirectory("gcnc-vc");
    }

    @AfterEach
    void clean() throws IOException {
        try (var files = Files.walk(tmp)) {
            files.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }

    private Links open(Links.Kind kind, InjectedFault... faults) throws IOException {
        return open(kind, 20, faults);
    }

    private Links open(Links.Kind kind, double speed, InjectedFault... faults) throws IOException {
        assumeTrue(kind == Links.Kind.TCP || Links.socat(), "socat is not installed (setup.sh installs it): no pty pair");
        return Links.open(kind, Model.standard(), speed, List.of(faults), tmp.resolve("trace.txt"));
    }

    private List<String> trace() throws IOException {
        return Files.readAllLines(tmp.resolve("trace.txt"));
    }

    /** Five VP segments of 1000 counts on X, begun. */
    private static void fiveSegments(HostLink h) throws IOException {
        for (String c : List.of("SH XY", "VM XY", "VS 20000", "VP 1000,0", "VP 2000,0", "VP 3000,0", "VP 4000,0",
                "VP 5000,0", "VE", "BGS")) {
            assertEquals(":", h.send(c), c);
        }
    }

    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void theProtocolRepliesAsAGalil(Links.Kind kind) throws IOException {
        try (Links l = open(kind)) {
            HostLink h = l.host;
            assertEquals("DMC4040 Rev 1.2d\r\n:", h.send("\u0012\u0016"));
            assertEquals("?", h.send("GO"));
            assertEquals("1 Unrecognized command\r\n:", h.send("TC1"));
            h.write("MG 1;MG 1+2*3\r");
            assertEquals(" 1.0000\r\n:", h.reply(), "one reply per ;-separated command");
            assertEquals(" 9.0000\r\n:", h.reply());
            assertEquals(":", h.send(""), "an empty line answers :");
            assertEquals(" 511.0000\r\n:", h.send("MG _LMS"));
            assertEquals("0, 0, 0, 0\r\n:", h.send("TP"));
            assertEquals("?", h.send("WT 100"));
            assertEquals("2 Command only valid from program\r\n:", h.send("TC1"));
        }
    }

    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void downloadThenUploadIsByteIdentical(Links.Kind kind) throws IOException {
        try (Links l = open(kind)) {
            HostLink h = l.host;
            String program = "#GCNC\r\nSH XY\r\nVM XY\r\nVA 1000000;VD 1000000\r\n'a remark; kept\r\nVS 1667\r\n"
                    + "VP -5000,0\r\nCR 10000,0,90\r\nVE\r\nBGS\r\nAMS\r\nMG \"done\"\r\nEN\r\n";
            assertEquals("::", h.download(program));
            assertEquals(program, h.upload());
            assertEquals(" 509.0000\r\n:", h.send("MG _DL"), "510 labels, one used");
            assertEquals("?", h.download("#A\r\n" + "x=1;".repeat(21) + "\r\n"), "a line over 80 characters");
            assertEquals("60 Download error - line too long or too many lines\r\n:", h.send("TC1"));
            assertEquals(program, h.upload(), "a refused download leaves the program");
        }
    }

    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void aStreamedSequenceRunsAndTheTraceIsItsPath(Links.Kind kind) throws IOException, InterruptedException {
        try (Links l = open(kind)) {
            HostLink h = l.host;
            fiveSegments(h);
            long until = System.nanoTime() + 5_000_000_000L;
            while (h.number("MG _BGS") != 0 && System.nanoTime() < until) {
                Thread.sleep(5);
            }
            assertEquals("5000, 0, 0, 0\r\n:", h.send("TP"));
            assertEquals(" 5.0000 101.0000 511.0000\r\n:", h.send("MG _CSS,_SCS,_LMS"),
                    "after the end the counter reads the five segments finished (the manuals do not say: our reading)");
            List<String> segments = trace().stream().filter(t -> !t.startsWith("#"))
                    .map(t -> String.join(" ", Arrays.asList(t.split(" ")).subList(0, 5))).toList();
            assertEquals(List.of("1 1 VP 1000 0", "1 2 VP 2000 0", "1 3 VP 3000 0", "1 4 VP 4000 0", "1 5 VP 5000 0"),
                    segments);
        }
    }

    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void rejectAnswersQuestionMarkToThatCommandOnly(Links.Kind kind) throws IOException {
        try (Links l = open(kind, InjectedFault.parse("reject=3"))) {
            HostLink h = l.host;
            assertEquals(":", h.send("a=1"));
            assertEquals(":", h.send("b=2"));
            assertEquals("?", h.send("c=3"), "the third command");
            assertEquals("1 Unrecognized command\r\n:", h.send("TC1"));
            assertEquals("?", h.send("MG c"), "it was not executed");
            assertEquals(":", h.send("c=3"), "and the fault fires once");
        }
    }

    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void garbageComesAfterThatManyBytes(Links.Kind kind) throws IOException {
        try (Links l = open(kind, InjectedFault.parse("garbage-after=12"))) {
            HostLink h = l.host;
            assertEquals(" 511.0000\r\n:", h.send("MG _LMS"), "12 bytes, then the garbage");
            String next = h.send("MG _LMS");
            assertFalse(next.equals(" 511.0000\r\n:"), next);
            byte[] all = h.raw.toByteArray();
            assertArrayEquals(Faults.GARBAGE, Arrays.copyOfRange(all, 12, 12 + Faults.GARBAGE.length));
            assertEquals(" 511.0000\r\n:", h.send("MG _LMS"), "once");
        }
    }

    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void disconnectEndsTheLinkAndTheMotionGoesOn(Links.Kind kind) throws IOException, InterruptedException {
        try (Links l = open(kind, 2, InjectedFault.parse("disconnect-after=80"))) {
            HostLink h = l.host;
            fiveSegments(h); // 77 bytes
            assertThrows(IOException.class, () -> h.send("MG _LMS"), "the link is gone after byte 80");
            VirtualGalil c = l.controller.controller();
            long until = System.nanoTime() + 5_000_000_000L;
            while (c.moving() && System.nanoTime() < until) {
                Thread.sleep(10);
            }
            assertEquals(5000, c.position(0), "the sequence ran to its end without the host");
        }
    }

    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void slowDelaysEveryReply(Links.Kind kind) throws IOException {
        try (Links l = open(kind, InjectedFault.parse("slow=150"))) {
            long start = System.nanoTime();
            assertEquals(":", l.host.send("a=1"));
            assertEquals(":", l.host.send("b=1"));
            assertTrue(System.nanoTime() - start >= 300_000_000L, "two replies, 150 ms each");
        }
    }

    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void stallStopsDrainingTheBufferAfterThatSegment(Links.Kind kind) throws IOException, InterruptedException {
        try (Links l = open(kind, InjectedFault.parse("stall=2"))) {
            HostLink h = l.host;
            fiveSegments(h);
            Thread.sleep(400); // 2 s of controller time at 20x: far longer than the five segments take
            assertEquals(" 1.0000 1.0000 507.0000\r\n:", h.send("MG _BGS,_CSS,_LMS"),
                    "still in the sequence, at segment 2 (_CSS 1: from zero), three segments and VE in the buffer");
            assertEquals("2000, 0, 0, 0\r\n:", h.send("TP"));
            assertEquals(":", h.send("ST S"));
            Thread.sleep(50);
            assertEquals(" 0.0000 4.0000\r\n:", h.send("MG _BGS,_SCS"));
            assertEquals(2, trace().stream().filter(t -> !t.startsWith("#")).count());
        }
    }

    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void aLimitTripsDuringThatSegmentAndRunsLimswi(Links.Kind kind) throws IOException, InterruptedException {
        try (Links l = open(kind, InjectedFault.parse("limit-at=3"))) {
            HostLink h = l.host;
            assertEquals("::", h.download("#LIMSWI\r\nlim=_LFX\r\nMG \"LIMIT\",_CSS{F1.0}\r\nRE\r\n"));
            assertEquals(":", h.send("CW 1"));
            assertEquals(":", h.send("CF I"), "unsolicited messages to this port (COMALL CF: the serial port unless told)");
            fiveSegments(h);
            long until = System.nanoTime() + 5_000_000_000L;
            while (h.number("MG _BGS") != 0 && System.nanoTime() < until) {
                Thread.sleep(5);
            }
            assertEquals(" 0.0000 2.0000\r\n:", h.send("MG lim,_SCS"),
                    "the forward limit input read active (0) in #LIMSWI; stopped by the limit");
            double x = l.controller.controller().position(0);
            assertTrue(x > 2500 && x < 4000, "decelerated to a stop past the middle of segment 3: " + x);
            assertEquals("LIMIT2\r\n", h.unsolicited.toString(),
                    "#LIMSWI's MG during segment 3 (_CSS 2: from zero), marked as unsolicited (CW 1)");
            List<String> t = trace();
            // 20000 counts/s comes down at VD 256000 in 781 counts: the stop that began half way through
            // segment 3 ends in segment 4
            assertEquals(3, t.stream().filter(s -> !s.startsWith("#")).count(), "segments 1 to 3 ran to their ends");
            assertTrue(t.stream().anyMatch(s -> s.startsWith("# limit switch tripped")), t.toString());
            assertTrue(t.stream().anyMatch(s -> s.startsWith("# stop 1 at")), t.toString());
            assertEquals(":", h.send("VP 1000,0"), "the limit is released after the stop: motion may resume");
        }
    }

    /**
     * 600 segments streamed as a sender streams them (more than the buffer holds): never more in flight
     * than {@code sent - _CSS <= 511}, VE at the end; the buffer never refuses one, the sequence never
     * runs dry, and the trace has every segment, in order, at its end point.
     */
    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void aLongStreamWithFlowControlRunsEverySegment(Links.Kind kind) throws IOException, InterruptedException {
        try (Links l = open(kind, 4)) {
            HostLink h = l.host;
            for (String c : List.of("SH XY", "VM XY", "VS 100000", "VA 1024000", "VD 1024000")) {
                assertEquals(":", h.send(c), c);
            }
            int sent = 0;
            boolean begun = false;
            while (sent < 600) {
                double css = begun ? h.number("MG _CSS") : 0;
                while (sent < 600 && sent - css < 500) {
                    sent++;
                    assertEquals(":", h.send("VP " + 1000 * sent + "," + (sent % 2 == 0 ? 0 : 500)), "segment " + sent);
                }
                if (!begun) {
                    assertEquals(":", h.send("BGS"));
                    begun = true;
                }
                Thread.sleep(20);
            }
            assertEquals(":", h.send("VE"));
            long until = System.nanoTime() + 20_000_000_000L;
            while (h.number("MG _BGS") != 0 && System.nanoTime() < until) {
                Thread.sleep(20);
            }
            List<String> t = trace();
            assertTrue(t.stream().noneMatch(s -> s.startsWith("# underrun")), t.get(t.size() - 1));
            List<String> ends = t.stream().filter(s -> !s.startsWith("#"))
                    .map(s -> String.join(" ", Arrays.asList(s.split(" ")).subList(1, 5))).toList();
            assertEquals(600, ends.size());
            for (int i = 1; i <= 600; i++) {
                assertEquals(i + " VP " + 1000 * i + " " + (i % 2 == 0 ? 0 : 500), ends.get(i - 1));
            }
        }
    }

    /** With no clock (speed 0) the test turns the controller's time itself: the trace is the same every run. */
    @ParameterizedTest
    @EnumSource(Links.Kind.class)
    void withoutAClockTheTestTurnsTheTime(Links.Kind kind) throws IOException {
        try (Links l = open(kind, 0)) {
            HostLink h = l.host;
            fiveSegments(h);
            assertEquals(" 1.0000 0.0000\r\n:", h.send("MG _BGS,_CSS"), "begun; no time has passed");
            l.controller.controller().advance(0.15);
            assertEquals(" 2.0000\r\n:", h.send("MG _CSS"), "in the third segment: the counter starts at zero");
            l.controller.controller().settle(5);
            List<String[]> lines = trace().stream().filter(t -> !t.startsWith("#")).map(t -> t.split(" ")).toList();
            // VS 20000 at the default VA = VD = 256000: 0.078125 s and 781.25 counts to reach speed and to stop
            double ramp = 20000 / 256000.0;
            double first = ramp + (1000 - 781.25) / 20000;
            double[] ends = {first, first + 0.05, first + 0.1, first + 0.15, first + 0.15 + first};
            for (int i = 0; i < 5; i++) {
                String[] t = lines.get(i);
                assertEquals("1 " + (i + 1) + " VP " + 1000 * (i + 1) + " 0 " + (506 + i), String.join(" ",
                        Arrays.asList(t).subList(0, 6)), "segment, end, free slots (VE holds one to the end)");
                assertEquals(ends[i], Double.parseDouble(t[6]), 0.001, "segment " + (i + 1) + " ends on time");
            }
            assertEquals(5, lines.size());
        }
    }
}
