package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.PART;
import static gcnc.cli.RunOnControllerTest.axes;
import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.home;
import static gcnc.cli.RunOnControllerTest.homed;
import static gcnc.cli.RunOnControllerTest.model;
import static gcnc.cli.RunOnControllerTest.part;
import static gcnc.cli.RunOnControllerTest.path;
import static gcnc.cli.RunOnControllerTest.programEnd;
import static gcnc.cli.RunOnControllerTest.tcp;
import static gcnc.cli.RunOnControllerTest.traced;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.controller.VirtualController;
import gcnc.machine.Plane;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@code gcnc run --resume-at N --way-back FEED} against the virtual Galil: the way back E827
 * advises made leg by leg (one axis at a time), then the resume to the end; and its refusals, with
 * nothing moved: a leg the simulator finds cutting the part, a missing word, a feed too high.
 */
class WayBackRunTest {
    /** A resume at {@code line} from home (off the path) with the way back at {@code feed}, {@code input} typed. */
    private static RunOnControllerTest.Run resume(VirtualController vc, Path p, String line, String feed, String input,
                                                  String... more) {
        List<String> args = new java.util.ArrayList<>(List.of("run", p.toString(), "--machine", "haas", "--tcp", tcp(vc),
                "--resume-at", line, "--way-back", feed, "--poll", "20"));
        args.addAll(List.of(more));
        return gcnc(input, args.toArray(new String[0]));
    }

    private static double[] end(String counts) {
        String[] f = counts.split(" ");
        return new double[] {Double.parseDouble(f[0]), Double.parseDouble(f[1])};
    }

    @Test
    void theWayBackMovesXThenZThenXAndTheResumeFinishesThePart() throws Exception {
        Path p = part(PART);
        Path trace = p.resolveSibling("wayback.trace");
        try (VirtualController vc = traced(RunOnControllerTest.FAST, model("DMC-4040"), trace)) {
            homed(vc);
            // a controller that never ran the program (powered up after the fault): it holds no TOOL, and
            // the question for it must not leave an error that the resumed program's end reads in _TC
            int before = path(trace).size();
            homed(vc);
            // at home, off line 7's path (X42 Z2 to X40 Z2): home is farther out than the clear X42, so
            // X keeps its place; then Z to Z2 and X in to X42 (X41.999 in its counts) in front of the face
            RunOnControllerTest.Run r = resume(vc, p, "7", "3000", "move\n", "--confirm-from-stdin");
            assertEquals(0, r.status(), r.all());
            assertTrue(r.out().contains("way back: Z, to X"), r.out());
            assertTrue(r.out().contains("way back: X in to the block's start, to X41.999 Z2.000 (Galil counts "), r.out());
            List<String> ends = path(trace).subList(before, path(trace).size());
            // machine X and Z of home and of each leg's end (the plane's counts in the profile's order)
            Plane plane = Plane.of(RunOnControllerTest.haas());
            long[] h = home();
            double[] from = plane.machine(new double[] {h[0], h[1]});
            double[] z = plane.machine(end(ends.get(0)));
            double[] x = plane.machine(end(ends.get(1)));
            // the Z leg keeps X at home, the X leg keeps the Z the Z leg reached: never a diagonal
            assertEquals(from[0], z[0], 0.5, ends.toString());
            assertTrue(Math.abs(z[1] - from[1]) > 1000, ends.toString());
            assertEquals(z[1], x[1], 0.5, ends.toString());
            assertTrue(Math.abs(x[0] - z[0]) > 1000, ends.toString());
            assertArrayEquals(programEnd(p), axes(vc));
        }
    }

    /**
     * A resume from home with the way back at {@code feed}, {@code input} typed, on a controller of its own:
     * refused before anything moved (exit 2), the axes still at home; returns what it wrote on standard error.
     */
    private static String refused(String line, String feed, String input, String... more) throws Exception {
        try (VirtualController vc = traced(RunOnControllerTest.FAST, model("DMC-4040"), null)) {
            homed(vc);
            RunOnControllerTest.Run r = resume(vc, part(PART), line, feed, input, more);
            assertEquals(2, r.status(), r.all());
            assertArrayEquals(home(), axes(vc));
            return r.err();
        }
    }

    @Test
    void aLegThatWouldCutThePartIsRefusedAndNothingMoves() throws Exception {
        // line 9's start is X40 Z-30, below the blank's face: X in there goes through the stock
        String err = refused("9", "3000", "move\n", "--confirm-from-stdin");
        assertTrue(err.contains("part.nc:9:1: error[E838]: the way back's leg X in to the block's start to X40.000"
                + " Z-30.000 (Galil counts "), err);
        assertTrue(err.contains("the simulator found E"), err);
        // a dry run checks the legs as well, and refuses the same
        String dry = refused("9", "3000", "", "--dry-run");
        assertTrue(dry.contains("error[E838]: the way back's leg X in to the block's start"), dry);
    }

    @Test
    void aDryRunChecksTheWayBackAndMakesNone() throws Exception {
        try (VirtualController vc = traced(RunOnControllerTest.FAST, model("DMC-4040"), null)) {
            homed(vc);
            RunOnControllerTest.Run r = resume(vc, part(PART), "7", "3000", "", "--dry-run");
            assertEquals(0, r.status(), r.all());
            assertTrue(r.out().contains("dry run: the way back was checked and not made: move X away from the part first,"
                    + " to X423.999 Z363.000 (Galil counts " + home()[0] + "," + home()[1] + "), then Z, to "), r.out());
            assertArrayEquals(home(), axes(vc));
        }
    }

    @Test
    void withoutTheWordNothingMoves() throws Exception {
        String err = refused("7", "3000", "yes\n", "--confirm-from-stdin");
        assertTrue(err.contains("error[E839]: the way back moves the axes: it runs only after the word 'move' is"
                + " typed ('yes' was typed)"), err);
        // standard input is no terminal here: the word is taken from it only when asked to
        String notAsked = refused("7", "3000", "move\n");
        assertTrue(notAsked.contains("error[E839]") && notAsked.contains("give --confirm-from-stdin"), notAsked);
    }

    @Test
    void aFeedAboveTheMachinesOrNoneIsRefused() throws Exception {
        String err = refused("7", "1000000", "move\n", "--confirm-from-stdin");
        assertTrue(err.contains("error[E837]: the way back cannot move at feed 1000000: the machine's fastest"
                + " cutting feed is F"), err);
        String zero = refused("7", "0", "move\n", "--confirm-from-stdin");
        assertTrue(zero.contains("error[E837]") && zero.contains("never a rapid"), zero);
        // no feed at all is a usage error, before anything is compiled or connected
        RunOnControllerTest.Run none = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", "127.0.0.1:1",
                "--resume-at", "7", "--way-back");
        assertEquals(2, none.status(), none.all());
        assertTrue(none.err().contains("--way-back"), none.err());
    }
}
