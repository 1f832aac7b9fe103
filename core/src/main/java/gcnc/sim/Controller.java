package gcnc.sim;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import java.util.ArrayList;
import java.util.List;

/**
 * The controller: what a Galil does with the commands gcnc emits (docs/dmc-format.md, both
 * dialects), one {@link Command} at a time, handed on to a {@link Listener} as what the machine
 * does: vector sequences when BGS starts them, dwells, tool changes, output changes. It holds the
 * controller's state (position in whole counts, the sequence being buffered, speed, acceleration,
 * the gearing of a thread pass) and no checks of the machine around it: those are the
 * {@link Simulator}'s. A command that makes no sense where it stands (another plane, a gear ratio
 * with no master, anything after EN) is reported, never skipped silently. Positions are Galil
 * coordinates in the vector plane; {@link Plane} turns them into machine counts.
 */
final class Controller {
    /** What the replayed program makes the machine do. */
    interface Listener {
        void sequence(List<Segment> segments, double speed, int line);

        void dwell(double seconds, int line);

        void tool(int n, int line);

        void output(int bit, boolean on, int line);

        void spindleVolts(double volts, int line);

        void report(Code code, int line, Object... args);

        /**
         * A command set on the way: after {@code AV trip}, while the last sequence runs. {@code around}:
         * the sources of the segments the path is on at that point (one, or two where it is at their
         * joint), for the check that it is where the program has it (docs/galil.md).
         */
        default void onTheWay(gcnc.dmc.Source what, List<gcnc.dmc.Source> around, long trip, String text, int line) {
        }

        /**
         * A program stop ({@code JS #PSTOP}: M00, M01 with the switch on): the machine waits for the
         * operator, at rest; the cycle time counts none of it.
         */
        default void programStop(int line) {
        }

        /** The sequence that ran ends here (AMS), for the reason the planner recorded (the corner report). */
        default void stopped(gcnc.plan.Stop why, int line) {
        }
    }

    private static final double INT32 = 2147483647;

    private final Plane plane;
    private final Listener out;
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
    private double speed;
    double acceleration;
    double deceleration;
    private boolean ended;
    /** When a G-code block is there to compare with, conformance reports zero sweeps instead. */
    boolean checkedByCaller;
    private final int spindleChannel;

    /**
     * The spindle encoder threads are geared to (channel, counts per revolution; -1 when the
     * machine has none), the drive's r/min per volt (for a thread pass's speed) and how far, in
     * counts, a geared pass may end from its settling move before it is E317.
     */
    int encoderChannel = -1;
    int encoderCounts;
    double rpmPerVolt;
    double threadTolerance = 2;
    private double volts;
    /** The gearing of a thread pass as the DMC sets it up (docs/dmc-format.md, "Thread passes"). */
    private boolean gearMaster;
    private String syncVariable;
    private boolean synchronised;
    private boolean engaged;
    private double ratio1;
    private double ratio2;
    private double engaged1;
    private double engaged2;
    /** The plane index (0, 1) whose trip point ends the pass, and that point; -1 when none yet. */
    private int tripAxis = -1;
    private double trip;
    /** Where the disengaged pass left the axes, and the PA target; NaN when none. */
    private double geared1 = Double.NaN;
    private double geared2 = Double.NaN;
    private double target1 = Double.NaN;
    private double target2 = Double.NaN;
    private Instruction gearLine;
    /**
     * The geared segments of the pass before the current ratios: one per change of the ratios
     * while geared (a chamfered pull-out's corner, docs/threading.md); empty for a straight pass.
     */
    private final List<Segment> geared = new ArrayList<>(1);
    /** The encoder counts the master turned over those segments (for the pass's speed). */
    private double masterTurned;
    /**
     * How far, in counts, each plane axis of the pass being geared may stand off the helix that
     * starts at the sync point: at engagement its ratio × the master's counts in 2 servo samples
     * (COMALL MF: "The accuracy of the MF command is the number of counts that occur in 2*TM"),
     * half a count once its measured phase error was added by IP (IP's resolution is 1 count).
     */
    private final double[] phaseLag = {-1, -1};
    /** The variables a {@code gpu=(_TPC-gsp)*_GRX-(_RPX-..)} line measured each axis's phase error into. */
    private final String[] phaseVariable = new String[2];
    /** The largest such offset of any pass per thread line (docs/threading.md, "One groove"). */
    private final java.util.Map<Integer, Double> phaseSpread = new java.util.TreeMap<>();
    /** The threads already warned of (E340), by line. */
    private final java.util.Set<Integer> phaseReported = new java.util.HashSet<>();
    /** How far apart, in counts, the passes of one thread may start before it is E340 (issue 30: 2 counts). */
    static final double PHASE_TOLERANCE = 2;
    /** The servo sample (COMALL TM default 1000 µs; gcnc never sets TM), seconds. */
    static final double SAMPLE = 0.001;

