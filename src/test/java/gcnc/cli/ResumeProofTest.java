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
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Issue 33 item 5, the resume half: a long finishing contour (200 chords, one blended sequence) is
 * interrupted in its middle on the virtual controller by a limit trip, a stall, a refused command and
 * a dropped link; the resume the run prints finishes the part, and the segment ends the controller
 * executed over both runs are those of the run never interrupted, point by point. No refusal (E827)
 * and so no jog advice comes in between: each resume follows from where the axes are. (The stream
 * form's commands are the segments, so the N-th command and the N-th byte fall inside the contour
 * whatever the clock; in the program form a dropped link's byte count lands in the contour only in a
 * window a few hundred bytes wide that depends on how often the host polled, so it is not here.)
 */
class ResumeProofTest {
    /** The chords: X from 40 to 48 (diameter) over Z 0 to -40 along a quarter of a cosine. */
    static final int CHORDS = 200;

    static String contour() {
        List<String> l = new ArrayList<>(List.of("O1004 (FINISHING CONTOUR)", "G21 G99", "G50 S2500", "T0101",
                "G97 S1200 M03", "G00 X52. Z2.", "G01 X40. Z0. F0.2"));
        for (int k = 1; k <= CHORDS; k++) {
            double s = (double) k / CHORDS;
            l.add(String.format(Locale.ROOT, "X%.3f Z%.3f", 40 + 8 * (1 - Math.cos(Math.PI / 2 * s)), -40 * s));
        }
        l.addAll(List.of("G01 X52.", "G00 X60. Z5.", "M05", "M30", ""));
        return String.join("\n", l);
    }

    /** The bytes of each form's DMC and stream: what the host sends before the contour moves. */
    static final java.util.Map<String, Long> SENT = new java.util.HashMap<>();
    /** Each form's uninterrupted path, run once for the class. */
    static final java.util.Map<String, List<String>> WHOLE = new java.util.HashMap<>();

    /** {@link #contour} run to its end without a stop in {@code form}: the segment ends a resumed run must repeat. */
    static synchronized List<String> uninterrupted(String form) throws Exception {
        if (WHOLE.containsKey(form)) {
            return WHOLE.get(form);
        }
        Path p = part(contour());
        long sent = 0;
        Path trace = p.resolveSibling("whole.trace");
        try (VirtualController vc = traced(RunOnControllerTest.FAST, model("DMC-4040"), trace)) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--form", form);
            assertEquals(0, r.status(), r.all());
        }
        for (String f : List.of("part.dmc", "part.stream")) {
            if (Files.exists(p.resolveSibling(f))) {
                sent += Files.size(p.resolveSibling(f));
            }
        }
        SENT.put(form, sent);
        WHOLE.put(form, List.copyOf(path(trace)));
        return WHOLE.get(form);
    }

    @ParameterizedTest(name = "{0} in the {1} form")
    @CsvSource({"limit-at=100, program", "stall=100, program", "reject=150, stream", "disconnect-after=4000, stream",
            "disconnect-after-begun, stream"})
    void aFaultInTheMiddleOfALongContourResumesOnTheUninterruptedPath(String fault, String form) throws Exception {
        List<String> whole = uninterrupted(form);
        assertTrue(whole.size() > CHORDS, "the contour's chords are executed: " + whole.size());
        Path p = part(contour());
        Path stopped = Files.createTempDirectory("gcnc-trace").resolve("stopped.trace");
        // after its BGS: the resident program and every segment sent, and some polls while it moves
        String given = fault.equals("disconnect-after-begun") ? "disconnect-after=" + (SENT.get(form) + 500) : fault;
        try (VirtualController vc = traced(RunOnControllerTest.FAST, model("DMC-4040"), stopped, given)) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--form", form,
                    "--poll", "20", "--stall", "1");
            assertEquals(3, r.status(), r.all());
            if (fault.startsWith("disconnect")) {
                // the link dropped: the controller runs on without the host (E851), to rest in controller time
                assertTrue(r.err().contains("error[E851]"), r.err());
                assertFalse(r.out().contains("stopped:"), r.out());
                vc.controller().settle(600);
            }
            String resume = resumeCommand(r.out());
            // in the contour, lines 7 (its first block, where a sequence of which nothing moved resumes) to 207
            int at = Integer.parseInt(resume.replaceAll(".*--resume-at (\\d+).*", "$1"));
            assertTrue(at >= 7 && at <= 7 + CHORDS, resume);
            RunOnControllerTest.Run again = gcnc("", resumeArgs(resume));
            assertEquals(0, again.status(), again.all());
            assertFalse(again.all().contains("E827"), again.all());
            if (fault.equals("disconnect-after-begun")) {
                // the controller ran out its buffer without the host: the resume says what it did
                assertTrue(again.out().contains("the controller finished the sequence") || again.out().contains(
                        "the controller ran on"), again.out());
            }
        }
        assertEquals(whole, path(stopped));
    }
}
