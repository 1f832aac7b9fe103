package gcnc.galil;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.Fixed;
import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Feed;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.plan.Piece;
import gcnc.plan.Step;
import gcnc.plan.Switch;
import java.util.function.Consumer;

/**
 * Writes a planned group (docs/galil.md, "Continuous contouring"): one vector sequence, every
 * segment at its own speed with its corner speed, {@code VS <first speed>}, then {@code VP a,b <o >p}
 * and {@code CR r,θ,Δθ <o >p} measured from the sequence's start, {@code VE}, {@code BGS}; what is
 * set on the way, one mechanism for both: the spindle speeds of the motions that change it (G96) and
 * the outputs that switch on the fly ({@code plan.on_the_fly}), each after {@code AV <distance>}:
 * the trip point is the path the written segments measure up to the start of its motion (a whole count
 * at or before it, so that the controller always reaches it), and {@code AV} is written as the distance
 * from the previous trip point of the sequence (from its start for the first), since Galil measures it
 * "from the start of a coordinated move sequence or from the last AV command" (command reference AV;
 * DMC-40x0 User Manual p.86, "After Relative Vector distance"); the distances of a sequence add up to
 * its last trip point, never past the path's end (docs/galil.md, "Set on the way"); after {@code VE}
 * and {@code BGS} for a sequence that fits the buffer, and in one fed while it runs also before each
 * wait for room, for the trip points {@link #TRIP_LEAD} segments inside the buffer by then (the VM
 * reference lets segments be given during the motion; AV waits on the path while they run);
 * {@code AMS} with the reason the machine stops there. Speeds are even, 2 or more (Galil's
 * resolution for {@code <} and {@code >}), rounded down, never up.
 */
final class GroupWriter {
    private final GalilDialect d;
    private final Consumer<Instruction> sink;
    /**
     * Whether the group being written sets anything on the way, so that the written path must be
     * measured for its trip points; most groups set nothing, and their lengths (a hypot per VP, the
     * trigonometry of an arc's closing move) are not worked out.
     */
    private boolean measuring;
    /**
     * Where the controller's path is within the group being written, counts: the whole count of the
     * last VP's target, or where the last CR really ends (its printed radius and angles, from where
     * it started), a fraction of a count off its target. A CR starts there, not at the count the
     * arc was planned from, so a chain of arcs would carry each one's fraction into the next.
     */
    private double atU;
    private double atV;

    /** The share of the stopping speed a closing move at a sequence's end is given (as the planner's margin). */
    private static final double STOP_MARGIN = 0.9;

    /**
     * The segments given before {@code BGS} when a sequence is longer than the buffer: all slots but
     * the one VE takes (COMALL VM: "Up to 511 segments may be given before the Begin Sequence").
     */
    private final int fill;
    /**
     * The segments written after each wait for room: the wait ({@code JS #LMWAIT}, MachineCode) lets
     * them through once {@code _LMS} counts this many free slots and one more for VE.
     */
    static final int BATCH = gcnc.dmc.StreamSplit.BUFFER_BATCH;

    /*
     * The sequence being written, kept from one group to the next while it goes on (Step.Group#goesOn):
     * where it started, the writer of the last block, the path written so far, its segments, and
     * whether BGS has started it (after the first fill), with its trip points.
     */
    private long u0;
    private long v0;
    private boolean started;
    private BlockWriter out;
    private double along;
    private int segments;
    private boolean begun;
    private java.util.List<Piece> onTheWay = new java.util.ArrayList<>();
    private java.util.List<Double> at = new java.util.ArrayList<>();
    /** The segment each trip point's motion starts with (0 for the sequence's first), and how many trip points are written. */
    private java.util.List<Integer> atSegment = new java.util.ArrayList<>();
    private int tripsWritten;
    /** The last trip point written, counts from the sequence's start; -1 before the first. */
    private long tripped;
    /**
     * How far inside the buffer a trip point's segment must be before its {@code AV} is written in a
     * sequence fed while it runs: the program waits there until the path reaches it, and does not feed
     * meanwhile, so the buffer then still holds at least this many segments after it; written before
     * the next wait for room, the trip point is still ahead of the path (at most 510 segments are in the
     * buffer, so the path is at least 210 behind it when the program runs as fast as the motion needs).
     */
    static final int TRIP_LEAD = gcnc.dmc.StreamSplit.TRIP_LEAD;

