package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.homed;
import static gcnc.cli.RunOnControllerTest.model;
import static gcnc.cli.RunOnControllerTest.part;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.controller.VirtualController;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Behind {@code -PlongRun} (about four minutes): the campaign that found this session's sender faults,
 * kept. The bushing of docs/examples runs on the virtual Galil at a hundred times real time in both
 * forms, each run with one injected fault (a refused command, garbage or a dropped link after so many
 * bytes, a stall, a limit switch); what every run must do whatever the fault:
 * <ul>
 *   <li>end with a located diagnostic and status 0, 2 (nothing moved) or 3 (stopped), never a stack trace;</li>
 *   <li>a stop names the blocks, where the axes stand, and a resume command;</li>
 *   <li>that resume, on the same controller, finishes the part at the program's end, or is refused
 *       before anything moves (E827) with a way back that moves X away from the part first.</li>
 * </ul>
 */
class FaultSweepTest {
    private static final List<String> PROGRAM_FORM = List.of("reject=27", "reject=30", "reject=39", "reject=45",
            "stall=5", "stall=50", "limit-at=5", "limit-at=50", "garbage-after=9000");
    private static final List<String> STREAM_FORM = List.of("reject=60", "reject=130", "stall=10", "limit-at=10",
            "limit-at=100", "garbage-after=6000", "disconnect-after=6000");
    private static final Pattern AXES = Pattern.compile(
            "(?m)^axes (at|last seen at) X-?[0-9.]+ Z-?[0-9.]+ \\(Galil counts -?\\d+,-?\\d+\\)");

    @TestFactory
    Stream<DynamicTest> everyFaultEndsLocatedAndEveryResumeIsSafe() {
        org.junit.jupiter.api.Assumptions.assumeTrue(Boolean.getBoolean("gcnc.longRun"), "gradle junitPlatformTest -PlongRun");
        List<DynamicTest> tests = new ArrayList<>();
        for (String f : PROGRAM_FORM) {
            tests.add(DynamicTest.dynamicTest("program " + f, () -> sweep("program", f)));
        }
        for (String f : STREAM_FORM) {
            tests.add(DynamicTest.dynamicTest("stream " + f, () -> sweep("stream", f)));
        }
        return tests.stream();
    }

    private static void sweep(String form, String fault) throws Exception {
        Path p = part(Files.readString(Path.of("docs/examples/bushing.nc")));
        try (VirtualController vc = RunOnControllerTest.traced(100, model("DMC-4040"), null, fault)) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--form", form, "--machine", "haas", "--stock",
                    "1.5in,200mm,150mm", "--tcp", RunOnControllerTest.tcp(vc));
            assertFalse(r.all().contains("Exception"), r.all());
            assertTrue(List.of(0, 2, 3).contains(r.status()), r.all());
            if (r.status() == 0) {
                assertTrue(r.out().contains("ran to the end"), r.all());
                return;
            }
            assertTrue(Pattern.compile("(?m)^\\S*part\\.nc(:\\d+:\\d+)?: error\\[E8\\d\\d\\]").matcher(r.err()).find(), r.err());
            if (r.status() == 2) {
                return; // refused before anything moved
            }
            assertTrue(r.out().contains("stopped: last block completed:")
                    || r.out().contains("the link dropped; the controller may run on"), r.out());
            assertTrue(AXES.matcher(r.out()).find(), r.out());
            String resume = RunOnControllerTest.resumeCommand(r.out());
            RunOnControllerTest.Run again = gcnc("", RunOnControllerTest.resumeArgs(resume));
            assertFalse(again.all().contains("Exception"), again.all());
            if (again.status() == 0) {
                // the bushing ends with G28: at home, in either form
                assertTrue(again.out().contains("ran to the end"), again.all());
                assertArrayEquals(RunOnControllerTest.home(), RunOnControllerTest.axes(vc), again.all());
            } else {
                assertEquals(2, again.status(), again.all());
                assertTrue(again.err().contains("error[E827]") && again.err().contains("move X away from the part first"),
                        again.err());
            }
        }
    }
}