    Controller(Plane plane, double x, double z, double acc, double dec, double speed, char spindleAxis,
                   Listener out) {
        this.plane = plane;
        this.out = out;
        this.acceleration = acc;
        this.deceleration = dec;
        this.speed = speed;
        this.spindleChannel = Plane.channel(spindleAxis);
        moveTo(x, z);
    }

    /** Puts the machine at a position (machine counts): the start, or a resync after a mismatch. */
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

    boolean hasPending() {
        return !pending.isEmpty();
    }

    /**
     * Replays a sequence started by BGS whose VE has not come, as it stands: where the program
     * gives no more (a hand-written BGS without VE; gcnc writes VE with a fed sequence's last segment).
     */
    void startBegun() {
        if (begun) {
            startSequence();
            runDeferred();
        }
    }

    void dropPending() {
        pending.clear();
    }

    /**
     * A {@code NO G01} comment came before this sequence: gcnc marks a feed whose speed equals the
     * rapid speed so that a bare replay does not take it for a rapid (docs/dmc-format.md).
     */
    private boolean feedMarked;

    boolean feedMarked() {
        return feedMarked;
    }

    /**
     * Runs one instruction. Comments, labels and the marks gcnc writes are
     * taken anywhere; any other command after {@code EN} is E312.
     */
    void run(Instruction i) {
        this.instruction = i;
        this.line = i.source().line();
        Command cmd = i.command();
        boolean wait = cmd instanceof Command.Call c && c.label().equals(gcnc.dmc.StreamSplit.BUFFER_WAIT);
        if (begun && (cmd instanceof Command.AfterVector || deferring && !wait && !joinsRunning(cmd))) {
            // a trip point of the sequence running and what it sets (GroupWriter writes them while it is
            // fed): run after the sequence, which the replay runs whole at its VE
            deferred.add(i);
            deferring = true;
            return;
        }
        deferring = false;
        if (begun && !fed && !wait) {
            handWrittenBegin(); // any command but the wait for room after a BGS before VE: it started there
        }
        cmd.accept(step);
    }

    /** A command that goes on with the sequence begun: a segment, its VE, the end of the wait. */
    private static boolean joinsRunning(Command c) {
        return c instanceof Command.VectorPosition || c instanceof Command.CircularArc || c instanceof Command.VectorEnd
                || c instanceof Command.AwaitSequence;
    }

    /**
     * The trip points (AV) given while a sequence begun before its VE is fed, with the commands after
     * each (the outputs it switches): run once the sequence is replayed, in order, as those after VE.
     */
    private final List<Instruction> deferred = new ArrayList<>();
    private boolean deferring;

    /** Runs the trip points deferred while the sequence was fed, after the replay of the sequence. */
    private void runDeferred() {
        if (deferred.isEmpty()) {
            return;
        }
        List<Instruction> now = new ArrayList<>(deferred);
        deferred.clear();
        Instruction was = instruction;
        for (Instruction d : now) {
            this.instruction = d;
            this.line = d.source().line();
            d.command().accept(step);
        }
        this.instruction = was;
        this.line = was.source().line();
    }

    /** The instruction being run and its G-code line, for the findings about it. */
    private Instruction instruction;
    private int line;

    private String text() {
        return instruction.text();
    }

