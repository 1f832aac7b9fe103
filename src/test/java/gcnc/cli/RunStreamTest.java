package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.homed;
import static gcnc.cli.RunOnControllerTest.model;
import static gcnc.cli.RunOnControllerTest.part;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.controller.VirtualController;
import gcnc.machine.Plane;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@code gcnc run} in the stream form (docs/galil.md, "Two forms"; docs/run.md) on the virtual Galil
 * over loopback TCP: the resident program downloaded and set up, the stream fed through the command
 * line, the thread passes run as resident routines; the executed path, sequence by sequence and pass
 * by pass, is the program form's, count for count. A program longer than the controller's memory is
 * run in the stream form without being asked, and the run refuses no program the compile accepted.
 */
class RunStreamTest {
    /** Where each sequence and each pass ended on the controller, in order. */
    private static List<String> ends(Path trace) throws Exception {
        return Files.readAllLines(trace).stream().filter(l -> l.startsWith("# end ") || l.startsWith("# pass "))
                .map(l -> l.replaceAll(" t=.*", "").replaceAll("^# (end|pass) \\d+ ", "# $1 ")).toList();
    }

    private static Path ran(Path program, String form, String... more) throws Exception {
        Path trace = program.resolveSibling("run-" + form + ".trace");
        try (VirtualController vc = VirtualController.tcp(0,
                new VirtualController.Options(model("DMC-4040"), 200, List.of(), trace))) {
            homed(vc);
            String[] args = {"run", program.toString(), "--machine", "haas", "--stock", "20,50", "--tcp",
                    "127.0.0.1:" + vc.port(), "--poll", "10", "--form", form};
            String[] all = java.util.Arrays.copyOf(args, args.length + more.length);
            System.arraycopy(more, 0, all, args.length, more.length);
            RunOnControllerTest.Run r = gcnc("", all);
            assertEquals(0, r.status(), r.all());
            assertTrue(r.out().contains("ran to the end"), r.out());
        }
        return trace;
    }

    @Test
    void aThreadingProgramStreamedRunsThePathItRunsAsOneProgram() throws Exception {
        Path p = part(RunThreadTest.THREAD);
        List<String> program = ends(ran(p, "program"));
        List<String> stream = ends(ran(p, "stream"));
        assertTrue(Files.readString(p.resolveSibling("part.stream")).contains("JS #B1"), "the passes are resident routines");
        assertEquals(program, stream);
        assertTrue(stream.stream().filter(l -> l.startsWith("# pass")).count() >= 5, stream.toString());
    }

