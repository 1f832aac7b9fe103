package gcnc.sim;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Instruction;
import gcnc.ir.ArcGeometry;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
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
    private final Controller dmc;
    private final OutputState outputs;
    private final MotionChecks checks;
    private final SimMachine machine;
    /** The stations already warned of as not described (E321/E322): once per station, not per tool change. */
    private final java.util.Set<Integer> undescribed = new java.util.HashSet<>();
    private final Trace trace;
    private final List<Motion> motions = new ArrayList<>();
    private List<Motion> expected = List.of();
    private int nextMotion;
    private int findings;
    private int lastLine = 1;
    /** Where the block being replayed was run from (a called program's file and calls): its findings go there. */
    private gcnc.diag.Origin origin = gcnc.diag.Origin.PROGRAM;

    /** How far a geared thread pass may end from its exact end before it is E317, mm. */
    static final double THREAD_TOLERANCE_MM = 0.005;

    public Simulator(MachineProfile profile, SimOptions options, Diagnostics diagnostics) {
        this.profile = profile;
        this.options = options;
        this.diagnostics = diagnostics;
        this.plane = new Plane(profile);
        this.outputs = new OutputState(profile);
        this.machine = SimMachine.read(profile);
        this.checks = new MotionChecks(profile, machine, options, this::report);
        if (!checks.hasStock()) {
            // No stock, no stock check: never collisions with a guessed blank (chuck, tailstock and travel still run).
            diagnostics.report(new Diagnostic(Code.E316_SIM_NO_STOCK, gcnc.diag.Severity.NOTE, Span.of(1, 1), List.of()));
        }
        this.dmc = new Controller(plane, profile.home().x(), profile.home().z(), profile.acceleration(),
                profile.deceleration(), profile.rapidSpeed(), profile.spindleAxis(), new Events());
        profile.encoder().ifPresent(e -> {
            dmc.encoderChannel = Plane.channel(e.channel());
            dmc.encoderCounts = e.countsPerRev();
        });
        dmc.rpmPerVolt = profile.rpmPerVolt();
        dmc.threadTolerance = threadTolerance(profile, options);
        this.trace = options.trace() == null ? null : new Trace(options.trace(), profile);
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

    public void begin(List<Instruction> header) {
        run(header);
    }

    /** One G-code block: what the checker meant, and the DMC the backend wrote for it. */
    public void block(CheckedBlock intended, List<Instruction> emitted) {
        origin = intended.origin();
        checks.frame(intended.frame());
        expected = motions;
        motions.clear();
        for (Motion m : intended.motions()) {
            if (!(m instanceof Motion.Dwell)) {
                expected.add(m);
            }
        }
        nextMotion = 0;
        dmc.checkedByCaller = true;
        run(emitted);
        dmc.checkedByCaller = false;
        closeSequences(intended.line());
        skipStandingMotions(null);
        if (nextMotion != expected.size()) {
            report(Code.E311_SIM_SEQUENCE_COUNT, intended.line(), expected.size(), nextMotion);
        }
        expected = List.of();
    }

    public void end(List<Instruction> footer) {
        run(footer);
        closeSequences(lastLine);
    }

    /** Replays DMC with no G-code to compare against: a hand-edited file, or --trace. */
    public void replay(List<Instruction> lines) {
        expected = null;
        checks.frame(null);
        run(lines);
    }

    public SimReport report() {
        return checks.report(findings);
    }

    private void run(List<Instruction> lines) {
        for (Instruction i : lines) {
            // every line of the DMC passes here in order: the count is the line's number in the file
            checks.dmcLine(++dmcLines);
            int line = i.source().line();
            if (line > 0) {
                origin = i.source().origin(); // a called program's file: its findings go there
            }
            dmc.run(i.command(), line);
            lastLine = Math.max(1, line);
            if (trace != null) {
                trace.line(i, dmc.x(), dmc.z(), checks.tool(), outputs.describe());
            }
        }
    }

    /**
     * A motion that does not move (G28 U0 W0's intermediate point, an arc shorter than a count)
     * needs no sequence: the backend may leave it out. Skips such motions unless the sequence at
     * hand is that motion (the backend kept it: a move of a count or two after rounding).
     */
    private void skipStandingMotions(List<Segment> next) {
        while (nextMotion < expected.size() && standing(expected.get(nextMotion))
                && (next == null || !sameMove(expected.get(nextMotion), next))) {
            nextMotion++;
        }
    }

    /**
     * Ends within the tolerance; for an arc also no more than half a turn (so it bulges no more)
     * or a diameter within the tolerance (a circle that small).
     */
    private boolean standing(Motion m) {
        double tol = options.tolerance();
        return m.accept(new Motion.Visitor<Boolean>() {
            @Override
            public Boolean linear(Motion.Linear l) {
                return distance(l.from(), l.to()) <= tol;
            }

            @Override
            public Boolean thread(Motion.Thread t) {
                return distance(t.from(), t.to()) <= tol;
            }

            @Override
            public Boolean dwell(Motion.Dwell d) {
                return true;
            }

            @Override
            public Boolean arc(Motion.Arc a) {
                return distance(a.from(), a.to()) <= tol
                        && (Math.abs(ArcGeometry.sweepDegrees(a.from(), a.to(), a.centre(), a.clockwise())) <= 180
                                || Conformance.pointLike(a, tol));
            }
        });
    }

    /**
     * Is the sequence that motion: the same kind (an arc within the tolerance may be written as a
     * straight move), and its displacement within the tolerance?
     */
    private boolean sameMove(Motion m, List<Segment> segs) {
        Segment first = segs.get(0);
        Segment last = segs.get(segs.size() - 1);
        double dx = last.toX() - first.fromX();
        double dz = last.toZ() - first.fromZ();
        return m.accept(new Motion.Visitor<Boolean>() {
            @Override
            public Boolean linear(Motion.Linear l) {
                return segs.size() == 1 && !first.arc() && sameDisplacement(dx, dz, l.from(), l.to());
            }

            @Override
            public Boolean thread(Motion.Thread t) {
                return segs.size() == Conformance.geared(t) && !first.arc() && sameDisplacement(dx, dz, t.from(), t.to());
            }

            @Override
            public Boolean dwell(Motion.Dwell d) {
                return false;
            }

            @Override
            public Boolean arc(Motion.Arc a) {
                return (first.arc() || Conformance.pointLike(a, options.tolerance()))
                        && sameDisplacement(dx, dz, a.from(), a.to());
            }
        });
    }

    private boolean sameDisplacement(double dx, double dz, Point from, Point to) {
        return Geometry.length(dx - (to.x() - from.x()), dz - (to.z() - from.z())) <= options.tolerance();
    }

    private static double distance(Point a, Point b) {
        return Geometry.length(b.x() - a.x(), b.z() - a.z());
    }

    private void closeSequences(int line) {
        if (dmc.hasPending()) {
            report(Code.E314_SIM_SEQUENCE_NOT_STARTED, line);
            dmc.dropPending();
        }
    }

    /** A DMC line that could not be read (a replay of a file by itself), reported where it came from. */
    void fault(gcnc.dmc.Source at, Code code, Object... args) {
        origin = at.origin();
        report(code, at.line(), args);
    }

    private void report(Code code, int line, Object... args) {
        findings++;
        diagnostics.report(Diagnostic.error(code, Span.of(Math.max(1, line), 1), args).in(origin));
    }

    /** The interpreter's events, turned into machine state and checks. */
    private final class Events implements Controller.Listener {
        @Override
        public void sequence(List<Segment> segments, double speed, int line) {
            Motion m = null;
            if (expected != null) {
                skipStandingMotions(segments);
                m = nextMotion < expected.size() ? expected.get(nextMotion) : null;
                nextMotion++;
            }
            boolean rapid = m == null ? speed == profile.rapidSpeed() && !dmc.feedMarked()
                    : m instanceof Motion.Linear && ((Motion.Linear) m).rapid();
            boolean stopped = !rapid && outputs.spindleKnown && !outputs.running;
            boolean open = !rapid && outputs.chuckKnown && !outputs.closed;
            boolean removed = checks.sequence(segments, speed, rapid, line, dmc.acceleration, dmc.deceleration,
                    stopped || open);
            // A feed that takes no material (a bar puller's pull, a move in the air) is not a cut. With
            // no blank that cannot be told: a bare replay judges every feed a cut, as nothing else judges
            // it; a compile leaves it to the checker's warning (E660/E661), errors (E037/E038) elsewhere.
            boolean cut = checks.hasStock() ? removed : expected == null;
            if (stopped && cut) {
                report(Code.E306_SIM_FEED_SPINDLE_STOPPED, line, outputs.describe());
            }
            if (open && cut) {
                report(Code.E307_SIM_FEED_CHUCK_OPEN, line, outputs.describe());
            }
            if (m != null) {
                double[] resync = checks.conformance(m, segments, line);
                if (resync != null) {
                    dmc.moveTo(resync[0], resync[1]);
                }
            }
        }

        @Override
        public void dwell(double seconds, int line) {
            checks.dwell(seconds);
        }

        @Override
        public void tool(int n, int line) {
            checks.selectTool(n);
            if (n != 0 && !machine.described(n) && undescribed.add(n)) {
                // never silently the default outline: say which station, and what its checks rest on
                boolean tipOnly = machine.defaultTool().kind() == gcnc.machine.MachineModel.ToolKind.TIP;
                diagnostics.report(Diagnostic.warning(tipOnly ? Code.E322_SIM_STATION_TIP_ONLY
                        : Code.E321_SIM_STATION_ASSUMED, Span.of(Math.max(1, line), 1), n, profile.name(),
                        machine.defaultTool().name()).in(origin));
            }
        }

        @Override
        public void output(int bit, boolean on, int line) {
            outputs.set(bit, on);
        }

        @Override
        public void spindleVolts(double volts, int line) {
            // The run/stop state comes from the outputs; the speed does not affect any check.
        }

        @Override
        public void report(Code code, int line, Object... args) {
            Simulator.this.report(code, line, args);
        }
    }
}
