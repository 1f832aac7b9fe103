package gcnc.sim;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Instruction;
import gcnc.dmc.Source;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import gcnc.machine.Plane;
import java.util.ArrayList;
import java.util.List;

/**
 * Replays the emitted DMC on a model of the lathe (docs/simulator.md): streams block by block in
 * constant memory (the path is kept only for an SVG), and reports each problem as a located
 * diagnostic at the G-code line of the DMC line that caused it, column 1.
 */
public final class Simulator {
    private final MachineProfile profile;
    private final SimOptions options;
    private final Diagnostics diagnostics;
    private final Plane plane;
    private final ReplayController dmc;
    private final OutputState outputs;
    private final MotionChecks checks;
    private final SimMachine machine;
    /** The stations already warned of as not described (E321/E322): once per station, not per tool change. */
    private final java.util.Set<Integer> undescribed = new java.util.HashSet<>();
    private final Trace trace;
    private final Corners corners;
    /** The motions the checker meant that the DMC has not carried out yet; null for a bare replay (nothing to compare with). */
    private ExpectedMotions expected;
    private int findings;
    /** The last DMC line replayed ({@link Source#NONE} before any): where a sequence still open at the end is. */
    private Source lastRun = Source.NONE;
    /**
     * The last DMC line replayed that has a G-code line of its own. A line from no block (the header,
     * the footer, which the backend writes with line 0) has no file either, yet its finding must be in
     * one: it goes to line 1 of this one's file, the file the replay was last in (the main program's
     * until a located line has run). Kept so on purpose: it is where the replay has always put them,
     * and a value taken here rather than a file set wherever a finding is made.
     */
    private Source lastLocated = Source.NONE;

    /** How far a geared thread pass may end from its exact end before it is E317, mm. */
    static final double THREAD_TOLERANCE_MM = 0.005;

    public Simulator(MachineProfile profile, SimOptions options, Diagnostics diagnostics) {
        this.profile = profile;
        this.options = options;
        this.diagnostics = diagnostics;
        this.plane = Plane.of(profile);
        this.outputs = new OutputState(profile);
        this.machine = SimMachine.read(profile);
        this.checks = new MotionChecks(profile, machine, options, this::report);
        if (!checks.hasStock()) {
            // No stock, no stock check: never collisions with a guessed blank (chuck, tailstock and travel still run).
            diagnostics.report(new Diagnostic(Code.E316_SIM_NO_STOCK, gcnc.diag.Severity.NOTE, Span.of(1, 1), List.of()));
        }
        Events events = new Events();
        ThreadGearing gearing = new ThreadGearing(plane, profile.encoder().map(e -> Plane.channel(e.channel())).orElse(-1),
                profile.encoder().map(e -> e.countsPerRev()).orElse(0), profile.rpmPerVolt(),
                threadTolerance(profile, options), events);
        // the spindle's volts come from AO, not the OF of its channel, when an analog output drives it
        int spindleAnalog = gcnc.machine.MachineIo.of(profile).drive()
                instanceof gcnc.machine.MachineIo.SpindleDrive.Analog a ? a.output() : -1;
        this.dmc = new ReplayController(plane, profile.home().x(), profile.home().z(), profile.acceleration(),
                profile.deceleration(), profile.rapidSpeed(), profile.spindleAxis(), spindleAnalog, gearing, events,
                sequences);
        this.trace = options.trace() == null ? null : new Trace(options.trace(), profile);
        this.corners = new Corners(profile, this::report);
    }

    /**
     * How far, in counts, a geared thread pass may end from its settling move (E317) or turn into
     * its chamfer from where the program's chamfer starts (E308): 5 micrometres, or two counts, or
     * the conformance tolerance, whichever is largest; far below any thread's pitch tolerance
     * (docs/threading.md), above what GR's four decimals leave.
     */
    static double threadTolerance(MachineProfile profile, SimOptions options) {
        return Math.max(Math.max(2, options.tolerance()), THREAD_TOLERANCE_MM * profile.z().countsPerMm());
    }

    /** How many DMC lines have been replayed. */
    private int dmcLines;

    /**
     * Told of every DMC line replayed, with the cycle clock before and after it (gcnc.CompileObserver#replayed),
     * and of every motion that ran, at the line that waits for it, after that line ({@link Sequence};
     * gcnc.CompileObserver#sequence).
     */
    @FunctionalInterface
    public interface Replayed {
        void line(Instruction line, double secondsBefore, double secondsAfter);

        default void sequence(Sequence s) {
        }
    }

    private Replayed replayed;
    /** Where each motion lies, told to {@link #replayed}. */
    private final SequenceLog sequences = new SequenceLog();

    /** Tells {@code r} of every line replayed and every motion run from now on (null: nobody). */
    public void onReplayed(Replayed r) {
        replayed = r;
        sequences.listen(r);
    }

