package gcnc.send;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.Fixed;
import gcnc.dmc.SequencePart;
import gcnc.dmc.StreamSplit;
import gcnc.sim.Sequence;
import java.util.ArrayList;
import java.util.List;

/**
 * The rest of an interrupted vector sequence as a sequence of its own, for {@link Resume}: from where
 * the axes are, the remaining part of the segment they are on, then the sequence's later segments,
 * each with its own speeds and its VP measured from the new origin; what the sequence set on the way
 * ({@code AV}, then the outputs and spindle speeds of its trip point), for every trip point still
 * ahead; and, as the compile writes a sequence longer than the buffer (docs/galil.md, "Continuous
 * contouring"), {@code BGS} once the first fill is given and a wait for room ({@code JS #LMWAIT})
 * before each further batch, so that the new sequence never gives more segments than the buffer
 * holds ({@code LM}: 511 on the DMC-40x0). The trip points are written where the compile writes them:
 * at the wait for room by which their segment is {@link StreamSplit#TRIP_LEAD} segments inside the
 * buffer, else after {@code VE}.
 *
 * <p>{@code AV} is relative ("from the start of a coordinated move sequence or from the last AV
 * command", command reference AV): the original's trip points are the sums of its AVs; the first one
 * kept is written from the new sequence's start (the path already run taken off), each later one
 * from the trip point before it.
 */
final class Replan {
    /** The re-planned rest of a sequence, and its commands the axes are already past (the state they set). */
    record Result(Download.Builder lines, List<Integer> passed) {
    }

    /** One segment of the new sequence: its command, the compiled line it continues, its path length. */
    private record Segment(Command command, int origin, double length) {
    }

    /** A trip point of the original: its distance from the original's start, its AV, and what it sets. */
    private record Trip(long at, int av, List<Integer> sets) {
    }

    private final DmcProgram program;
    /** The segments given before {@code BGS} when the sequence is fed (the model's buffer less the slot VE takes). */
    private final int fill;

    /**
     * @param fill the segments a sequence longer than the buffer gives before its {@code BGS}
     *             ({@code Integer.MAX_VALUE}: unknown, taken from the interrupted sequence itself)
     */
    Replan(DmcProgram program, int fill) {
        this.program = program;
        this.fill = fill;
    }

    /**
     * The rest of sequence {@code s} from {@code axes}: its piece {@code k} from where the axes are
     * ({@code partial}) or whole, then the later pieces; each line's origin is the compiled line it
     * continues, so the controller's segment numbers ({@code _CSS}) of the new sequence still name
     * the G-code blocks.
     */
    Result of(Sequence s, int k, boolean partial, double[] axes, ResumePoint at) throws RunFault {
        List<Sequence.Piece> pieces = s.pieces();
        List<Segment> segments = segments(s, k, partial, axes);
        double run = s.lengthBefore(k) + (partial ? along(pieces.get(k), axes) : 0);
        int firstKept = pieces.get(k).line();

        Layout o = layout(s, firstKept);
        int feedFrom = o.fedFill() >= 0 ? o.fedFill() : fill;
        int wait = roomWait(o, segments.size(), feedFrom, s, at);
        List<Integer> loose = o.loose();
        List<Integer> passed = o.passed();
        // the trip points the axes are past set the state; the others are kept, measured on the new path
        List<Trip> ahead = new ArrayList<>();
        for (Trip t : o.trips()) {
            if (t.at() <= run) {
                passed.addAll(t.sets());
            } else {
                ahead.add(t);
            }
        }
        int[] tripSegment = tripSegments(ahead, segments, run);

        Download.Builder b = new Download.Builder();
        int vs = s.first();
        Command speed = program.command(vs);
        b.add(speed instanceof Command.VectorSpeed ? speed : new Command.VectorSpeed(Fixed.of(Math.round(s.speed()))), vs);
        Writer w = new Writer(b, ahead, tripSegment, run);
        boolean begun = false;
        int li = 0;
        for (int j = 0; j < segments.size(); j++) {
            if (j >= feedFrom && (j - feedFrom) % StreamSplit.BUFFER_BATCH == 0) {
                if (!begun) {
                    b.add(new Command.BeginSequence(), o.bgs());
                    begun = true;
                }
                w.trips(j - StreamSplit.TRIP_LEAD);
                b.add(new Command.Call(StreamSplit.BUFFER_WAIT), wait);
            }
            Segment g = segments.get(j);
            b.add(g.command(), g.origin());
            // what the original gave after this segment, before its next one
            int next = j + 1 < segments.size() ? segments.get(j + 1).origin() : o.ve() < 0 ? s.last() : o.ve();
            for (; li < loose.size() && loose.get(li) < next; li++) {
                b.add(program.command(loose.get(li)), loose.get(li));
            }
        }
        b.add(new Command.VectorEnd(), o.ve());
        for (; li < loose.size(); li++) {
            b.add(program.command(loose.get(li)), loose.get(li));
        }
        if (!begun) {
            b.add(new Command.BeginSequence(), o.bgs());
        }
        w.trips(Integer.MAX_VALUE);
        b.add(program.command(s.last()), s.last());
        return new Result(b, passed);
    }