    /**
     * A limit switch trips inside a blended sequence of the stream: motion and spindle stop, the run
     * names the block executing (line 8) and the one completed (7), and the printed resume command
     * finishes the part in the stream form along the uninterrupted run's path, segment for segment.
     */
    @Test
    void aStopInsideAStreamedSequenceResumesAtItsBlockAlongTheSamePath() throws Exception {
        Path p = part(RunOnControllerTest.PART);
        Path dir = Files.createTempDirectory("gcnc-trace");
        Path whole = dir.resolve("whole.trace");
        Path stopped = dir.resolve("stopped.trace");
        try (VirtualController vc = RunOnControllerTest.traced(RunOnControllerTest.FAST, model("DMC-4040"), whole)) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp",
                    RunOnControllerTest.tcp(vc), "--form", "stream");
            assertEquals(0, r.status(), r.all());
        }
        try (VirtualController vc = RunOnControllerTest.traced(model("DMC-4040"), stopped, "limit-at=3")) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp",
                    RunOnControllerTest.tcp(vc), "--poll", "20", "--form", "stream");
            assertEquals(3, r.status(), r.all());
            assertTrue(r.err().contains("part.nc:8:1: error[E825]"), r.err());
            assertTrue(r.out().contains("stopped: last block completed: line 7; executing: line 8"), r.out());
            String resume = RunOnControllerTest.resumeCommand(r.out());
            assertTrue(resume.contains("--form stream") && resume.endsWith("--resume-at 8"), resume);
            RunOnControllerTest.Run again = gcnc("", RunOnControllerTest.resumeArgs(resume));
            assertEquals(0, again.status(), again.all());
        }
        assertEquals(RunOnControllerTest.path(whole), RunOnControllerTest.path(stopped));
    }

    /**
     * A limit switch trips at the last segment of a sequence of the stream: the resident program's
     * #LIMSWI stops the axes and turns the spindle off (#FAULT), and the sequence stands at its end, so
     * only the routine's message says so. The host stops there (E825 with the controller's words) and
     * sends no next sequence: it used to go on cutting from where the axes stood, the spindle off, and
     * report "ran to the end".
     */
    @Test
    void aFaultRoutinesMessageStopsTheStream() throws Exception {
        Path p = part(Files.readString(Path.of("docs/examples/bushing.nc")));
        try (VirtualController vc = RunOnControllerTest.traced(100, model("DMC-4040"), null, "limit-at=10")) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--stock",
                    "1.5in,200mm,150mm", "--tcp", RunOnControllerTest.tcp(vc), "--form", "stream");
            assertEquals(3, r.status(), r.all());
            assertTrue(r.err().contains("part.nc:14:1: error[E825]: the controller cannot run the program: its fault routine"
                    + " stopped it ('LIMIT SWITCH AT G-CODE LINE 14')"), r.err());
            assertFalse(r.out().contains("ran to the end"), r.out());
            assertTrue(r.out().contains("executing: line 14"), r.out());
            assertFalse(vc.controller().moving());
        }
    }

    /**
     * The thesis's bishop on its own lathe over a real pseudo-terminal pair, in both forms: the same
     * executed path, segment for segment. The thesis's DMC-1700 is an ISA card gcnc run cannot reach
     * (E830, galil_models.csv host_link = bus), so the lathe's profile is run with a networked DMC-4040
     * in its place (same channels and outputs).
     */
    @Test
    void theBishopRunsThePathStreamedOverAPtyThatItRunsAsOneProgram() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(gcnc.PtyPair.available(), "socat (setup.sh installs it)");
        gcnc.machine.MachineProfile thesis = gcnc.Session.open(gcnc.Session.Options.defaults().withMachine("thesis-2004")).profile();
        double[] g = Plane.of(thesis).galil(thesis.home().x(), thesis.home().z());
        long[] home = {Math.round(g[0]), Math.round(g[1])};
        Path dir = Files.createTempDirectory("gcnc-pty");
        Path bishop = Files.copy(Path.of("samples/bishop.nc"), dir.resolve("bishop.nc"));
        Path lathe = dir.resolve("thesis-2004-dmc4040.machine");
        Files.writeString(lathe, Files.readString(Path.of("tables/machines/thesis-2004.machine"))
                .replace("galil.model = DMC-1700", "galil.model = DMC-4040"));
        List<List<String>> paths = new java.util.ArrayList<>();
        for (String form : List.of("program", "stream")) {
            Path trace = dir.resolve(form + ".trace");
            try (gcnc.PtyPair pty = gcnc.PtyPair.open(dir, "-" + form)) {
                Path b = pty.host;
                try (VirtualController vc = VirtualController.pty(pty.controller,
                        new VirtualController.Options(model("DMC-4040"), 200, List.of(), trace))) {
                    RunOnControllerTest.definePosition(b, home);
                    RunOnControllerTest.Run r = gcnc("", "run", bishop.toString(), "--machine", lathe.toString(), "--port",
                            b.toString(), "--poll", "20", "--form", form);
                    assertEquals(0, r.status(), form + ": " + r.all());
                }
            }
            paths.add(RunOnControllerTest.path(trace));
        }
        assertFalse(paths.get(0).isEmpty());
        assertEquals(paths.get(0), paths.get(1));
    }

    @Test
    void aProgramLongerThanTheControllersMemoryIsStreamedToItsEnd() throws Exception {
        StringBuilder text = new StringBuilder("O4411 (CAM CHORDS)\nG21 G99\nT0101\nG97 S1200 M03\nG00 X19. Z2.\n");
        // 6,300 chords: three to a packed line, more lines than the DMC-4040's 2,000
        for (int pass = 0; pass < 15; pass++) {
            double d = 19 - (pass % 5) * 0.5;
            text.append(String.format(java.util.Locale.ROOT, "G00 X%.3f Z1.%nG01 Z0. F0.3%n", d));
            for (int k = 1; k <= 420; k++) {
                text.append(String.format(java.util.Locale.ROOT, "X%.3f Z%.3f%n", d - 1 + 0.5 * Math.sin(k / 40.0), -k * 0.05));
            }
            text.append(String.format(java.util.Locale.ROOT, "G00 X%.3f%nZ1.%n", d + 1));
        }
        text.append("G00 X40. Z20.\nM05\nM30\n");
        Path p = part(text.toString());
        Path trace = p.resolveSibling("run-auto.trace");
        try (VirtualController vc = VirtualController.tcp(0,
                new VirtualController.Options(model("DMC-4040"), 1000, List.of(), trace))) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--stock", "20,50", "--tcp",
                    "127.0.0.1:" + vc.port(), "--poll", "10", "--format", "json");
            assertEquals(0, r.status(), r.all());
            assertTrue(r.out().contains("\"form\":\"stream\""), r.out().lines().limit(5).toList().toString());
            assertTrue(r.out().contains("\"event\":\"finished\""), r.all());
        }
        assertTrue(Files.readAllLines(p.resolveSibling("part.dmc")).size() < 100, "the resident program is small");
        assertTrue(Files.readAllLines(p.resolveSibling("part.stream")).size() > 2000);
        // the controller ran every sequence to the end the simulator replays for the stream form's two files
        List<String> simulated = gcnc("", "simulate", p.resolveSibling("part.stream").toString(), "--machine", "haas",
                "--stock", "20,50").out().lines().filter(l -> l.startsWith("simulation: ")).toList();
        assertEquals(1, simulated.size(), simulated.toString());
        assertFalse(ends(trace).isEmpty());
        assertTrue(simulated.get(0).contains(" 0 findings"), simulated.get(0));
    }

    /**
     * Behind {@code -PlongRun} (about 25 s): a CAM finishing program of 100,356 blocks (250 passes of
     * 399 chords) compiled to the stream form and streamed to the virtual Galil over loopback TCP to
     * its end; every sequence the simulator replays from the two files ran on the controller.
     */
    @Test
    void aHundredThousandBlockProgramIsStreamedToItsEnd() throws Exception {
        org.junit.jupiter.api.Assumptions.assumeTrue(Boolean.getBoolean("gcnc.longRun"), "gradle junitPlatformTest -PlongRun");
        StringBuilder text = new StringBuilder("%\nO1234 (LONG CAM FINISH)\nG21 G18 G40 G99\nG28 U0. W0.\nT0101\n"
                + "G97 S1200 M03\nG00 X52. Z2. M08\n");
        for (int pass = 0, n = 0; n < 100_000; pass++, n += 403) {
            double d = 50 - (pass % 10) * 0.5;
            text.append(String.format(java.util.Locale.ROOT, "G00 X%.3f Z1.%nG01 Z0. F0.2%n", d));
            for (int k = 1; k < 400; k++) {
                text.append(String.format(java.util.Locale.ROOT, "X%.3f Z%.3f%n", d - 2 + Math.sin(k / 40.0), -k * 0.05));
            }
            text.append(String.format(java.util.Locale.ROOT, "G00 X%.3f%nZ1.%n", d + 2));
        }
        text.append("G00 X60. Z5. M09\nG28 U0. W0. M05\nM30\n%\n");
        Path p = part(text.toString());
        Path trace = p.resolveSibling("run-long.trace");
        try (VirtualController vc = VirtualController.tcp(0,
                new VirtualController.Options(model("DMC-4040"), 1000, List.of(), trace))) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp",
                    "127.0.0.1:" + vc.port(), "--poll", "20", "--quiet");
            assertEquals(0, r.status(), r.all());
        }
        String simulated = gcnc("", "simulate", p.resolveSibling("part.stream").toString(), "--machine", "haas").out()
                .lines().filter(l -> l.startsWith("simulation: ")).findFirst().orElseThrow();
        long sequences = Long.parseLong(simulated.replaceAll("^simulation: (\\d+) sequences.*", "$1"));
        assertEquals(sequences, Files.readAllLines(trace).stream().filter(l -> l.startsWith("# end ")).count(), simulated);
    }

    @Test
    void theProgramFormAskedForAProgramThatDoesNotFitIsRefusedBeforeAnythingMoves() throws Exception {
        StringBuilder text = new StringBuilder("O4412\nG21 G99\nT0101\nG97 S1200 M03\nG00 X19. Z2.\nG01 Z0. F0.3\n");
        for (int k = 1; k <= 6300; k++) { // three chords to a packed line: more than 2,000 lines
            text.append(String.format(java.util.Locale.ROOT, "X%.3f Z%.3f%n", 18.5 + 0.3 * Math.sin(k / 30.0), -k * 0.005));
        }
        text.append("G00 X40.\nZ20.\nM05\nM30\n");
        Path p = part(text.toString());
        RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--stock", "20,50", "--tcp",
                "127.0.0.1:1", "--form", "program");
        assertEquals(1, r.status(), r.all());
        assertTrue(r.all().contains("error[E238]"), r.all());
    }
}
