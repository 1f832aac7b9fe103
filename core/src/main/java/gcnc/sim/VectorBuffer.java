package gcnc.sim;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.machine.Plane;
import java.util.ArrayList;
import java.util.List;

/**
 * The controller's coordinated motion (COMALL VM): where the plane axes stand, in whole Galil
 * counts; the vector sequence being buffered (VP, CR, from the sequence's start), whether VE
 * ended it or BGS began it before its VE (fed while it runs); the sequence that started last
 * with its path lengths, and the AV trip point on it the commands after it wait for. It hands a
 * started sequence to the {@link ReplayListener}; which command starts it is the
 * {@link ReplayController}'s.
 */
final class VectorBuffer {
    private static final double INT32 = 2147483647;

    private final Plane plane;
    private final ReplayListener out;
    /** Where each motion lies, for whoever listens (the sender's view of the program). */
    private final SequenceLog log;
    private double g1;
    private double g2;
    private double seqStart1;
    private double seqStart2;
    private double cursor1;
    private double cursor2;
    private List<Segment> pending = new ArrayList<>();
    /** VE came for the segments pending (the whole sequence in the buffer before BGS). */
    private boolean vectorEnded;
    /** BGS came before VE: the segments after it join the running sequence until VE (COMALL VM). */
    private boolean begun;
    /** The begun sequence is fed while it runs: gcnc's wait for room (JS #LMWAIT) followed its BGS. */
    private boolean fed;
    /**
     * A {@code NO G01} comment came before this sequence: gcnc marks a feed whose speed equals the
     * rapid speed so that a bare replay does not take it for a rapid (docs/dmc-format.md).
     */
    private boolean feedMarked;
    /**
     * The segments of the last sequence started (the list {@link #pending} was, swapped at BGS: no
     * copy), kept for the trip points after it, which {@link #measure} works out only when an AV asks.
     */
    private List<Segment> last = new ArrayList<>();
    /** Whether {@link #reached} stands for {@link #last} yet. */
    private boolean measured = true;
    /** The last sequence started: each segment's end, counts of path from its start (what AV measures). */
    private double[] reached = new double[64];
    /** How many of {@link #reached} (and {@link #reachedBy}) stand for the last sequence. */
    private int reachedCount;
    private final List<gcnc.dmc.Source> reachedBy = new ArrayList<>();
    /**
     * The AV trip point the commands after it wait for, counts of path from the sequence's start (the
     * sum of its AVs so far); -1 when none (after BGS, before the first AV; at rest after AMS).
     */
    private long avTrip = -1;

    VectorBuffer(Plane plane, ReplayListener out, SequenceLog log) {
        this.plane = plane;
        this.out = out;
        this.log = log;
    }

    /** A command of a motion runs (VS, a thread pass's GA; a segment): the log's motion starts here if none is under way. */
    void open() {
        log.open(g1, g2);
    }

    /** AMS, a thread pass's AM: the motion that ran is waited for. */
    void waited() {
        log.waited();
    }

    /** Puts the axes at a position (machine counts): the start, or a resync after a mismatch. */
    void moveTo(double x, double z) {
        g1 = Math.rint(plane.galil1(x, z));
        g2 = Math.rint(plane.galil2(x, z));
    }

    double x() {
        return plane.machineX(g1, g2);
    }

    double z() {
        return plane.machineZ(g1, g2);
    }

    /** Where the first plane axis stands, Galil counts. */
    double galil1() {
        return g1;
    }

    /** Where the second plane axis stands, Galil counts. */
    double galil2() {
        return g2;
    }

    boolean hasPending() {
        return !pending.isEmpty();
    }

    void dropPending() {
        pending.clear();
    }

    /** {@code NO G01}: the next sequence is a feed whatever its speed. */
    void markFeed() {
        feedMarked = true;
    }

    boolean feedMarked() {
        return feedMarked;
    }

    /** Whether a BGS began the sequence before its VE came. */
    boolean begun() {
        return begun;
    }

    /** Whether the begun sequence is fed while it runs (the wait for room followed its BGS). */
    boolean fed() {
        return fed;
    }

    /** The wait for room after a BGS: the begun sequence is fed while it runs. */
    void feed() {
        fed = true;
    }

    /** VE for a sequence not begun: it is whole in the buffer. */
    void end() {
        vectorEnded = true;
    }

    /**
     * BGS: true when the sequence is to start now (VE came, or nothing is buffered); else it is
     * begun, and its segments after this join it until its VE (a sequence longer than the buffer).
     */
    boolean begin() {
        if (vectorEnded || pending.isEmpty()) {
            return true;
        }
        begun = true;
        fed = false;
        return false;
    }

    /** VP: a straight segment to (p, q) from the sequence's start. */
    void vp(Command.VectorPosition c, Instruction at) {
        Command.Speeds speeds = c.speeds();
        startIfNeeded();
        double e1 = seqStart1 + c.first();
        double e2 = seqStart2 + c.second();
        log.line(cursor1, cursor2, e1, e2);
        // made with its speeds (no copy: one per replayed segment)
        add(new Segment(plane.machineX(cursor1, cursor2), plane.machineZ(cursor1, cursor2),
                plane.machineX(e1, e2), plane.machineZ(e1, e2), false, 0, 0, 0, 0, 0, at,
                speeds.speed() == 0 ? Double.NaN : speeds.speed(), speeds.end() == 0 ? Double.NaN : speeds.end()),
                e1, e2, Command.Speeds.NONE, at);
    }

