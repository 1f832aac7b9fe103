package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Session;
import gcnc.dmc.Command;
import gcnc.dmc.DmcPrinter;
import gcnc.dmc.StreamSplit;
import gcnc.sim.Sequence;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.junit.jupiter.api.Test;

/**
 * A resume inside a sequence longer than the buffer (issue 33): the compile feeds such a sequence
 * ({@code BGS} after 510 segments, {@code JS #LMWAIT} before each further 100) and writes its trip
 * points between segments, at the waits for room; the rest of it from a resume point is fed the same
 * way and keeps every trip point still ahead, with what it sets (here M08 and M09, coolant on and off
 * on the way, bit 3 on haas).
 */
public class ResumeFedTest {
    /** The chords of the contour, and the ones that switch the coolant on and off on the way. */
    public static final int CHORDS = 1200;
    public static final int COOLANT_ON = 400;
    public static final int COOLANT_OFF = 1000;

    /** 1,200 chords, X 40 to 48 (diameter) over Z 0 to -40 along a quarter of a cosine; M08 at chord 400, M09 at 1000. */
    public static String contour() {
        List<String> l = new ArrayList<>(List.of("O1006 (LONG FINISH, COOLANT ON THE WAY)", "G21 G99", "G50 S2500",
                "T0101", "G97 S1200 M03", "G00 X52. Z2.", "G01 X40. Z0. F0.2"));
        for (int k = 1; k <= CHORDS; k++) {
            double s = (double) k / CHORDS;
            l.add(String.format(Locale.ROOT, "X%.3f Z%.3f", 40 + 8 * (1 - Math.cos(Math.PI / 2 * s)), -40 * s)
                    + (k == COOLANT_ON ? " M08" : k == COOLANT_OFF ? " M09" : ""));
        }
        l.addAll(List.of("G01 X52.", "G00 X60. Z5.", "M05", "M30", ""));
        return String.join("\n", l);
    }

    /** The contour's sequence (the one of most segments) of the compiled program. */
    static Sequence contourOf(DmcProgram p) {
        Sequence most = p.sequences().get(0);
        for (Sequence s : p.sequences()) {
            most = s.pieces().size() > most.pieces().size() ? s : most;
        }
        return most;
    }

    /** A trip point: its distance along the path (counts) and what it sets, as printed. */
    record Trip(double at, List<String> sets) {
    }

    /** The trip points of commands {@code from} to {@code to} of {@code commands}: the sums of their AVs, from {@code start}. */
    static List<Trip> trips(List<Command> commands, int from, int to, double start) {
        List<Trip> t = new ArrayList<>();
        double at = start;
        List<String> sets = null;
        for (int i = from; i <= to; i++) {
            Command c = commands.get(i);
            if (c instanceof Command.AfterVector av) {
                at += av.counts();
                sets = new ArrayList<>();
                t.add(new Trip(at, sets));
            } else if (DmcProgram.isSegment(c) || c instanceof Command.Call || c instanceof Command.VectorEnd
                    || c instanceof Command.BeginSequence || c instanceof Command.AwaitSequence) {
                sets = null;
            } else if (sets != null) {
                sets.add(DmcPrinter.print(c));
            }
        }
        return t;
    }

    static List<Command> commands(DmcProgram p) {
        List<Command> c = new ArrayList<>();
        for (int i = 0; i < p.size(); i++) {
            c.add(p.command(i));
        }
        return c;
    }

    /** The first and last command of the piece's re-planned sequence: its VS and its AMS. */
    static int[] replanned(Download r, Sequence s) {
        int vs = -1;
        for (int j = 0; j < r.commands().size(); j++) {
            if (vs < 0 && r.originOf(j) == s.first() && r.commands().get(j) instanceof Command.VectorSpeed) {
                vs = j;
            }
            if (vs >= 0 && r.commands().get(j) instanceof Command.AwaitSequence) {
                return new int[] {vs, j};
            }
        }
        throw new AssertionError("no re-planned sequence");
    }

    /**
     * The buffer as the re-planned sequence gives it: the segments before BGS, and the most given
     * between two waits for room (or after the last before VE); -1 for BGS when it comes after VE.
     */
    static int[] feeding(List<Command> c, int from, int to) {
        int before = -1;
        int given = 0;
        int batch = 0;
        int most = 0;
        boolean waited = false;
        for (int i = from; i <= to; i++) {
            if (DmcProgram.isSegment(c.get(i))) {
                given++;
                batch++;
            } else if (c.get(i) instanceof Command.BeginSequence && before < 0) {
                before = given;
                batch = 0;
            } else if (c.get(i) instanceof Command.Call call && call.label().equals(StreamSplit.BUFFER_WAIT)) {
                most = waited ? Math.max(most, batch) : most;
                waited = true;
                batch = 0;
            } else if (c.get(i) instanceof Command.VectorEnd) {
                most = waited ? Math.max(most, batch) : most;
                if (before < 0) {
                    before = given; // all of it before BGS (BGS after VE)
                }
            }
        }
        return new int[] {before, most, given};
    }

