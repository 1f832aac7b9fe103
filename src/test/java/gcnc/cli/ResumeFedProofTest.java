package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.homed;
import static gcnc.cli.RunOnControllerTest.model;
import static gcnc.cli.RunOnControllerTest.part;
import static gcnc.cli.RunOnControllerTest.path;
import static gcnc.cli.RunOnControllerTest.resumeArgs;
import static gcnc.cli.RunOnControllerTest.resumeCommand;
import static gcnc.cli.RunOnControllerTest.tcp;
import static gcnc.cli.RunOnControllerTest.traced;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.controller.VirtualController;
import gcnc.send.ResumeFedTest;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A resume inside a sequence longer than the buffer, on the virtual controller (issue 33): the
 * 1,200-chord contour of {@link ResumeFedTest} (one sequence, fed while it runs; M08 at chord 400 and
 * M09 at chord 1,000 on the way) stopped by a limit trip some 200 chords in, in each form, so that
 * 1,000 segments and both coolant switches are still ahead, and some 520 chords in, past M08. The resume must feed the buffer (the controller refuses a
 * segment given to a full buffer: TC 1 "buffer full" would stop it), finish on the uninterrupted run's
 * path point by point, and switch the coolant on and off on the way (the coolant is off at the end,
 * as M09 leaves it; a downloaded program's trace shows both trip points passed in the resumed run). The stream form's host sends one segment per reply:
 * its controller runs at twice real time, not {@link RunOnControllerTest#FAST}, at which the chords
 * (0.034 mm each at 4 mm/s: some 120 a second in real time) would outrun the loopback link and starve the
 * buffer (E890), which is not what this test is about.
 */
class ResumeFedProofTest {
    /** The coolant's output on haas (M08 SB3, M09 CB3). */
    static final int COOLANT = 3;

    @ParameterizedTest(name = "{0} in the {1} form")
    @CsvSource({"limit-at=200, program, 20", "limit-at=520, program, 20", "limit-at=200, stream, 2"})
    void aResumeWithMostOfALongContourLeftIsFedAndSwitchesTheCoolantOnTheWay(String fault, String form, double speed)
            throws Exception {
        Path p = part(ResumeFedTest.contour());
        Path whole = p.resolveSibling("whole.trace");
        try (VirtualController vc = traced(speed, model("DMC-4040"), whole)) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--form", form);
            assertEquals(0, r.status(), r.all());
        }
        // the trace counts the trip points a downloaded program passes (in the stream form the host waits
        // for them itself, polling _AVS, and the controller sees the outputs alone)
        boolean downloaded = form.equals("program");
        assertEquals(downloaded ? 2 : 0, tripped(whole), "the uninterrupted run switches the coolant on and off on the way");
        Path stopped = Files.createTempDirectory("gcnc-trace").resolve("stopped.trace");
        try (VirtualController vc = traced(speed, model("DMC-4040"), stopped, fault)) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--form", form,
                    "--poll", "20");
            assertEquals(3, r.status(), r.all());
            String resume = resumeCommand(r.out());
            int at = Integer.parseInt(resume.replaceAll(".*--resume-at (\\d+).*", "$1"));
            // in the contour (its first chord is line 8), with more than the buffer left
            assertTrue(at >= 8 && at < 8 + ResumeFedTest.CHORDS - 511, resume);
            // M08 ahead (limit-at=200), or passed and restored as the state the resume sets (limit-at=520)
            boolean on = at > 7 + ResumeFedTest.COOLANT_ON;
            assertEquals(fault.equals("limit-at=520"), on, resume);
            assertEquals(downloaded && on ? 1 : 0, tripped(stopped), "the switches before the stop");
            RunOnControllerTest.Run again = gcnc("", resumeArgs(resume));
            assertEquals(0, again.status(), again.all());
            assertFalse(again.all().contains("E827"), again.all());
            // the pre-flight gives where the axes stopped as the program writes it, the counts after it
            assertTrue(java.util.regex.Pattern.compile("axes at X4[0-9]\\.\\d{3} Z-\\d+\\.\\d{3} \\(Galil counts -?\\d+,-?\\d+\\)")
                    .matcher(again.out()).find(), again.out());
            assertFalse(vc.controller().output(COOLANT), "M09 switched the coolant off on the way");
        }
        assertEquals(downloaded ? 2 : 0, tripped(stopped), "each trip point passed once over both runs: none dropped");
        assertEquals(path(whole), path(stopped));
    }

    /** The AV trip points the controller passed ({@code # av n tripped at ...} of its trace). */
    static long tripped(Path trace) throws java.io.IOException {
        List<String> l = Files.readAllLines(trace);
        return l.stream().filter(s -> s.matches("# av -?\\d+ tripped at .*")).count();
    }
}