    GroupWriter(GalilDialect dialect, Consumer<Instruction> sink) {
        this.d = dialect;
        this.sink = sink;
        this.fill = d.bufferSegments() - 1;
    }

    /** A joined motion's programmed feed: null for a rapid; only straight moves and arcs are joined. */
    private static final Motion.Visitor<Feed> FEED = new Motion.Visitor<>() {
        @Override
        public Feed linear(Motion.Linear l) {
            return l.rapid() ? null : l.feed();
        }

        @Override
        public Feed arc(Motion.Arc a) {
            return a.feed();
        }

        @Override
        public Feed dwell(Motion.Dwell w) {
            throw new IllegalStateException("a dwell is never joined into a sequence");
        }

        @Override
        public Feed thread(Motion.Thread t) {
            throw new IllegalStateException("a thread pass is never joined into a sequence");
        }
    };

    /** Writes a group: a whole sequence, or one window of it (the next group goes on from where this one ends). */
    void write(Step.Group g) {
        if (!g.continues()) {
            begin();
        }
        int n = g.pieces().size();
        // a sequence in windows is measured throughout: a trip point in a later window counts the path before it
        measuring = g.onTheWay() || g.continues() || g.goesOn();
        for (int k = 0; k < n; k++) {
            Piece p = g.pieces().get(k);
            CheckedBlock b = p.block();
            out = d.writer(b, sink);
            out.motion(p.motion());
            Motion m = p.path();
            Feed feed = m.accept(FEED);
            long vs = d.speed(b, feed);
            if (vs < 0) {
                continue; // reported (E207, E201): the output is void
            }
            boolean last = k == n - 1 && !g.goesOn();
            Command.Speeds speeds = new Command.Speeds(Math.min(vs, evenDown(p.speed())), last ? 0 : evenDown(p.exit()));
            if (!started) {
                d.speedLine(vs, feed != null, out);
                started = true;
            }
            if (p.onTheWay()) {
                onTheWay.add(p);
                at.add(along);
                atSegment.add(segments);
            }
            along += written(p, b, m, speeds);
        }
        if (!started || g.goesOn()) {
            return;
        }
        out.emit(new Command.VectorEnd());
        if (!begun) {
            out.emit(new Command.BeginSequence()); // the whole sequence fitted the buffer: started after VE
        }
        BlockWriter out = trips(Integer.MAX_VALUE, this.out);
        out.emit(new Command.AwaitSequence(g.stop()));
    }

    /** The start of a sequence: its position, and nothing written or measured of it yet. */
    private void begin() {
        u0 = d.posU;
        v0 = d.posV;
        atU = u0;
        atV = v0;
        started = false;
        out = null;
        along = 0; // the path written so far, counts, as the controller measures it for AV
        segments = 0;
        begun = false;
        // the pieces with something on the way and the path before each (always array lists: a group
        // that measures after many that do not must not meet another list type in compiled code)
        onTheWay = new java.util.ArrayList<>();
        at = new java.util.ArrayList<>();
        atSegment = new java.util.ArrayList<>();
        tripsWritten = 0;
        tripped = -1;
    }

    /** Writes piece {@code p} (motion {@code m} of block {@code b}) at {@code speeds}; returns the path it adds (counts). */
    private double written(Piece p, CheckedBlock b, Motion m, Command.Speeds speeds) {
        return m.accept(new Motion.Visitor<Double>() {
            @Override
            public Double arc(Motion.Arc a) {
                return GroupWriter.this.arc(b, a, u0, v0, speeds, out);
            }

            @Override
            public Double linear(Motion.Linear l) {
                if (p.parts() == 1) {
                    return straight(b, l.to(), u0, v0, speeds, out);
                }
                // one of the equal pieces of a move longer than a VP segment: to its share of the way
                double share = (p.part() + 1) / (double) p.parts();
                double fu = d.plane().galil1(l.from());
                double fv = d.plane().galil2(l.from());
                return straight(b, fu + (d.plane().galil1(l.to()) - fu) * share, fv + (d.plane().galil2(l.to()) - fv) * share,
                        u0, v0, speeds, out);
            }

            @Override
            public Double dwell(Motion.Dwell w) {
                return straight(b, null, u0, v0, speeds, out);
            }

            @Override
            public Double thread(Motion.Thread t) {
                return straight(b, null, u0, v0, speeds, out);
            }
        });
    }