    public void begin(List<Instruction> header) {
        run(header);
    }

    /**
     * One G-code block: what the checker meant, and the DMC the backend wrote when it was given it
     * (its own, or a sequence that ends with it and carries the blocks before it too). Each sequence
     * is paired with the motions it carries out by where its segments came from ({@code Source}).
     */
    public void block(CheckedBlock intended, List<Instruction> emitted) {
        block(intended, emitted, true);
    }

    /**
     * @param settled whether the DMC of every motion meant so far has been given (the planner holds
     *                none back): a motion still not carried out then never will be (E311)
     */
    public void block(CheckedBlock intended, List<Instruction> emitted, boolean settled) {
        if (expected == null) {
            expected = new ExpectedMotions(options.tolerance(), this::missed);
        }
        expected.add(intended);
        dmc.checkedByCaller(true);
        run(emitted);
        dmc.checkedByCaller(false);
        if (settled) {
            // (while the planner holds pieces, a sequence longer than its window may be open here: its
            // VE comes with a later block)
            closeSequences(at(intended));
        }
        if (settled) {
            expected.skipAll();
        }
    }

    /** The sequences the planner held back to the end of the program's blocks. */
    public void held(List<Instruction> lines) {
        dmc.checkedByCaller(true);
        run(lines);
        dmc.checkedByCaller(false);
        closeSequences(lastRun);
    }

    public void end(List<Instruction> footer) {
        run(footer);
        closeSequences(lastRun);
        if (expected != null) {
            expected.skipAll();
        }
    }

    /** Replays DMC with no G-code to compare against: a hand-edited file, or --trace. */
    public void replay(List<Instruction> lines) {
        checks.frame(null);
        run(lines);
    }

    /**
     * Puts the axes at machine counts {@code x}, {@code z} without a move: where a stopped run left them,
     * for a way back checked from there after a replay of the program up to the stop (gcnc.send.WayBackRun).
     */
    public void placeAxes(double x, double z) {
        dmc.moveTo(x, z);
    }

    public SimReport report() {
        java.util.Map<String, Integer> byReason = new java.util.LinkedHashMap<>();
        for (gcnc.plan.Stop why : gcnc.plan.Stop.values()) {
            if (stops[why.ordinal()] > 0) {
                byReason.put(why.key(), stops[why.ordinal()]);
            }
        }
        return checks.report(findings).withCorners(corners.slowest.slowest(), SlowestCorners.KEPT).withStops(byReason);
    }

    /** How many sequences ended for each reason (the planner's, carried by AMS), in the reasons' order. */
    private final int[] stops = new int[gcnc.plan.Stop.values().length];

    private void run(List<Instruction> lines) {
        for (Instruction i : lines) {
            // every line of the DMC passes here in order: the count is the line's number in the file
            checks.dmcLine(++dmcLines);
            if (i.source().line() > 0) {
                lastLocated = i.source();
            }
            double before = replayed == null ? 0 : checks.seconds();
            if (replayed != null) {
                sequences.running(before);
            }
            dmc.run(i);
            if (replayed != null) {
                double after = checks.seconds();
                replayed.line(i, before, after);
                sequences.ran(after);
            }
            lastRun = i.source();
            if (trace != null) {
                trace.line(i, dmc.x(), dmc.z(), checks.tool(), outputs.describe());
            }
        }
    }

    private void closeSequences(Source at) {
        dmc.startBegun(); // a BGS whose VE never came (a hand-written program): it runs as it stands
        if (dmc.hasPending()) {
            report(Code.E314_SIM_SEQUENCE_NOT_STARTED, at);
            dmc.dropPending();
        }
    }

    /** A motion meant that moves and was not carried out: E311 at its block. */
    private void missed(CheckedBlock block, int count, int done) {
        report(Code.E311_SIM_SEQUENCE_COUNT, at(block), count, done);
    }

    /** A block's place: its file and calls, and its line (the findings about its motions as a whole). */
    private static Source at(CheckedBlock block) {
        return new Source(block.origin(), block.line(), -1);
    }

    /** A DMC line that could not be read (a replay of a file by itself), reported where it came from. */
    void fault(Source at, Code code, Object... args) {
        report(code, at, args);
    }

    private void report(Code code, Source at, Object... args) {
        findings++;
        diagnostics.report(Diagnostic.error(code, span(at), args).in(origin(at)));
    }

    /** The line a finding at {@code at} is reported at: its own, or the first for a line from no block. */
    private static Span span(Source at) {
        return Span.of(Math.max(1, at.line()), 1);
    }

    /** The file and calls a finding at {@code at} goes to: its own, or for a line from no block the last located's. */
    private gcnc.diag.Origin origin(Source at) {
        return at.line() > 0 ? at.origin() : lastLocated.origin();
    }

