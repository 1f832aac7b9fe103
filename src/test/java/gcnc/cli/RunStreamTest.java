package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.homed;
import static gcnc.cli.RunOnControllerTest.model;
import static gcnc.cli.RunOnControllerTest.part;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.controller.VirtualController;
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

    @Test
    void aProgramLongerThanTheControllersMemoryIsStreamedToItsEnd() throws Exception {
        StringBuilder text = new StringBuilder("O4411 (CAM CHORDS)\nG21 G99\nT0101\nG97 S1200 M03\nG00 X19. Z2.\n");
        for (int pass = 0; pass < 5; pass++) {
            double d = 19 - pass * 0.5;
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
                new VirtualController.Options(model("DMC-4040"), 200, List.of(), trace))) {
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

    @Test
    void theProgramFormAskedForAProgramThatDoesNotFitIsRefusedBeforeAnythingMoves() throws Exception {
        StringBuilder text = new StringBuilder("O4412\nG21 G99\nT0101\nG97 S1200 M03\nG00 X19. Z2.\nG01 Z0. F0.3\n");
        for (int k = 1; k <= 2100; k++) {
            text.append(String.format(java.util.Locale.ROOT, "X%.3f Z%.3f%n", 18.5 + 0.3 * Math.sin(k / 30.0), -k * 0.01));
        }
        text.append("G00 X40.\nZ20.\nM05\nM30\n");
        Path p = part(text.toString());
        RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--stock", "20,50", "--tcp",
                "127.0.0.1:1", "--form", "program");
        assertEquals(1, r.status(), r.all());
        assertTrue(r.all().contains("error[E238]"), r.all());
    }
}