    /**
     * Writes the trip points not yet written whose motions start at segment {@code upTo} or before,
     * each {@code AV} relative to the last; returns the writer the last command went to ({@code out}
     * when none is written).
     */
    private BlockWriter trips(int upTo, BlockWriter out) {
        for (; tripsWritten < onTheWay.size() && atSegment.get(tripsWritten) <= upTo; tripsWritten++) {
            int i = tripsWritten;
            Piece p = onTheWay.get(i);
            long trip = (long) Math.floor(at.get(i));
            BlockWriter w = d.writer(p.block(), sink);
            w.motion(p.motion());
            if (trip != tripped) {
                w.emit(new Command.AfterVector(trip - Math.max(0, tripped))); // relative to the last AV
                tripped = trip;
            }
            // in program order: what earlier blocks left on the way, then this block's speed and outputs
            for (Switch s : p.switches()) {
                if (s.block() != p.block()) {
                    w = outputs(s, w);
                }
            }
            if (p.spindle()) {
                w = d.writer(p.block(), sink);
                d.spindle(p.block(), p.block().spindleRpm().getAsDouble(), w);
            }
            for (Switch s : p.switches()) {
                if (s.block() == p.block()) {
                    w = outputs(s, w);
                }
            }
            out = w;
        }
        return out;
    }

    /**
     * Gives the controller one segment of the sequence. A sequence longer than the buffer is started
     * ({@code BGS}) once the first {@link #fill} segments are in it, and fed while it runs: before
     * each further {@link #BATCH} segments the program waits for that many free slots and one for VE
     * ({@code JS #LMWAIT}: COMALL VM, "Additional segments may be given during the motion when the
     * buffer frees additional spaces"; _LMS, "the number of spaces available in the sequence buffer").
     */
    private void segment(Command c, BlockWriter out) {
        if (segments >= fill && (segments - fill) % BATCH == 0) {
            if (!begun) {
                out.emit(new Command.BeginSequence());
                begun = true;
            }
            // the trip points well inside the buffer, while it runs: the path reaches them before the
            // buffer could run dry (TRIP_LEAD), and the outputs switch where the path is
            if (trips(segments - TRIP_LEAD, out) != out) {
                d.resume(out); // the segments go on in their own block's writer
            }
            d.awaitBuffer(BATCH + 1, out);
        }
        out.emit(c);
        segments++;
    }

    /** The outputs of {@code s} (after the trip point already written), in the writer of their own block. */
    private BlockWriter outputs(Switch s, BlockWriter w) {
        BlockWriter own = d.writer(s.block(), sink);
        if (own != w) {
            own.motion(-1);
        }
        d.outputs(s.block(), s.calls(), own);
        return own;
    }

    /** A VP to {@code to}; its length, counts (0 when nothing is written or nothing is {@link #measuring}). */
    private double straight(CheckedBlock b, Point to, long u0, long v0, Command.Speeds speeds, BlockWriter out) {
        return straight(b, d.plane().galil1(to), d.plane().galil2(to), u0, v0, speeds, out);
    }