    /** The interpreter's events, turned into machine state and checks. */
    private final class Events implements ReplayListener {
        @Override
        public void sequence(List<Segment> segments, double speed, Source at) {
            // the runs of segments from one motion each, and the motions they carry out
            for (int n = meant.match(segments, expected); n > 0; n--) {
                report(Code.E311_SIM_SEQUENCE_COUNT, at, 0, 1); // a sequence no motion of the program asked for
            }
            Motion m = meant.isEmpty() ? null : meant.get(0).motion();
            if (m != null) {
                checks.frame(meant.get(0).block().frame());
                if (meant.size() > 1) {
                    // a sequence of several blocks: each segment's findings in its own block's coordinates
                    checks.frames(meant.frames());
                }
            }
            boolean rapid = expected == null ? speed == profile.rapidSpeed() && !dmc.feedMarked()
                    : m instanceof Motion.Linear && ((Motion.Linear) m).rapid();
            boolean stopped = !rapid && outputs.spindleKnown && !outputs.running;
            boolean open = !rapid && outputs.chuckKnown && !outputs.closed;
            boolean removed = checks.sequence(segments, speed, rapid, at, dmc.acceleration(), dmc.deceleration(),
                    stopped || open);
            corners.check(segments, speed, at, meant.isEmpty() ? null : meant.numbers);
            // A feed that takes no material (a bar puller's pull, a move in the air) is not a cut. With
            // no blank that cannot be told: a bare replay judges every feed a cut, as nothing else judges
            // it; a compile leaves it to the checker's warning (E660/E661), errors (E037/E038) elsewhere.
            boolean cut = checks.hasStock() ? removed : expected == null;
            if (stopped && cut) {
                report(Code.E306_SIM_FEED_SPINDLE_STOPPED, at, outputs.describe());
            }
            if (open && cut) {
                report(Code.E307_SIM_FEED_CHUCK_OPEN, at, outputs.describe());
            }
            for (int k = 0; k < meant.size(); k++) {
                ExpectedMotions.Expected e = meant.get(k);
                checks.frame(e.block().frame());
                double[] resync = checks.conformance(e.motion(), meant.run(k, segments), at(e.block()));
                if (resync != null && k == meant.size() - 1) {
                    dmc.moveTo(resync[0], resync[1]);
                }
            }
        }

        /** The motions of the program the last sequence carried out (reused from one to the next). */
        private final MeantMotions meant = new MeantMotions();

        @Override
        public void dwell(double seconds, int line) {
            checks.dwell(seconds);
        }

        @Override
        public void programStop(int line) {
            checks.programStop();
        }

        @Override
        public void tool(int n, Source at) {
            checks.selectTool(n);
            if (n != 0 && !machine.described(n) && undescribed.add(n)) {
                // never silently the default outline: say which station, and what its checks rest on
                boolean tipOnly = machine.defaultTool().kind() == gcnc.machine.MachineModel.ToolKind.TIP;
                diagnostics.report(Diagnostic.warning(tipOnly ? Code.E322_SIM_STATION_TIP_ONLY
                        : Code.E321_SIM_STATION_ASSUMED, span(at), n, profile.name(),
                        machine.defaultTool().name()).in(origin(at)));
            }
        }

        @Override
        public void output(int bit, boolean on, int line) {
            outputs.set(bit, on);
        }

        @Override
        public void spindleVolts(double volts, int line) {
            // The run/stop state comes from the outputs; the speed affects no check, only the setup
            // sheet's highest speed (it was never passed on before: "not known" beside a G50 S2500)
            checks.spindle(volts * profile.rpmPerVolt());
        }

        @Override
        public void report(Code code, Source at, Object... args) {
            Simulator.this.report(code, at, args);
        }

        @Override
        public void stopped(gcnc.plan.Stop why, int line) {
            corners.stopped(why);
            stops[why.ordinal()]++;
        }

        /**
         * An output or speed set on the way must be where its block stands in the program: between
         * the lines of the segments the path is on at its trip point (the motion before it and the one
         * after, in the same file). Judged where the sources are a compile's (counted blocks: a DMC
         * file read back may number its own lines); a path that runs lines backwards there (a loop) is not.
         */
        @Override
        public void onTheWay(Source what, List<Source> around, long trip, String text) {
            if (around.isEmpty() || what.line() <= 0 || what.block() < 0) {
                return;
            }
            int lo = Integer.MAX_VALUE;
            int hi = Integer.MIN_VALUE;
            for (Source s : around) {
                if (!java.util.Objects.equals(s.origin(), what.origin())) {
                    return;
                }
                lo = Math.min(lo, s.line());
                hi = Math.max(hi, s.line());
            }
            if (around.get(0).line() > around.get(around.size() - 1).line()) {
                return;
            }
            if (what.line() < lo || what.line() > hi) {
                report(Code.E335_SIM_SWITCHED_ELSEWHERE, what, text, trip, lo == hi ? String.valueOf(lo) : lo + "-" + hi);
            }
        }
    }
}
