package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.model;
import static gcnc.cli.RunOnControllerTest.tcp;
import static gcnc.cli.RunOnControllerTest.tell;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.controller.VirtualController;
import gcnc.send.CompiledRun;
import gcnc.send.DmcProgram;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * A resume's estimate is the compile's clock left from where it takes the program up: for
 * {@code --resume-at N:K}, from motion K of line N, not from line N's first motion. The bushing's G71
 * (line 14) makes dozens of motions; resumed at its 35th, the run said "about 0:01:36" and its first
 * status line "0:01:06 left".
 */
class ResumeEstimateTest {
    @Test
    void aResumeAtTheKthMotionOfABlockEstimatesTheTimeFromThatMotion() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-estimate");
        Path p = dir.resolve("bushing.nc");
        Files.copy(Path.of("docs/examples/bushing.nc"), p);
        String text = Files.readString(p);
        Session session = Session.open(Session.Options.defaults().withMachine("haas"));
        CompiledRun seen = new CompiledRun();
        session.compile(new StringReader(text), java.util.Optional.of(session.simulation()), false, line -> { }, seen);
        DmcProgram program = seen.program(session.profile());
        List<DmcProgram.Motion> motions = program.motionsOf(14);
        int k = 35;
        DmcProgram.Motion m = motions.get(k - 1);
        assertEquals(0, m.from(), "motion 35 of the G71 starts a sequence of its own");
        double expected = program.totalSeconds() - program.secondsBefore(m.sequence().first());
        double fromTheLine = program.totalSeconds() - program.secondsBefore(program.firstLineOf(14));
        assertTrue(fromTheLine - expected > 10, "the passes before motion 35 take time: " + fromTheLine + " " + expected);
        double[] at = m.start();
        try (VirtualController vc = RunOnControllerTest.fast(model("DMC-4040"))) {
            assertEquals(":", tell(vc, "DP " + Math.round(at[0]) + "," + Math.round(at[1])));
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc),
                    "--resume-at", "14:" + k, "--dry-run", "--format", "json");
            assertEquals(0, r.status(), r.all());
            assertEquals(expected, RunTimeTest.started(r).get("seconds").asDouble(), 0.0015, r.out());
        }
    }
}