    /** A VP to the Galil point (u, v), rounded to whole counts; its length, counts (0 when nothing is written). */
    private double straight(CheckedBlock b, double u, double v, long u0, long v0, Command.Speeds speeds,
                            BlockWriter out) {
        long tu = GalilNumbers.round(u);
        long tv = GalilNumbers.round(v);
        if (!d.inRange(b, "VP", tu - u0) || !d.inRange(b, "VP", tv - v0)) {
            return 0;
        }
        if (tu == d.posU && tv == d.posV) {
            return 0; // no move: a segment of no length is TC 30
        }
        segment(new Command.VectorPosition(tu - u0, tv - v0, speeds), out);
        double written = measuring ? Math.hypot(tu - d.posU, tv - d.posV) : 0;
        d.posU = tu;
        d.posV = tv;
        atU = tu;
        atV = tv;
        return written;
    }

    /** A CR (and its closing VP) for the arc; its length, counts (0 when nothing is written). */
    private double arc(CheckedBlock b, Motion.Arc m, long u0, long v0, Command.Speeds speeds, BlockWriter out) {
        long tu = GalilNumbers.round(d.plane().galil1(m.to()));
        long tv = GalilNumbers.round(d.plane().galil2(m.to()));
        if (!d.inRange(b, "CR", tu - u0) || !d.inRange(b, "CR", tv - v0)
                || !d.inRange(b, "CR", GalilNumbers.round(m.radius()))) {
            return 0;
        }
        ArcPlanner.Written written = ArcPlanner.forMotion(d.plane(), d.posU, d.posV, m);
        if (written == null) {
            return straight(b, m.to(), u0, v0, speeds, out);
        }
        ArcPlanner.Cr cr = written.cr();
        if (cr == null) {
            d.error(Code.E202_ARC_NOT_REPRESENTABLE, b, GalilNumbers.round(m.radius()));
            return 0;
        }
        // where the printed CR ends, about the centre its start angle implies from where the path
        // is (after another CR, a fraction of a count off the count this arc was planned from)
        double theta = Math.toRadians(Fixed.fourDecimals(cr.start()).value());
        double end = theta + Math.toRadians(Fixed.fourDecimals(cr.sweep()).value());
        double eu = atU - cr.radius() * Math.cos(theta) + cr.radius() * Math.cos(end);
        double ev = atV - cr.radius() * Math.sin(theta) + cr.radius() * Math.sin(end);
        // a closing VP to the target when the arc ends short (the planner's), or when the fraction
        // carried along a chain of arcs brings its end nearer another count than the target's (as
        // the planner's own closing VPs, never shorter than a count in whole counts): the next
        // sequence then starts on the target's count, not a count off, and no chain of arcs drifts
        // by half a count per arc
        boolean closing = cr.closing() || GalilNumbers.round(eu) != tu || GalilNumbers.round(ev) != tv;
        // the controller's path length of a CR: its radius times its sweep
        double length = measuring ? cr.radius() * Math.toRadians(Math.abs(Fixed.fourDecimals(cr.sweep()).value())) : 0;
        if (!closing) {
            segment(new Command.CircularArc(Fixed.of(cr.radius()), Fixed.fourDecimals(cr.start()),
                    Fixed.fourDecimals(cr.sweep()), speeds), out);
            atU = eu;
            atV = ev;
        } else {
            // the closing move keeps the corner speed; where the sequence ends, the arc slows to a
            // speed the machine can stop from within that move (a count or two)
            double gap = Math.hypot(tu - eu, tv - ev); // from where the printed arc ends to the target
            long closeAt = speeds.end() != 0 ? speeds.end()
                    : Math.min(speeds.speed(), evenDown(STOP_MARGIN * Math.sqrt(2 * d.stopping() * gap)));
            segment(new Command.CircularArc(Fixed.of(cr.radius()), Fixed.fourDecimals(cr.start()),
                    Fixed.fourDecimals(cr.sweep()), new Command.Speeds(speeds.speed(), closeAt)), out);
            segment(new Command.VectorPosition(tu - u0, tv - v0, new Command.Speeds(closeAt, speeds.end())), out);
            length += measuring ? gap : 0;
            atU = tu;
            atV = tv;
        }
        d.posU = tu;
        d.posV = tv;
        return length;
    }

    /** The even speed at or below {@code v}, at least 2. */
    static long evenDown(double v) {
        return Math.max(2, 2 * (long) Math.floor(v / 2));
    }
}