    /**
     * Whether the program has ended: E312 for the command, which then does nothing. A label after
     * {@code EN} starts a routine the main program reaches only by a jump or a fault (the homing
     * refusal, the waits, the error handlers: docs/galil.md): its commands are not run by the replay.
     */
    private boolean afterEnd() {
        if (ended && !routine) {
            out.report(Code.E312_SIM_AFTER_END, line, text());
        }
        return ended;
    }

    /** A label after EN has been met: what follows is a routine, not run in the replay. */
    private boolean routine;

    /**
     * The analog output that drives the spindle ({@code spindle.output = AO n}), or -1 when the
     * spindle is the OF of its channel; set by the simulator from the profile.
     */
    int spindleAnalog = -1;

    private final Command.Visitor<Void> step = new Command.Visitor<>() {
        public Void label(Command.Label c) {
            routine |= ended;
            return null;
        }

        public Void stock(Command.Stock c) {
            return null;
        }

        public Void feedMark(Command.FeedMark c) {
            feedMarked = true;
            return null;
        }

        public Void sourceMark(Command.SourceMark c) {
            return null;
        }

        public Void remark(Command.Remark c) {
            return null;
        }

        public Void servoHere(Command.ServoHere c) {
            boolean spindle = c.axes().length() == 1 && Plane.channel(c.axes().charAt(0)) == spindleChannel;
            if (!afterEnd() && !spindle && !plane.sameChannels(c.axes())) {
                out.report(Code.E313_SIM_VECTOR_PLANE, line, "SH", c.axes(), plane.letters);
            }
            return null;
        }

        public Void vectorMode(Command.VectorMode c) {
            if (!afterEnd() && !plane.sameChannels(c.axes())) {
                out.report(Code.E313_SIM_VECTOR_PLANE, line, "VM", c.axes(), plane.letters);
            }
            return null;
        }

        public Void vectorAcceleration(Command.VectorAcceleration c) {
            if (!afterEnd()) {
                acceleration = c.countsPerSecond2().value();
            }
            return null;
        }

        public Void vectorDeceleration(Command.VectorDeceleration c) {
            if (!afterEnd()) {
                deceleration = c.countsPerSecond2().value();
            }
            return null;
        }

        public Void vectorSpeed(Command.VectorSpeed c) {
            if (!afterEnd()) {
                speed = c.countsPerSecond().value();
            }
            return null;
        }

        public Void vectorPosition(Command.VectorPosition c) {
            if (!afterEnd()) {
                Controller.this.vp(c.first(), c.second(), c.speeds());
            }
            return null;
        }

        public Void circularArc(Command.CircularArc c) {
            if (!afterEnd()) {
                Controller.this.cr(c.radius().value(), c.start().value(), c.sweep().value(), c.speeds());
            }
            return null;
        }

        public Void vectorEnd(Command.VectorEnd c) {
            if (!afterEnd()) {
                if (begun) {
                    startSequence(); // a sequence fed while it ran: its last segment came before this VE
                    runDeferred();
                } else {
                    vectorEnded = true;
                }
            }
            return null;
        }

        public Void beginSequence(Command.BeginSequence c) {
            if (!afterEnd()) {
                if (vectorEnded || pending.isEmpty()) {
                    Controller.this.startSequence();
                } else {
                    // BGS after the first fill, VE after the last segment (a sequence longer than the
                    // buffer, fed while it runs: COMALL VM): replayed whole at its VE, once the wait for
                    // room that gcnc writes right after such a BGS (JS #LMWAIT) says it is one
                    begun = true;
                    fed = false;
                }
            }
            return null;
        }

        public Void awaitSequence(Command.AwaitSequence c) {
            if (begun) {
                startSequence(); // (a hand-written BGS without VE: replayed as it stands)
                runDeferred();
            }
            if (!afterEnd() && c.why() != null) {
                out.stopped(c.why(), line);
            }
            avTrip = -1; // what follows is at rest
            return null;
        }

        public Void afterVector(Command.AfterVector c) {
            // the sequence has been replayed whole at BGS: what follows acts on the state after it. AV is
            // relative (command reference AV: "from the start of a coordinated move sequence or from the
            // last AV command"), so its trip point is the last one's plus n; it must be on the path: what
            // the controller does at an AV it never reaches the reference does not say, so the safe
            // reading is that it waits there for ever (docs/simulator.md)
            if (!afterEnd()) {
                measure();
                double total = reachedCount == 0 ? 0 : reached[reachedCount - 1];
                long trip = Math.max(0, avTrip) + c.counts();
                if (trip > total + 1) {
                    out.report(Code.E334_SIM_TRIP_PAST_END, line, c.counts(), trip, Math.round(total));
                }
                avTrip = trip;
            }
            return null;
        }

        public Void offset(Command.Offset c) {
            if (!afterEnd() && c.channel() == spindleChannel && spindleAnalog < 0) {
                volts = c.volts().value();
                onTheWay();
                out.spindleVolts(volts, line);
            }
            return null;
        }

        public Void await(Command.Wait c) {
            if (!afterEnd()) {
                out.dwell(c.milliseconds() / 1000.0, line);
            }
            return null;
        }

        public Void toolNumber(Command.ToolNumber c) {
            if (!afterEnd()) {
                out.tool(c.station(), line);
            }
            return null;
        }

        public Void revolver(Command.Revolver c) {
            if (!afterEnd()) {
                out.tool(c.station(), line);
            }
            return null;
        }

        public Void passThroughM(Command.PassThroughM c) {
            afterEnd(); // the thesis's pass-through: no output, no effect
            return null;
        }

        public Void output(Command.Output c) {
            if (!afterEnd()) {
                onTheWay();
                out.output(c.bit(), c.on(), line);
            }
            return null;
        }

        public Void gearMaster(Command.GearMaster c) {
            if (!afterEnd()) {
                Controller.this.gearAxes(c);
            }
            return null;
        }

        public Void syncPoint(Command.SyncPoint c) {
            if (!afterEnd()) {
                Controller.this.assignment(c);
            }
            return null;
        }

        public Void waitPast(Command.WaitPast c) {
            if (!afterEnd()) {
                Controller.this.tripPoint(c);
            }
            return null;
        }

        public Void gearRatio(Command.GearRatio c) {
            if (!afterEnd()) {
                Controller.this.gearRatio(c);
            }
            return null;
        }

        public Void positionAbsolute(Command.PositionAbsolute c) {
            if (!afterEnd()) {
                Controller.this.settle(c);
            }
            return null;
        }

        public Void phaseError(Command.PhaseError c) {
            if (!afterEnd()) {
                Controller.this.phaseError(c);
            }
            return null;
        }

        public Void incrementPosition(Command.IncrementPosition c) {
            if (!afterEnd()) {
                Controller.this.phaseCorrection(c);
            }
            return null;
        }

        public Void definePosition(Command.DefinePosition c) {
            if (!afterEnd() && Plane.channel(c.axis()) != encoderChannel) {
                out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "DP", text()); // gcnc defines the spindle count only
            }
            return null;
        }

