package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.PART;
import static gcnc.cli.RunOnControllerTest.axes;
import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.homed;
import static gcnc.cli.RunOnControllerTest.model;
import static gcnc.cli.RunOnControllerTest.part;
import static gcnc.cli.RunOnControllerTest.path;
import static gcnc.cli.RunOnControllerTest.programEnd;
import static gcnc.cli.RunOnControllerTest.resumeArgs;
import static gcnc.cli.RunOnControllerTest.resumeCommand;
import static gcnc.cli.RunOnControllerTest.tcp;
import static gcnc.cli.RunOnControllerTest.traced;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.controller.VirtualController;
import gcnc.send.DmcProgram;
import gcnc.send.MapReader;
import gcnc.sim.Sequence;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code gcnc run} sends the blended program: the test part's cut (lines 7 to 10: the approach, the
 * turn, the G02 corner, the face-out) is one vector sequence of four segments, and the run follows it
 * block by block from the controller's {@code _CSS}; a stop inside it names the block of the segment
 * and {@code --resume-at} that block finishes the part along the same path, count for count.
 */
class RunBlendedTest {
    static DmcProgram compiled(Path part) throws Exception {
        return DmcProgram.read(Files.readAllLines(part.resolveSibling("part.dmc")), MapReader.read(
                Files.newBufferedReader(part.resolveSibling("part.dmc.map"))), RunOnControllerTest.haas());
    }

    @Test
    void theCutIsOneSequenceAndTheEventsFollowItsBlocks() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = traced(model("DMC-4040"), null)) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc),
                    "--format", "json", "--poll", "10");
            assertEquals(0, r.status(), r.all());
            // the program downloaded is the blended one: lines 7-10 make one sequence of four segments
            DmcProgram program = compiled(p);
            Sequence cut = program.sequenceAt(program.firstLineOf(8));
            assertEquals(4, cut.pieces().size());
            List<Integer> lines = new ArrayList<>();
            for (Sequence.Piece piece : cut.pieces()) {
                lines.add(program.sourceLine(piece.line()));
            }
            assertEquals(List.of(7, 8, 9, 10), lines);
            // every block of the sequence is reported executing, in order, each naming the one before it completed
            List<String> blocks = new ArrayList<>();
            for (String line : r.out().split("\n")) {
                com.google.gson.JsonObject o = com.google.gson.JsonParser.parseString(line).getAsJsonObject();
                if (o.get("event").getAsString().equals("block")) {
                    blocks.add(o.get("completed").getAsInt() + ">" + o.get("line").getAsInt());
                }
            }
            int at = blocks.indexOf("6>7");
            assertTrue(at >= 0, blocks.toString());
            assertEquals(List.of("6>7", "7>8", "8>9", "9>10", "10>11"), blocks.subList(at, at + 5), blocks.toString());
            assertEquals(Arrays.toString(programEnd(p)), Arrays.toString(axes(vc)));
        }
    }

    /**
     * A limit switch trips half way through the third segment the controller runs: the turn of line 8,
     * the second segment of the blended cut. The run stops there naming line 8 executing and line 7
     * completed; resumed at 8, the rest of the turn, the corner and the face-out are a new sequence from
     * where the axes stopped, and the segments' end points are those of a run never stopped.
     */
    @ParameterizedTest(name = "polled every {0} ms")
    @ValueSource(ints = {20, 1500})
    void aStopInsideTheSequenceResumesAtItsBlockAlongTheSamePath(int poll) throws Exception {
        Path p = part(PART);
        Path stopped = Files.createTempDirectory("gcnc-trace").resolve("stopped.trace");
        try (VirtualController vc = traced(model("DMC-4040"), stopped, "limit-at=3")) {
            homed(vc);
            // polled every 1.5 s the last poll saw the spindle's dwell before the cut: where the axes stopped
            // and _CSS, asked after the stop, still name the turn of line 8
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--poll",
                    Integer.toString(poll));
            assertEquals(3, r.status(), r.all());
            assertTrue(r.err().contains("part.nc:8:1: error[E825]"), r.err());
            assertTrue(r.err().contains("stop code 2: a limit switch"), r.err());
            assertTrue(r.out().contains("stopped: last block completed: line 7; executing: line 8"), r.out());
            String resume = resumeCommand(r.out());
            assertTrue(resume.endsWith("--resume-at 8"), resume);
            RunOnControllerTest.Run again = gcnc("", resumeArgs(resume));
            assertEquals(0, again.status(), again.all());
            assertEquals(Arrays.toString(programEnd(p)), Arrays.toString(axes(vc)));
        }
        assertEquals(6, RunOnControllerTest.uninterruptedPath().size());
        assertEquals(RunOnControllerTest.uninterruptedPath(), path(stopped));
    }
    /**
     * The profiler stops taking segments after the turn (the third segment run, the second of the cut):
     * the run is stopped as stalled naming line 8; resumed there, the axes stand at the turn's end, so
     * the new sequence starts with the corner of line 9, and the path is the uninterrupted run's.
     */
    @Test
    void aStallAtACornerOfTheSequenceResumesWithTheNextSegment() throws Exception {
        Path p = part(PART);
        Path stopped = Files.createTempDirectory("gcnc-trace").resolve("stopped.trace");
        try (VirtualController vc = traced(model("DMC-4040"), stopped, "stall=3")) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--poll", "20",
                    "--stall", "1");
            assertEquals(3, r.status(), r.all());
            assertTrue(r.err().contains("part.nc:8:1: error[E825]"), r.err());
            assertTrue(r.out().contains("stopped: last block completed: line 7; executing: line 8"), r.out());
            String resume = resumeCommand(r.out());
            assertTrue(resume.endsWith("--resume-at 8"), resume);
            RunOnControllerTest.Run again = gcnc("", resumeArgs(resume));
            assertEquals(0, again.status(), again.all());
            assertEquals(Arrays.toString(programEnd(p)), Arrays.toString(axes(vc)));
        }
        assertEquals(RunOnControllerTest.uninterruptedPath(), path(stopped));
    }
}
