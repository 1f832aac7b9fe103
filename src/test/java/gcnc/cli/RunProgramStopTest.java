package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.controller.VirtualController;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * Program stops on the virtual Galil (issue 30, item 3): a program with M00 stops at that line,
 * moves nothing and keeps its spindle stopped while it waits, and goes on after Enter, in the
 * program form and the stream form; M01 runs through with the optional stop switch off and stops
 * with it on. Enter is typed only once the stop was announced (an Enter typed before a stop does
 * not end it), by a writer that watches what the run prints.
 */
class RunProgramStopTest {
    /** A turn, an M00 with its comment, a second turn, an M01, a third: Haas M05/M09 at the stop. */
    static final String PART = String.join("\n",
            "O1003 (STOP TEST)",
            "G21 G99",
            "G50 S2500",
            "T0101",
            "G97 S1200 M03",
            "M08",
            "G00 X42. Z2.",
            "G01 X40. F0.2",
            "G01 Z-10.",
            "G00 X50. Z5.",
            "M00 (CHECK PART, TURN INSERT)",
            "G01 X40. Z-20. F0.2",
            "G00 X50. Z5.",
            "M01 (OPTIONAL CHECK)",
            "G01 X40. Z-25. F0.2",
            "G00 X60. Z10.",
            "M05",
            "M09",
            "M30", "");

    /** What the controller showed while one stop waited. */
    record AtStop(String line, long[] before, long[] after, String moving, String spindleRun, String coolant,
                  String offset) {
    }

    record Result(int status, String out, String err, List<AtStop> stops) {
        String all() {
            return out + err;
        }
    }