    @Test
    void aResumeWithMoreThanTheBufferLeftIsFedAndKeepsBothCoolantSwitches() throws Exception {
        ResumeTest.Compiled c = ResumeTest.compiled(contour());
        DmcProgram p = c.program();
        Sequence s = contourOf(p);
        assertEquals(CHORDS + 2, s.pieces().size(), "the contour is one sequence: the feed in, the chords, the feed out");
        List<Trip> original = trips(commands(p), s.first(), s.last(), 0);
        assertEquals(2, original.size(), original.toString());
        // resumed part way along chord 150 (1,051 chords left): its rest, then chords 151 to 1,200
        int k = 150;
        Sequence.Piece on = s.pieces().get(k);
        double[] axes = {Math.round((on.from()[0] + on.to()[0]) / 2), Math.round((on.from()[1] + on.to()[1]) / 2)};
        Resume resume = new Resume(p, c.blocks(), 3).spindle(Session.open(Session.Options.defaults().withMachine("haas"))
                .profile());
        Download r = resume.plan(new ResumePoint(p.sourceLine(on.line()), 0), axes);
        int[] at = replanned(r, s);
        int[] fed = feeding(r.commands(), at[0], at[1]);
        assertEquals(s.pieces().size() - k, fed[2], "every segment from the resume point on");
        // as the compile feeds it: BGS once 510 segments are in the buffer (511 slots, VE takes one),
        // then at most 100 after each wait for room
        assertEquals(510, fed[0]);
        assertEquals(StreamSplit.BUFFER_BATCH, fed[1]);
        // both coolant switches, at the trip points of the original measured from the resume point
        double run = s.lengthBefore(k) + Math.hypot(axes[0] - on.from()[0], axes[1] - on.from()[1]);
        List<Trip> kept = trips(r.commands(), at[0], at[1], run);
        assertEquals(original.size(), kept.size(), kept.toString());
        for (int t = 0; t < original.size(); t++) {
            assertEquals(original.get(t).at(), kept.get(t).at(), 1.0, "trip point " + t);
            assertEquals(original.get(t).sets(), kept.get(t).sets());
        }
        assertTrue(original.get(0).sets().contains("SB3") && original.get(1).sets().contains("CB3"), original.toString());
        // and each is written once its segment is at least TRIP_LEAD segments inside the buffer, as the compile does
        assertTripsLead(r.commands(), at[0], at[1], run, s, k);
    }

    /** Each AV comes after VE, or after the segments up to its trip point and TRIP_LEAD more have been given. */
    static void assertTripsLead(List<Command> c, int from, int to, double run, Sequence s, int k) {
        double trip = run;
        int given = 0;
        boolean ended = false;
        List<Double> ends = new ArrayList<>(); // where each segment from the resume point on ends, original's counts
        for (int j = k; j < s.pieces().size(); j++) {
            ends.add(s.lengthBefore(j + 1));
        }
        for (int i = from; i <= to; i++) {
            if (DmcProgram.isSegment(c.get(i))) {
                given++;
            } else if (c.get(i) instanceof Command.VectorEnd) {
                ended = true;
            } else if (c.get(i) instanceof Command.AfterVector av) {
                trip += av.counts();
                int before = 0;
                while (before < ends.size() && ends.get(before) <= trip + 1) {
                    before++;
                }
                assertTrue(ended || given - before >= StreamSplit.TRIP_LEAD, "AV at " + trip + " written after " + given
                        + " segments, its own the " + before + "th");
            }
        }
    }

    @Test
    void pastTheFirstSwitchItIsStateAndTheSecondIsKeptInASequenceThatFitsTheBuffer() throws Exception {
        ResumeTest.Compiled c = ResumeTest.compiled(contour());
        DmcProgram p = c.program();
        Sequence s = contourOf(p);
        List<Trip> original = trips(commands(p), s.first(), s.last(), 0);
        // at the start of chord 800: 402 segments left, M08 behind, M09 200 chords ahead
        int k = 800;
        Sequence.Piece on = s.pieces().get(k);
        Download r = new Resume(p, c.blocks(), 3).plan(new ResumePoint(p.sourceLine(on.line()), 0), on.from());
        int[] at = replanned(r, s);
        List<String> printed = r.commands().stream().map(DmcPrinter::print).toList();
        assertTrue(printed.subList(0, at[0]).contains("SB3"), "the coolant the program switched on before the point");
        int[] fed = feeding(r.commands(), at[0], at[1]);
        assertEquals(s.pieces().size() - k, fed[2]);
        assertEquals(fed[2], fed[0], "the rest fits the buffer: BGS after VE");
        assertTrue(!printed.subList(at[0], at[1]).contains("JS #" + StreamSplit.BUFFER_WAIT), "no wait for room");
        List<Trip> kept = trips(r.commands(), at[0], at[1], s.lengthBefore(k));
        assertEquals(1, kept.size(), kept.toString());
        assertEquals(original.get(1).at(), kept.get(0).at(), 1.0);
        assertEquals(original.get(1).sets(), kept.get(0).sets());
    }
}