        public Void begin(Command.Begin c) {
            if (afterEnd()) {
                return null;
            }
            if (plane.sameChannels(c.axes()) && !Double.isNaN(target1)) {
                Controller.this.threadPass();
            } else {
                out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "BG", text());
            }
            return null;
        }

        public Void afterMotion(Command.AfterMotion c) {
            if (!afterEnd() && !plane.sameChannels(c.axes())) {
                out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "AM", text());
            }
            return null;
        }

        public Void end(Command.End c) {
            afterEnd();
            ended = true;
            return null;
        }

        public Void analogOut(Command.AnalogOut c) {
            if (!afterEnd() && c.output() == spindleAnalog) {
                volts = c.volts().value();
                onTheWay();
                out.spindleVolts(volts, line);
            }
            return null;
        }

        /**
         * Gains of zero on an axis that moves the tool would leave it uncontrolled: only the spindle's channel
         * takes them. IT 1 is no filtering, what the replay models; a smaller value (smoothing, which "also
         * filters the individual axes during Vector Mode" and "results in longer motion time", command
         * reference IT) is not simulated yet: E336.
         */
        public Void axisSetting(Command.AxisSetting c) {
            if (afterEnd()) {
                return null;
            }
            if (c.setting() == Command.Setting.IT) {
                if (c.value().value() != 1) {
                    out.report(Code.E336_SIM_SMOOTHING, line, text());
                }
                return null;
            }
            if (c.channel() != spindleChannel) {
                out.report(Code.E301_SIM_BAD_ARGUMENTS, line, c.setting().name(), text());
            }
            return null;
        }

        public Void softLimit(Command.SoftLimit c) {
            if (!afterEnd() && !plane.sameChannels("" + c.first() + c.second())) {
                out.report(Code.E313_SIM_VECTOR_PLANE, line, c.forward() ? "FL" : "BL", "" + c.first() + c.second(),
                        plane.letters);
            }
            return null;
        }

        /**
         * A conditional jump leaves for a routine when the machine is not ready (not at home, the
         * spindle not at speed, the turret not in position): the replay's machine is ready, so the
         * jump is not taken. An unconditional jump in the main program is not followed: E301.
         */
        public Void jump(Command.Jump c) {
            if (!afterEnd() && c.when().isEmpty()) {
                out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "JP", text());
            }
            return null;
        }

        /** A call of a wait routine (spindle at speed, turret in position): the replay's machine answers at once. */
        public Void call(Command.Call c) {
            if (begun && c.label().equals(gcnc.dmc.StreamSplit.BUFFER_WAIT)) {
                fed = true;
            }
            if (!afterEnd() && c.label().equals(gcnc.dmc.ProgramStop.LABEL)) {
                out.programStop(line);
            }
            return null;
        }

        public Void message(Command.Message c) {
            afterEnd();
            return null;
        }

        public Void stop(Command.Stop c) {
            afterEnd();
            return null;
        }

        public Void abort(Command.Abort c) {
            afterEnd();
            return null;
        }

        public Void clearStack(Command.ClearStack c) {
            afterEnd();
            return null;
        }

        public Void setVariable(Command.SetVariable c) {
            afterEnd();
            return null;
        }

        public Void setDeadline(Command.SetDeadline c) {
            afterEnd();
            return null;
        }
    };

    /** VP: a straight segment to (p, q) from the sequence's start. */
    private void vp(long p, long q, Command.Speeds speeds) {
        startIfNeeded();
        double e1 = seqStart1 + p;
        double e2 = seqStart2 + q;
        // made with its speeds (no copy: one per replayed segment)
        add(new Segment(plane.machineX(cursor1, cursor2), plane.machineZ(cursor1, cursor2),
                plane.machineX(e1, e2), plane.machineZ(e1, e2), false, 0, 0, 0, 0, 0, instruction,
                speeds.speed() == 0 ? Double.NaN : speeds.speed(), speeds.end() == 0 ? Double.NaN : speeds.end()),
                e1, e2, Command.Speeds.NONE);
    }

    /** CR: an arc of radius r from the start angle through the sweep, degrees. */
    private void cr(double r, double startDeg, double sweepDeg, Command.Speeds speeds) {
        if (sweepDeg == 0 && !checkedByCaller) {
            out.report(Code.E309_SIM_ZERO_SWEEP_ARC, line, text());
        }
        startIfNeeded();
        double[] end = new double[2];
        Segment arc = plane.cr(cursor1, cursor2, r, startDeg, sweepDeg, instruction, end);
        add(arc, end[0], end[1], speeds);
    }

    private void startIfNeeded() {
        if (pending.isEmpty()) {
            seqStart1 = g1;
            seqStart2 = g2;
            cursor1 = g1;
            cursor2 = g2;
        }
    }

    private void add(Segment s, double e1, double e2, Command.Speeds speeds) {
        if (speeds.any()) {
            s = s.withSpeeds(speeds.speed() == 0 ? Double.NaN : speeds.speed(), speeds.end() == 0 ? Double.NaN : speeds.end());
        }
        if (Math.abs(e1) > INT32 || Math.abs(e2) > INT32) {
            out.report(Code.E310_SIM_COUNT_RANGE, line, "the end point of '" + s.text() + "'");
        }
        pending.add(s);
        cursor1 = e1;
        cursor2 = e2;
    }

    /**
     * A BGS before VE that no wait for room followed (a hand-written program, the thesis's object
     * program: BGS after each segment and no VE) starts its sequence as it stood at the BGS, before
     * the next command runs, as the replay always ran it.
     */
    private void handWrittenBegin() {
        if (begun && !fed) {
            startSequence();
            runDeferred(); // (AV after a hand-written BGS measures the sequence as it stood)
        }
    }

    private void startSequence() {
        begun = false;
        vectorEnded = false;
        if (pending.isEmpty()) {
            return;
        }
        // The controller's position is whole counts: an arc that ends a fraction off its target
        // leaves the axes at the nearest count, and the next sequence starts from there.
        g1 = Math.rint(cursor1);
        g2 = Math.rint(cursor2);
        avTrip = -1;
        // The listener reads the segments during the call and keeps none of them.
        out.sequence(pending, speed, line);
        // kept for the trip points after it (the path lengths only when an AV asks: most sequences have none)
        List<Segment> free = last;
        last = pending;
        measured = false;
        pending = free;
        pending.clear();
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
     * The command being run comes after an AV trip point: the listener hears where on the path
     * (the segments within a count of the trip point: the one it falls in, and its neighbour when it
     * is at their joint).
     */
    private void onTheWay() {
        if (avTrip < 0) {
            return;
        }
        measure();
        if (reachedCount == 0) {
            return;
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
        out.onTheWay(instruction.source(), around, avTrip, text(), line);
    }

    /** The plane's two channels in plane order (0: the first of VP's arguments). */
    private int planeChannel(int i) {
        return Plane.channel(plane.letters.charAt(i));
    }

    /** {@code GA}: the spindle encoder's channel is the master of both plane axes, and of nothing else. */
    private void gearAxes(Command.GearMaster c) {
        if (encoderChannel < 0 || Plane.channel(c.master()) != encoderChannel
                || !plane.sameChannels("" + c.first() + c.second())) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "GA", text());
            return;
        }
        gearMaster = true;
    }

    /**
     * {@code gsp=(@INT[_TPC/4096]+1)*4096}: the encoder count of the next whole revolution, or
     * ({@code ...*4096+2048}) a start angle past it, less than one revolution (a multi-start thread).
     */
    private void assignment(Command.SyncPoint c) {
        if (encoderChannel < 0 || Plane.channel(c.encoder()) != encoderChannel || c.countsPerRev() != encoderCounts
                || Math.abs(c.phase()) >= encoderCounts) {
            out.report(Code.E300_SIM_UNKNOWN_INSTRUCTION, line, text());
            return;
        }
        syncVariable = c.variable();
        synchronised = false;
    }

    /**
     * {@code MF}/{@code MR}: on the encoder's channel with the sync variable, the wait for the whole
     * revolution (the pass will start at the same spindle angle as every other); on a plane axis
     * while geared, the point where the pass ends.
     */
    private void tripPoint(Command.WaitPast c) {
        String cmd = c.reverse() ? "MR" : "MF";
        int at = Plane.channel(c.axis());
        if (at == encoderChannel && c.at() instanceof Command.Operand.Variable v && v.name().equals(syncVariable)) {
            synchronised = true;
            return;
        }
        int axis = at == planeChannel(0) ? 0 : at == planeChannel(1) ? 1 : -1;
        if (axis < 0 || !(c.at() instanceof Command.Operand.Count n) || !engaged) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, cmd, text());
            return;
        }
        if (phaseLag[0] >= 0) {
            closePhase();
        }
        tripAxis = axis;
        trip = n.counts();
    }

    /**
     * {@code gpu=(_TPC-gsp)*_GRX-(_RPX-start)} right after the engagement: the phase error of a
     * geared plane axis measured against the helix from the sync variable, from where the axis
     * stood when GR engaged it; anything else is E301 (another start, variable or master).
     */
    private void phaseError(Command.PhaseError c) {
        int ch = Plane.channel(c.slave());
        int axis = ch == planeChannel(0) ? 0 : ch == planeChannel(1) ? 1 : -1;
        double start = axis == 0 ? engaged1 : engaged2;
        if (!engaged || axis < 0 || Plane.channel(c.encoder()) != encoderChannel || !c.sync().equals(syncVariable)
                || c.slaveStart() != Math.rint(start) || phaseLag[axis] < 0) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "phase error", text());
            return;
        }
        phaseVariable[axis] = c.variable();
    }

    /** {@code IP gpu,gpv}: the measured phase errors added while geared: each axis is then on the helix to half a count. */
    private void phaseCorrection(Command.IncrementPosition c) {
        char[] axes = c.second() == 0 ? new char[] {c.first()} : new char[] {c.first(), c.second()};
        String[] vars = {c.firstVariable(), c.secondVariable()};
        for (int i = 0; i < axes.length; i++) {
            int ch = Plane.channel(axes[i]);
            int axis = ch == planeChannel(0) ? 0 : ch == planeChannel(1) ? 1 : -1;
            if (!engaged || axis < 0 || !vars[i].equals(phaseVariable[axis])) {
                out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "IP", text());
                return;
            }
            phaseLag[axis] = 0.5;
            phaseVariable[axis] = null;
        }
    }

    /** The pass's first trip point: its phase offset is what it is now; the thread's spread keeps the largest. */
    private void closePhase() {
        double lag = Math.max(phaseLag[0], phaseLag[1]);
        Double before = phaseSpread.merge(line, lag, Math::max);
        if (lag > PHASE_TOLERANCE && (before == lag) && !phaseReported.contains(line)) {
            phaseReported.add(line);
            out.report(Code.E340_SIM_THREAD_PHASE, line, String.format(java.util.Locale.ROOT, "%.0f", lag));
        }
        phaseLag[0] = -1;
        phaseLag[1] = -1;
    }

    /**
     * The largest phase offset, in counts, any pass of each thread (by the line of its GA) may
     * start with against the helix from its whole revolution: two passes of one thread are at
     * most this far apart along the groove (docs/threading.md, "One groove").
     */
    java.util.Map<Integer, Double> phaseSpread() {
        return java.util.Collections.unmodifiableMap(phaseSpread);
    }

    /** {@code GR}: engages the plane axes at their ratios, or ({@code GR 0,0}) disengages them at the trip point. */
    private void gearRatio(Command.GearRatio c) {
        boolean firstIsFirst = Plane.channel(c.first()) == planeChannel(0);
        double r1 = (firstIsFirst ? c.firstRatio() : c.secondRatio()).value();
        double r2 = (firstIsFirst ? c.secondRatio() : c.firstRatio()).value();
        if (!plane.sameChannels("" + c.first() + c.second()) || Math.abs(r1) > gcnc.machine.SpindleEncoder.MAX_RATIO
                || Math.abs(r2) > gcnc.machine.SpindleEncoder.MAX_RATIO) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "GR", text());
            return;
        }
        if (r1 == 0 && r2 == 0) {
            if (engaged) {
                disengage();
            }
            return;
        }
        if (engaged) {
            change(r1, r2);
            return;
        }
        if (!gearMaster) {
            out.report(Code.E318_SIM_THREAD_NO_MASTER, line, text());
        } else if (!synchronised) {
            out.report(Code.E319_SIM_THREAD_UNSYNCHRONISED, line, text());
        }
        engaged = true;
        synchronised = false;
        ratio1 = r1;
        ratio2 = r2;
        engaged1 = g1;
        engaged2 = g2;
        double masterPerSample = Math.abs(volts * rpmPerVolt) / 60 * encoderCounts * SAMPLE;
        phaseLag[0] = Math.abs(r1) * 2 * masterPerSample;
        phaseLag[1] = Math.abs(r2) * 2 * masterPerSample;
        phaseVariable[0] = null;
        phaseVariable[1] = null;
        tripAxis = -1;
        gearLine = instruction;
        geared.clear();
        masterTurned = 0;
    }

    /**
     * {@code GR} with other ratios while geared: at the MF/MR point on a plane axis the ratios
     * change and the master goes on (a chamfered pull-out, docs/threading.md). The segment geared so
     * far is kept; the next starts where it ended.
     */
    private void change(double r1, double r2) {
        double[] at = tripped(" (no MF/MR point on a geared axis says where the ratios change)");
        if (at == null) {
            return;
        }
        geared.add(new Segment(plane.machineX(engaged1, engaged2), plane.machineZ(engaged1, engaged2),
                plane.machineX(at[0], at[1]), plane.machineZ(at[0], at[1]), false, 0, 0, 0, 0, 0, gearLine));
        engaged1 = at[0];
        engaged2 = at[1];
        ratio1 = r1;
        ratio2 = r2;
        tripAxis = -1;
        gearLine = instruction;
    }

    /** Where the geared axes stand when the trip axis reaches its point (the master turned the same counts for both). */
    private void disengage() {
        engaged = false;
        double[] at = tripped(" (no MF/MR point on a geared axis ends the pass)");
        if (at != null) {
            geared1 = at[0];
            geared2 = at[1];
        }
    }

    /**
     * {first plane axis, second, master counts turned} when the trip axis reaches its point from
     * where the current ratios began, the master's counts added to {@link #masterTurned}; null
     * after E301 when no MF/MR on a geared axis gave the point ({@code why}).
     */
    private double[] tripped(String why) {
        double r = tripAxis == 0 ? ratio1 : ratio2;
        if (tripAxis < 0 || r == 0) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "GR", text() + why);
            return null;
        }
        double master = (trip - (tripAxis == 0 ? engaged1 : engaged2)) / r;
        masterTurned += Math.abs(master);
        return new double[] {engaged1 + ratio1 * master, engaged2 + ratio2 * master, master};
    }

    /** {@code PA}: the settling move to the pass's exact end, started by {@code BG} on the plane. */
    private void settle(Command.PositionAbsolute c) {
        boolean firstIsFirst = Plane.channel(c.first()) == planeChannel(0);
        long p = firstIsFirst ? c.firstCount() : c.secondCount();
        long q = firstIsFirst ? c.secondCount() : c.firstCount();
        if (!plane.sameChannels("" + c.first() + c.second()) || Double.isNaN(geared1) || engaged) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "PA", text());
            return;
        }
        target1 = p;
        target2 = q;
    }

    /**
     * The geared pass and its settling move, replayed as one cutting sequence from where the gearing
     * began to the PA target at the speed the spindle gives it; E317 when the gearing ended further
     * than the tolerance from that target (the ratios make the wrong lead or taper).
     */
    private void threadPass() {
        double off = Math.hypot(geared1 - target1, geared2 - target2);
        if (off > threadTolerance) {
            double zOff = Math.abs(plane.machineZ(geared1, geared2) - plane.machineZ(target1, target2));
            out.report(Code.E317_SIM_THREAD_LEAD, line, String.format(java.util.Locale.ROOT, "%.1f", off),
                    zOff > threadTolerance ? "Z" : "X");
        }
        double rpm = volts * rpmPerVolt;
        Segment last = new Segment(plane.machineX(engaged1, engaged2), plane.machineZ(engaged1, engaged2),
                plane.machineX(target1, target2), plane.machineZ(target1, target2), false, 0, 0, 0, 0, 0, gearLine);
        List<Segment> one;
        double speed;
        if (geared.isEmpty()) {
            one = List.of(last);
            speed = Math.max(1, Math.abs(rpm) / 60 * encoderCounts * Math.hypot(ratio1, ratio2));
        } else {
            // a chamfered pull-out: the straight part, the chamfer; the spindle turns at one speed
            // over both, so the pass's mean speed is its length over the time the master takes
            one = new ArrayList<>(geared);
            one.add(last);
            double length = 0;
            for (Segment seg : one) {
                length += seg.length();
            }
            double seconds = masterTurned / (Math.abs(rpm) / 60 * encoderCounts);
            speed = seconds > 0 && length / seconds > 1 ? length / seconds : 1;
            geared.clear();
        }
        g1 = target1;
        g2 = target2;
        target1 = Double.NaN;
        target2 = Double.NaN;
        geared1 = Double.NaN;
        geared2 = Double.NaN;
        feedMarked = true; // a geared pass always cuts
        out.sequence(one, speed, line);
        feedMarked = false;
    }
}