    /**
     * {@code gcnc run} with Enter typed at each "program stop" line it prints, after the controller's
     * clock ran on 400 ms in the stop: the axes read before and after that time.
     */
    static Result run(VirtualController vc, Path part, String... more) throws Exception {
        Keyboard keys = new Keyboard();
        Keyboard in = keys;
        List<AtStop> stops = java.util.Collections.synchronizedList(new ArrayList<>());
        List<CompletableFuture<Void>> pending = java.util.Collections.synchronizedList(new ArrayList<>());
        StringWriter text = new StringWriter();
        Writer watching = new Writer() {
            private final StringBuilder line = new StringBuilder();

            @Override
            public void write(char[] b, int off, int len) {
                text.write(b, off, len);
                for (int i = off; i < off + len; i++) {
                    if (b[i] == '\n' || b[i] == '\r') {
                        String l = line.toString();
                        line.setLength(0);
                        if (l.startsWith("program stop at line")) {
                            pending.add(CompletableFuture.runAsync(() -> atStop(vc, l, keys, stops)));
                        }
                    } else {
                        line.append(b[i]);
                    }
                }
            }

            @Override
            public void flush() {
            }

            @Override
            public void close() {
            }
        };
        List<String> args = new ArrayList<>(List.of("run", part.toString(), "--machine", "haas", "--tcp",
                RunOnControllerTest.tcp(vc), "--poll", "20"));
        args.addAll(List.of(more));
        CommandLine cl = Main.commandLine(new Main.Streams(in, System.out), gcnc.tables.ErrorMessages.Lang.EN,
                args.toArray(new String[0]));
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(watching, true));
        cl.setErr(new PrintWriter(err, true));
        int status = cl.execute(args.toArray(new String[0]));
        for (CompletableFuture<Void> f : new ArrayList<>(pending)) {
            f.join();
        }
        keys.close();
        return new Result(status, text.toString(), err.toString(), stops);
    }

    /**
     * The run's standard input: the bytes the test types, as they are typed (a pipe would break when
     * the thread that typed into it ends).
     */
    static final class Keyboard extends java.io.InputStream {
        private final java.util.concurrent.LinkedBlockingQueue<Integer> typed = new java.util.concurrent.LinkedBlockingQueue<>();

        void write(byte[] bytes) {
            for (byte b : bytes) {
                typed.add(b & 0xff);
            }
        }

        void flush() {
        }

        @Override
        public int read() throws IOException {
            try {
                return typed.take();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return -1;
            }
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            if (len == 0) {
                return 0;
            }
            b[off] = (byte) read();
            return 1;
        }

        @Override
        public void close() {
            typed.add(-1);
        }
    }

    /** At a stop: the axes, 400 ms of controller time, the axes again and the outputs; then Enter. */
    private static void atStop(VirtualController vc, String line, Keyboard keys, List<AtStop> stops) {
        try {
            long[] before = RunOnControllerTest.axes(vc);
            double t0 = number(RunOnControllerTest.tell(vc, "MG TIME"));
            while (number(RunOnControllerTest.tell(vc, "MG TIME")) < t0 + 400) {
                Thread.onSpinWait(); // the controller's clock, not the test's, says how long the stop lasted
            }
            long[] after = RunOnControllerTest.axes(vc);
            stops.add(new AtStop(line, before, after, RunOnControllerTest.tell(vc, "MG _BGS"),
                    RunOnControllerTest.tell(vc, "MG @OUT[1]"), RunOnControllerTest.tell(vc, "MG @OUT[3]"),
                    RunOnControllerTest.tell(vc, "MG _OFC")));
            keys.write("\n".getBytes(StandardCharsets.ISO_8859_1));
            keys.flush();
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static double number(String reply) {
        return Double.parseDouble(reply.replace(":", "").strip());
    }

    static Path part(String text) throws IOException {
        return RunOnControllerTest.part(text);
    }

    private static void stoppedAndWentOn(AtStop s, String line) {
        assertTrue(s.line().startsWith("program stop at line " + line), s.line());
        assertEquals(s.before()[0], s.after()[0], "the axes moved during the stop: " + s);
        assertEquals(s.before()[1], s.after()[1], "the axes moved during the stop: " + s);
        assertTrue(s.moving().contains("0.0000"), "a sequence ran during the stop: " + s.moving());
        // Haas: M05 and M09 at the stop (output 1 spindle run, 3 flood coolant, haas.machine), 0 V on the drive
        assertTrue(s.spindleRun().contains("0.0000"), "the spindle's run output stayed on: " + s.spindleRun());
        assertTrue(s.coolant().contains("0.0000"), "the coolant stayed on: " + s.coolant());
        assertTrue(s.offset().contains("0.0000"), "the spindle drive kept its volts: " + s.offset());
    }

    @Test
    void m00StopsAtItsLineMovesNothingAndGoesOnAfterEnter() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = RunOnControllerTest.controller(RunOnControllerTest.model("DMC-4040"))) {
            RunOnControllerTest.homed(vc);
            Result r = org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(90),
                    () -> run(vc, p));
            assertEquals(0, r.status(), r.all());
            assertEquals(1, r.stops().size(), r.all()); // M01 with the switch off (Haas's default) runs through
            stoppedAndWentOn(r.stops().get(0), "11: CHECK PART, TURN INSERT");
            assertTrue(r.out().contains("line 11: going on"), r.out());
            assertTrue(r.out().contains("ran to the end"), r.out());
            // on at the end of the part: the spindle and coolant came back after the stop
            assertFalse(r.out().contains("program stop at line 14"), r.out());
            long[] end = RunOnControllerTest.programEnd(p);
            assertEquals(end[0], RunOnControllerTest.axes(vc)[0]);
            assertEquals(end[1], RunOnControllerTest.axes(vc)[1]);
        }
    }

    @Test
    void m01StopsWithTheOptionalStopSwitchOn() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = RunOnControllerTest.controller(RunOnControllerTest.model("DMC-4040"))) {
            RunOnControllerTest.homed(vc);
            Result r = org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(90),
                    () -> run(vc, p, "--optional-stop", "on"));
            assertEquals(0, r.status(), r.all());
            assertEquals(2, r.stops().size(), r.all());
            stoppedAndWentOn(r.stops().get(0), "11: CHECK PART, TURN INSERT");
            stoppedAndWentOn(r.stops().get(1), "14: OPTIONAL CHECK");
        }
    }

    @Test
    void theStreamFormStopsAndGoesOnToo() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = RunOnControllerTest.controller(RunOnControllerTest.model("DMC-4040"))) {
            RunOnControllerTest.homed(vc);
            Result r = org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(90),
                    () -> run(vc, p, "--form", "stream"));
            assertEquals(0, r.status(), r.all());
            assertEquals(1, r.stops().size(), r.all());
            stoppedAndWentOn(r.stops().get(0), "11: CHECK PART, TURN INSERT");
            assertTrue(Files.readString(p.resolveSibling("part.stream")).contains("JS #PSTOP"));
        }
    }
}