    /** CR: an arc of radius r from the start angle through the sweep, degrees. */
    void cr(Command.CircularArc c, Instruction at) {
        startIfNeeded();
        double[] end = new double[2];
        Segment arc = Segment.cr(plane, cursor1, cursor2, c.radius().value(), c.start().value(), c.sweep().value(), at, end);
        if (log.listening()) {
            // the centre back in the plane (exact: the machine frame only changes signs)
            log.arc(cursor1, cursor2, end[0], end[1], plane.galil1(arc.centreX(), arc.centreZ()),
                    plane.galil2(arc.centreX(), arc.centreZ()), c.radius().value(), c.start().value(), c.sweep().value());
        }
        add(arc, end[0], end[1], c.speeds(), at);
    }

    private void startIfNeeded() {
        open();
        if (pending.isEmpty()) {
            seqStart1 = g1;
            seqStart2 = g2;
            cursor1 = g1;
            cursor2 = g2;
        }
    }

    private void add(Segment s, double e1, double e2, Command.Speeds speeds, Instruction at) {
        if (speeds.any()) {
            s = s.withSpeeds(speeds.speed() == 0 ? Double.NaN : speeds.speed(), speeds.end() == 0 ? Double.NaN : speeds.end());
        }
        if (Math.abs(e1) > INT32 || Math.abs(e2) > INT32) {
            out.report(Code.E310_SIM_COUNT_RANGE, at.source(), "the end point of '" + s.text() + "'");
        }
        pending.add(s);
        cursor1 = e1;
        cursor2 = e2;
    }

    /** Starts the sequence buffered (if any) at {@code speed}: the listener hears it, the axes end where it does. */
    void start(double speed, gcnc.dmc.Source at) {
        begun = false;
        vectorEnded = false;
        if (pending.isEmpty()) {
            return;
        }
        log.started(speed, cursor1, cursor2, false);
        // The controller's position is whole counts: an arc that ends a fraction off its target
        // leaves the axes at the nearest count, and the next sequence starts from there.
        g1 = Math.rint(cursor1);
        g2 = Math.rint(cursor2);
        avTrip = -1;
        // The listener reads the segments during the call and keeps none of them.
        out.sequence(pending, speed, at);
        // kept for the trip points after it (the path lengths only when an AV asks: most sequences have none)
        List<Segment> free = last;
        last = pending;
        measured = false;
        pending = free;
        pending.clear();
        feedMarked = false;
    }

    /** A sequence that is not the buffer's (a geared thread pass, which always cuts), ending at (end1, end2). */
    void run(List<Segment> segments, double speed, double end1, double end2, gcnc.dmc.Source at) {
        log.started(speed, end1, end2, true);
        g1 = end1;
        g2 = end2;
        feedMarked = true;
        out.sequence(segments, speed, at);
        feedMarked = false;
    }

    /** Each segment's end in the last sequence started, counts of path from its start (what AV measures). */
    private void measure() {
        if (measured) {
            return;
        }
        measured = true;
        reachedCount = 0;
        reachedBy.clear();
        double along = 0;
        if (reached.length < last.size()) {
            reached = new double[Math.max(last.size(), 2 * reached.length)];
        }
        for (Segment g : last) {
            along += g.arc() ? g.radius() * Math.toRadians(Math.abs(g.sweepDeg()))
                    : Math.hypot(g.toX() - g.fromX(), g.toZ() - g.fromZ());
            reached[reachedCount++] = along; // unboxed: one per replayed segment
            reachedBy.add(g.source());
        }
    }

    /**
     * {@code AV n}: the trip point moves n counts of path on. AV is relative (command reference AV:
     * "from the start of a coordinated move sequence or from the last AV command"), so its trip point
     * is the last one's plus n; it must be on the path: what the controller does at an AV it never
     * reaches the reference does not say, so the safe reading is that it waits there for ever
     * (docs/simulator.md): E334.
     */
    void afterVector(Command.AfterVector c, gcnc.dmc.Source at) {
        measure();
        double total = reachedCount == 0 ? 0 : reached[reachedCount - 1];
        long trip = Math.max(0, avTrip) + c.counts();
        if (trip > total + 1) {
            out.report(Code.E334_SIM_TRIP_PAST_END, at, c.counts(), trip, Math.round(total));
        }
        avTrip = trip;
    }

    /** AMS: what follows is at rest, after no trip point. */
    void atRest() {
        log.waited();
        avTrip = -1;
    }

    /** The AV trip point the command being run waits for, counts of path; -1 when none. */
    long trip() {
        return avTrip;
    }

    /**
     * The sources of the segments within a count of the trip point (the one it falls in, and its
     * neighbour when it is at their joint); null when there is no trip point or no path to it.
     */
    List<gcnc.dmc.Source> around() {
        if (avTrip < 0) {
            return null;
        }
        measure();
        if (reachedCount == 0) {
            return null;
        }
        List<gcnc.dmc.Source> around = new ArrayList<>(2);
        double from = 0;
        for (int k = 0; k < reachedCount; k++) {
            double to = reached[k];
            if (avTrip >= from - 1 && avTrip <= to + 1 && reachedBy.get(k) != null) {
                around.add(reachedBy.get(k));
            }
            from = to;
        }
        return around;
    }
}