    /**
     * The wait for room the new sequence feeds its later batches with: the original's, else the
     * program's routine when the rest is longer than the buffer holds before BGS; E827 when there is none.
     */
    private int roomWait(Layout o, int segments, int feedFrom, Sequence s, ResumePoint at) throws RunFault {
        if (segments <= feedFrom || o.roomWait() >= 0) {
            return o.roomWait();
        }
        int wait = waitRoutine();
        if (wait < 0) {
            throw new RunFault(Code.E827_CANNOT_RESUME, at.line(), false, at, "the rest of the sequence from line "
                    + at.line() + " is " + segments + " segments, more than the buffer holds before BGS ("
                    + feedFrom + "), and the program has no wait for room (#" + StreamSplit.BUFFER_WAIT
                    + ") to feed it with: resume at the sequence's first block, line "
                    + program.sourceLine(s.pieces().get(0).line()));
        }
        return wait;
    }

    /**
     * The original sequence's structure: its BGS (before VE when it was fed; {@code fedFill} the
     * segments given before it then, else -1), its wait for room ({@code roomWait}), its VE (-1 for each it lacks), its trip
     * points with what each sets, the commands between its segments that belong to none of them
     * ({@code loose}) and those of them before the first kept piece ({@code passed}: the state).
     */
    private record Layout(int bgs, int roomWait, int ve, int fedFill, List<Trip> trips, List<Integer> loose,
                          List<Integer> passed) {
    }

    private Layout layout(Sequence s, int firstKept) {
        int bgs = -1;
        int wait = -1;
        int ve = -1;
        int fedFill = -1;
        int given = 0;
        long trip = 0;
        List<Trip> trips = new ArrayList<>();
        List<Integer> loose = new ArrayList<>();
        List<Integer> passed = new ArrayList<>();
        Trip open = null;
        for (int i = s.first(); i <= s.last(); i++) {
            Command c = program.command(i);
            SequencePart part = SequencePart.of(c);
            if (i == s.first() && part == SequencePart.SPEED || i == s.last()) {
                open = null; // the sequence's own VS and its AMS
                continue;
            }
            open = switch (part) {
                case SEGMENT -> {
                    given++;
                    yield null;
                }
                case BEGIN -> {
                    bgs = i;
                    if (ve < 0) {
                        fedFill = given;
                    }
                    yield null;
                }
                case ROOM_WAIT -> {
                    wait = i;
                    yield null;
                }
                case VECTOR_END -> {
                    ve = i;
                    yield null;
                }
                case TRIP -> {
                    trip += ((Command.AfterVector) c).counts();
                    Trip t = new Trip(trip, i, new ArrayList<>());
                    trips.add(t);
                    yield t;
                }
                case SPEED, AWAIT, OUTSIDE, NONE -> {
                    if (open != null) {
                        open.sets().add(i);
                    } else if (i < firstKept) {
                        passed.add(i); // between segments already run: part of the state
                    } else {
                        loose.add(i);
                    }
                    yield open;
                }
            };
        }
        return new Layout(bgs, wait, ve, fedFill, trips, loose, passed);
    }

    /**
     * The segment of the new sequence each kept trip point's motion starts with: the segments that
     * end at or before it (a trip point is the whole count at or before its motion's start).
     */
    private static int[] tripSegments(List<Trip> ahead, List<Segment> segments, double run) {
        int[] tripSegment = new int[ahead.size()];
        double end = 0;
        int n = 0;
        for (int t = 0; t < ahead.size(); t++) {
            double d = ahead.get(t).at() - run;
            while (n < segments.size() && end + segments.get(n).length() <= d + 1) {
                end += segments.get(n).length();
                n++;
            }
            tripSegment[t] = n;
        }
        return tripSegment;
    }

    /** Writes the kept trip points, each AV from the one before it (the first from the new start). */
    private final class Writer {
        private final Download.Builder b;
        private final List<Trip> ahead;
        private final int[] segmentOf;
        private int written;
        /** Where the next AV measures from, in the original's counts: the new start, then each trip point written. */
        private double from;

        Writer(Download.Builder b, List<Trip> ahead, int[] segmentOf, double run) {
            this.b = b;
            this.ahead = ahead;
            this.segmentOf = segmentOf;
            this.from = run;
        }

        /** The trip points not yet written whose segment is {@code upTo} or before. */
        void trips(int upTo) {
            for (; written < ahead.size() && segmentOf[written] <= upTo; written++) {
                Trip t = ahead.get(written);
                long n = Math.round(t.at() - from);
                b.add(new Command.AfterVector(n), t.av());
                from += n; // the controller's trip point, a fraction of a count off the original's at most
                for (int i : t.sets()) {
                    b.add(program.command(i), i);
                }
            }
        }
    }

    /** The program's wait for room (a {@code JS #LMWAIT} of another sequence), or -1 when it has none. */
    private int waitRoutine() {
        for (int i = 0; i < program.size(); i++) {
            if (program.command(i) instanceof Command.Call call && call.label().equals(StreamSplit.BUFFER_WAIT)) {
                return i;
            }
        }
        return -1;
    }

    /** The segments of the rest: piece {@code k} from the axes ({@code partial}) or whole, then the later ones. */
    private List<Segment> segments(Sequence s, int k, boolean partial, double[] axes) {
        List<Segment> out = new ArrayList<>();
        double[] cursor = axes;
        List<Sequence.Piece> pieces = s.pieces();
        for (int j = k; j < pieces.size(); j++) {
            Sequence.Piece p = pieces.get(j);
            Command c = program.command(p.line());
            if (p instanceof Sequence.Arc a) {
                Command.CircularArc cr = (Command.CircularArc) c;
                if (j == k && partial) {
                    double theta = Math.toDegrees(Math.atan2(axes[1] - a.centre()[1], axes[0] - a.centre()[0]));
                    double delta = Resume.sweepTo(theta, a.theta() + a.delta(), a.delta());
                    cr = new Command.CircularArc(cr.radius(), Fixed.fourDecimals(theta), Fixed.fourDecimals(delta), cr.speeds());
                }
                double[] g = Command.CircularArc.geometry(cursor[0], cursor[1], cr.radius().value(), cr.start().value(),
                        cr.sweep().value());
                out.add(new Segment(cr, p.line(), Math.abs(cr.radius().value() * Math.toRadians(cr.sweep().value()))));
                cursor = new double[] {g[2], g[3]};
                boolean closes = j == pieces.size() - 1 || pieces.get(j + 1) instanceof Sequence.Arc;
                if (closes && Math.hypot(cursor[0] - a.to()[0], cursor[1] - a.to()[1]) >= 0.5) {
                    // the arc from the stop ends a count or so off: close on the target
                    out.add(new Segment(vp(a.to(), axes, cr.speeds()), p.line(),
                            Math.hypot(cursor[0] - a.to()[0], cursor[1] - a.to()[1])));
                    cursor = a.to();
                }
            } else {
                Command.Speeds speeds = c instanceof Command.VectorPosition v ? v.speeds() : Command.Speeds.NONE;
                out.add(new Segment(vp(p.to(), axes, speeds), p.line(), Math.hypot(p.to()[0] - cursor[0],
                        p.to()[1] - cursor[1])));
                cursor = p.to();
            }
        }
        return out;
    }

    /** How far along piece {@code p} a point on it is, counts of path. */
    static double along(Sequence.Piece p, double[] q) {
        if (p instanceof Sequence.Arc a) {
            double ang = Math.toDegrees(Math.atan2(q[1] - a.centre()[1], q[0] - a.centre()[0]));
            return Math.abs(Math.toRadians(Resume.sweepTo(a.theta(), ang, a.delta()))) * a.radius();
        }
        return Math.hypot(q[0] - p.from()[0], q[1] - p.from()[1]);
    }

    /** {@code VP} to {@code to} from the new sequence's origin {@code origin}, whole counts. */
    private static Command vp(double[] to, double[] origin, Command.Speeds speeds) {
        return new Command.VectorPosition(Math.round(to[0] - origin[0]), Math.round(to[1] - origin[1]), speeds);
    }
}
