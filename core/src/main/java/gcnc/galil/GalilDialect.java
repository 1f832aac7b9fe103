package gcnc.galil;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Command;
import gcnc.dmc.DmcReader;
import gcnc.dmc.Fixed;
import gcnc.dmc.Instruction;
import gcnc.dmc.Source;
import gcnc.ir.ArcGeometry;
import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import gcnc.plan.Step;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;

/**
 * The default dialect: a standalone DMC program (docs/dmc-format.md, docs/galil.md). Each motion is
 * its own vector sequence ending in {@code VE / BGS / AMS}, so VP is simply the displacement from
 * where the controller stands, and outputs never switch while the axes move. The controller's
 * position is tracked in whole counts so rounding never accumulates. The machine around the
 * motion (spindle output and wait, turret, dwell, soft limits, homing check, error handlers) is
 * {@link MachineCode}'s.
 */
final class GalilDialect implements Dialect {
    private final MachineProfile profile;
    private final Diagnostics diagnostics;
    private final boolean inlineSourceMap;
    private final GalilFrame frame;
    private final gcnc.machine.ControllerLimits limits;
    long posU;
    long posV;
    /** The profile's output directives of each M code, read once. */
    private final Map<Integer, List<Command>> outputs = new java.util.HashMap<>();
    /** The spindle, the turret, the dwell, the soft limits, the homing check and the handlers. */
    private final MachineCode machine;

    GalilDialect(MachineProfile profile, Diagnostics diagnostics, boolean inlineSourceMap) {
        this.profile = profile;
        this.diagnostics = diagnostics;
        this.inlineSourceMap = inlineSourceMap;
        this.frame = new GalilFrame(profile);
        this.limits = profile.controllerLimits();
        this.machine = new MachineCode(profile, frame, diagnostics);
        this.posU = GalilNumbers.round(frame.u(profile.home()));
        this.posV = GalilNumbers.round(frame.v(profile.home()));
    }

    @Override
    public void begin(Consumer<Instruction> out) {
        String plane = frame.plane();
        out.accept(new Instruction(new Command.Label("GCNC"), Source.NONE));
        out.accept(new Instruction(new Command.ServoHere(plane), Source.NONE));
        out.accept(new Instruction(new Command.VectorMode(plane), Source.NONE));
        // IT 1 on both plane axes: no smoothing. IT is burnable and "also filters the individual axes during
        // Vector Mode (VM)", which "results in longer motion time" (command reference IT): a unit with a
        // smaller value burned in would round the corners and stretch the times the simulator verified
        for (int i = 0; i < 2; i++) {
            out.accept(new Instruction(new Command.AxisSetting(Command.Setting.IT,
                    gcnc.dmc.Channels.index(plane.charAt(i)), Fixed.of(1)), Source.NONE));
        }
        out.accept(new Instruction(new Command.VectorAcceleration(Fixed.of(acceleration(profile.acceleration()))),
                Source.NONE));
        out.accept(new Instruction(new Command.VectorDeceleration(Fixed.of(acceleration(profile.deceleration()))),
                Source.NONE));
        machine.setup(out);
    }

    /** VA or VD as the controller takes it (a multiple of 1,024, rounded down), warned of at line 1 when that changes it. */
    private long acceleration(double countsPerSecond2) {
        gcnc.machine.ControllerLimits.Rounded r = limits.roundAcceleration(GalilNumbers.round(countsPerSecond2));
        gcnc.machine.ControllerLimits.report(r, Span.of(1, 1), diagnostics);
        return r.taken();
    }

    /** {@code NO STOCK D<diameter> L<length> S<stickout>}, mm, or {@code NO STOCK NONE} (docs/dmc-format.md). */
    @Override
    public void blank(java.util.Optional<gcnc.machine.MachineModel.Blank> blank, Consumer<Instruction> out) {
        out.accept(new Instruction(new Command.Stock(blank), Source.NONE));
    }

    @Override
    public void end(Consumer<Instruction> out) {
        machine.finish(out);
    }

    @Override
    public void lower(Step step, Consumer<Instruction> sink) {
        if (step instanceof Step.Before s) {
            CheckedBlock b = s.block();
            BlockWriter out = writer(b, sink);
            if (b.spindleRpm().isPresent()) {
                spindle(b, b.spindleRpm().getAsDouble(), out);
            }
            if (b.tool().isPresent()) {
                machine.toolChange(b, b.tool().getAsInt(), out);
            }
            outputs(b, b.before(), out);
        } else if (step instanceof Step.Alone s) {
            BlockWriter out = writer(s.block(), sink);
            out.motion(s.motion());
            machine.beforeMotion(s.block().motions().get(s.motion()), out); // the wait for spindle speed
            motion(s.block(), s.block().motions().get(s.motion()), out);
            out.motion(-1);
        } else if (step instanceof Step.Group g) {
            if (g.continues()) {
                grouping = true; // the next window of the sequence being written (Contouring#WINDOW)
                try {
                    sequence.write(g);
                } finally {
                    grouping = false;
                }
            } else if (g.pieces().size() == 1 && !g.goesOn()) {
                // one motion: what the exact-stop planner writes, no segment speeds
                gcnc.plan.Piece p = g.pieces().get(0);
                stop = g.stop();
                lower(new Step.Alone(p.block(), p.motion()), sink);
                stop = null;
            } else {
                gcnc.plan.Piece first = g.pieces().get(0);
                machine.beforeMotion(first.block().motions().get(first.motion()), writer(first.block(), sink));
                // gline=<line> where the group starts only: an assignment between buffered segments
                // runs when it is read, not when the path gets there (docs/galil.md)
                grouping = true;
                try {
                    sequence = new GroupWriter(this, sink);
                    sequence.write(g);
                } finally {
                    grouping = false;
                }
            }
        } else if (step instanceof Step.After s) {
            BlockWriter out = writer(s.block(), sink);
            out.motion(-1);
            outputs(s.block(), s.block().after(), out);
        }
    }

    /** The writer of block {@code b}'s instructions: one per block, so that its inline map comment comes once. */
    BlockWriter writer(CheckedBlock b, Consumer<Instruction> sink) {
        if (writer == null || writer.block() != b) {
            writer = new BlockWriter(grouping ? sink : machine.marking(b, sink), b, inlineSourceMap, blocks++);
        }
        return writer;
    }

    private BlockWriter writer;

    /** Goes on writing with {@code w} (its block's writer), after trip points written for earlier blocks in between. */
    void resume(BlockWriter w) {
        writer = w;
    }

    /** The writer of the last sequence begun: a sequence that goes on is written on by it. */
    private GroupWriter sequence;
    /** A multi-motion group is being written: its blocks after the first get no gline=<line> (MachineCode). */
    private boolean grouping;
    /** The blocks written so far: each new one's number in the run (Source#block). */
    private long blocks;

    private void motion(CheckedBlock b, Motion m, BlockWriter out) {
        m.accept(new Motion.Visitor<Void>() {
            @Override
            public Void linear(Motion.Linear l) {
                GalilDialect.this.linear(b, l, out);
                return null;
            }

            @Override
            public Void arc(Motion.Arc a) {
                GalilDialect.this.arc(b, a, out);
                return null;
            }

            @Override
            public Void dwell(Motion.Dwell d) {
                GalilDialect.this.dwell(b, d, out);
                return null;
            }

            @Override
            public Void thread(Motion.Thread t) {
                GalilDialect.this.thread(b, t, out);
                return null;
            }
        });
    }

    /** The model's vector buffer, segments (tables/galil_models.csv {@code buffer_segments}). */
    int bufferSegments() {
        return (int) limits.model().range(gcnc.machine.GalilModel.Limit.BUFFER_SEGMENTS).max();
    }

    /** The wait for {@code slots} free slots of the vector buffer (MachineCode's {@code #LMWAIT}). */
    void awaitBuffer(int slots, BlockWriter out) {
        machine.awaitBuffer(slots, out);
    }

    /** The spindle's speed reference (also for G96 inside a group, GroupWriter): MachineCode's. */
    void spindle(CheckedBlock b, double rpm, BlockWriter out) {
        machine.spindleSpeed(b, rpm, out);
    }

    /**
     * The M functions' output directives and what they do to the spindle (also on the way,
     * GroupWriter); a program stop among them (M00, M01 with the switch on) comes after the others.
     */
    void outputs(CheckedBlock b, List<MCall> calls, BlockWriter out) {
        boolean stop = false;
        for (MCall m : calls) {
            if (profile.control().stopsProgram(m.code())) {
                stop = true;
            } else {
                apply(b, m.code(), out);
            }
        }
        if (stop) {
            programStop(b, out);
        }
    }

    /** The last M code applied in each of the control's M groups: what a program stop puts back. */
    private final Map<Integer, Integer> lastInGroup = new java.util.HashMap<>();

    /** One M code's output directives and what it does to the spindle. */
    private void apply(CheckedBlock b, int code, BlockWriter out) {
        for (Command directive : outputs.computeIfAbsent(code, this::directives)) {
            out.emit(directive);
        }
        machine.afterM(b, new MCall(code), out);
        gcnc.machine.MFunction f = profile.control().m().get(code);
        if (f != null && f.group() > 0) {
            lastInGroup.put(f.group(), code);
        }
    }

    /**
     * A program stop (docs/galil.md, "Program stops"), the axes at rest (the planner ended the
     * sequence): the control's {@code stop.off} codes that change something (Haas: M05 when the
     * spindle turns, M09 when the coolant is on), the wait for the operator ({@code gstop=1},
     * {@code JS #PSTOP}), then what they changed put back as the program had it (M03 with its
     * speed, and the wait for speed before the next feed, as after any M03; M08).
     */
    private void programStop(CheckedBlock b, BlockWriter out) {
        List<Integer> restore = new java.util.ArrayList<>();
        for (int off : profile.control().stop().off()) {
            gcnc.machine.MFunction f = profile.control().m().get(off);
            Integer last = f.group() > 0 ? lastInGroup.get(f.group()) : null;
            if (f.group() > 0 && (last == null || last == off || !restorable(last))) {
                continue; // nothing of that group is on: the stop changes nothing there
            }
            apply(b, off, out);
            if (last != null) {
                restore.add(last);
            }
        }
        machine.programStop(out);
        for (int code : restore) {
            apply(b, code, out);
        }
    }

    /** Whether M code {@code code} is a state a stop can put back: a spindle start or an output (not M19's orientation). */
    private boolean restorable(int code) {
        gcnc.machine.MFunction f = profile.control().m().get(code);
        gcnc.machine.MRole r = f == null ? null : f.role();
        return r == gcnc.machine.MRole.SPINDLE_CW || r == gcnc.machine.MRole.SPINDLE_CCW
                || r == gcnc.machine.MRole.OUTPUT;
    }

    /** The profile's output directives of M code {@code m} as commands (the loader has checked their form). */
    private List<Command> directives(int m) {
        return directives(profile, m);
    }

    static List<Command> directives(MachineProfile profile, int m) {
        List<Command> commands = new java.util.ArrayList<>();
        for (String d : profile.outputsFor(m)) {
            commands.add(java.util.Objects.requireNonNull(DmcReader.read(d, (code, args) -> {
                throw new IllegalStateException("profile output directive " + d + " is not SB/CB n");
            })));
        }
        return List.copyOf(commands);
    }

    private void linear(CheckedBlock b, Motion.Linear m, BlockWriter out) {
        straight(b, m.to(), m.rapid() ? null : m.feed(), out);
    }

    /** One VP sequence to {@code to} (feed null = rapid); nothing when it is the same count. */
    private void straight(CheckedBlock b, Point to, gcnc.ir.Feed feed, BlockWriter out) {
        long tu = GalilNumbers.round(frame.u(to));
        long tv = GalilNumbers.round(frame.v(to));
        long du = tu - posU;
        long dv = tv - posV;
        if (!inRange(b, "VP", tu) || !inRange(b, "VP", tv) || !inRange(b, "VP", du) || !inRange(b, "VP", dv)) {
            return;
        }
        long speed = speed(b, feed);
        if (speed < 0 || (du == 0 && dv == 0)) {
            return; // no move: an empty sequence would be TC 30 "segment too short"
        }
        speedLine(speed, feed != null, out);
        out.emit(new Command.VectorPosition(du, dv));
        finishSequence(out);
        posU = tu;
        posV = tv;
    }

    private void arc(CheckedBlock b, Motion.Arc m, BlockWriter out) {
        long tu = GalilNumbers.round(frame.u(m.to()));
        long tv = GalilNumbers.round(frame.v(m.to()));
        if (!inRange(b, "CR", tu) || !inRange(b, "CR", tv) || !inRange(b, "CR", GalilNumbers.round(m.radius()))) {
            return;
        }
        ArcPlanner.Written written = ArcPlanner.forMotion(frame, posU, posV, m);
        if (written == null) {
            straight(b, m.to(), m.feed(), out);
            return;
        }
        ArcPlanner.Cr cr = written.cr();
        if (cr == null) {
            diagnostics.error(Code.E202_ARC_NOT_REPRESENTABLE, at(b), GalilNumbers.round(m.radius()));
            return;
        }
        long speed = speed(b, m.feed());
        if (speed < 0) {
            return;
        }
        speedLine(speed, true, out);
        out.emit(new Command.CircularArc(Fixed.of(cr.radius()), Fixed.fourDecimals(cr.start()),
                Fixed.fourDecimals(cr.sweep())));
        if (cr.closing()) {
            out.emit(new Command.VectorPosition(tu - posU, tv - posV)); // VP is measured from the sequence start
        }
        finishSequence(out);
        posU = tu;
        posV = tv;
    }

    /** Galil's GR range: a gear ratio between -127 and 127 (COMALL GR). */
    static final double MAX_RATIO = gcnc.machine.SpindleEncoder.MAX_RATIO;
    /** The DMC variable that holds the spindle encoder count a thread pass starts at. */
    static final String SYNC_VARIABLE = "gsp";

    /**
     * One thread pass geared to the spindle encoder (docs/threading.md, docs/dmc-format.md):
     * {@code GA} makes the encoder's channel the master of both plane axes; the DMC waits with
     * {@code MF}/{@code MR} for the encoder to pass the next whole revolution (every pass starts at
     * the same spindle angle; a multi-start thread's pass its start angle further on, {@code +phase}
     * counts); {@code GR} engages both axes at the ratios that advance Z one lead
     * per revolution (X in proportion for a taper); {@code MF}/{@code MR} on Z waits for the end of
     * that segment. At each corner (a continuous G32 thread's joint, a chamfered pull-out's start
     * under Haas M23) the ratios change while geared ({@code GR} again, no new synchronisation) and
     * Z's wait moves on to the next segment's end.
     * {@code GR 0,0} disengages, and {@code PA}/{@code BG}/{@code AM} settle both axes on the exact
     * end counts (the few counts the disengagement and the 4-decimal ratios leave).
     */
    private void thread(CheckedBlock b, Motion.Thread t, BlockWriter out) {
        gcnc.machine.SpindleEncoder enc = profile.encoder().orElse(null);
        if (enc == null) {
            // the checker reports E190 first; a hand-built block without an encoder is the same fault here
            diagnostics.error(Code.E190_NO_SPINDLE_ENCODER, at(b), profile.name(), "a thread");
            return;
        }
        // the geared segments: from, each corner (a continuous thread's joints, a chamfer's start), to
        List<Point> points = new java.util.ArrayList<>(t.corners().size() + 2);
        points.add(t.from());
        points.addAll(t.corners());
        points.add(t.to());
        int n = points.size();
        long[] u = new long[n];
        long[] v = new long[n];
        u[0] = posU;
        v[0] = posV;
        for (int i = 1; i < n; i++) {
            u[i] = GalilNumbers.round(frame.u(points.get(i)));
            v[i] = GalilNumbers.round(frame.v(points.get(i)));
            String cmd = i == n - 1 ? "PA" : "MF";
            if (!inRange(b, cmd, u[i]) || !inRange(b, cmd, v[i])) {
                return;
            }
        }
        double[][] ratios = new double[n - 1][];
        double largest = 0;
        for (int i = 1; i < n; i++) {
            // from the geometry, not from each pass's rounded counts: every pass of a thread writes
            // the same ratio text, so the controller holds the same ratio on every pass
            ratios[i - 1] = ratios(enc, t, points.get(i - 1), points.get(i),
                    frame.u(points.get(i)) - frame.u(points.get(i - 1)), frame.v(points.get(i)) - frame.v(points.get(i - 1)));
            largest = Math.max(largest, Math.max(Math.abs(ratios[i - 1][0]), Math.abs(ratios[i - 1][1])));
        }
        if (largest > MAX_RATIO) {
            diagnostics.error(Code.E208_GEAR_RATIO_RANGE, at(b), ratio(largest));
            return;
        }
        char p1 = frame.plane().charAt(0);
        char p2 = frame.plane().charAt(1);
        char encoder = enc.channel();
        boolean zFirst = p1 == profile.z().galil();
        long[] z = zFirst ? u : v;
        out.emit(new Command.GearMaster(encoder, p1, p2));
        int cpr = enc.countsPerRev();
        // a multi-start thread's pass starts its start angle further on, in the spindle's direction
        long phase = Math.round(t.startAngle() / 360 * cpr) % cpr;
        out.emit(new Command.SyncPoint(SYNC_VARIABLE, encoder, cpr, t.reverse(), t.reverse() ? -phase : phase));
        out.emit(new Command.WaitPast(t.reverse(), encoder, new Command.Operand.Variable(SYNC_VARIABLE)));
        char zLetter = profile.z().galil();
        boolean zBack = z[n - 1] < z[0]; // a thread's Z goes one way through all its segments
        for (int i = 1; i < n; i++) {
            out.emit(new Command.GearRatio(p1, Fixed.of(ratio(ratios[i - 1][0])), p2, Fixed.of(ratio(ratios[i - 1][1]))));
            if (i == 1) {
                phaseCorrection(p1, p2, ratios[0], encoder, out);
            }
            // wait for Z to pass the segment's end: the next segment's ratios, or the pass's end
            out.emit(new Command.WaitPast(zBack, zLetter, new Command.Operand.Count(z[i])));
        }
        out.emit(new Command.GearRatio(p1, Fixed.of(0), p2, Fixed.of(0)));
        out.emit(new Command.PositionAbsolute(p1, u[n - 1], p2, v[n - 1]));
        out.emit(new Command.Begin(frame.plane()));
        out.emit(new Command.AfterMotion(frame.plane()));
        posU = u[n - 1];
        posV = v[n - 1];
    }

    /** The DMC variables of the slaves' phase errors (first and second plane axis). */
    static final String PHASE_FIRST = "gpu";
    static final String PHASE_SECOND = "gpv";

    /**
     * Right after the engagement, the phase correction (docs/threading.md, "One groove"): GR took
     * effect up to two samples after the spindle passed {@code gsp} (COMALL MF: "The accuracy of the
     * MF command is the number of counts that occur in 2*TM"), so each geared slave stands behind
     * the helix that starts at gsp by its ratio × the master's counts since gsp at engagement. Each
     * slave's lag is read in one expression (the master's counts past gsp × {@code _GR}, less its
     * commanded travel since it stood at its start, {@code _RP}) and added by {@code IP}, which on a
     * geared slave is a move "superimposed on top of the existing gearing motion" (COMALL IP). A
     * slave at ratio 0 (X of a straight thread) does not move and is not corrected.
     */
    private void phaseCorrection(char p1, char p2, double[] ratio, char encoder, BlockWriter out) {
        boolean first = !ratio(ratio[0]).equals(ratio(0));
        boolean second = !ratio(ratio[1]).equals(ratio(0));
        if (first) {
            out.emit(new Command.PhaseError(PHASE_FIRST, encoder, SYNC_VARIABLE, p1, posU));
        }
        if (second) {
            out.emit(new Command.PhaseError(PHASE_SECOND, encoder, SYNC_VARIABLE, p2, posV));
        }
        if (first && second) {
            out.emit(new Command.IncrementPosition(p1, PHASE_FIRST, p2, PHASE_SECOND));
        } else if (first || second) {
            out.emit(new Command.IncrementPosition(first ? p1 : p2, first ? PHASE_FIRST : PHASE_SECOND, (char) 0, ""));
        }
    }

    /**
     * The gear ratios of one geared segment of a pass from {@code a} to {@code b}: its displacement
     * in counts ({@code du}, {@code dv}, Galil's plane order, unrounded) over the encoder counts the
     * spindle turns while Z goes from a to b at the lead (negative under M04).
     */
    private static double[] ratios(gcnc.machine.SpindleEncoder enc, Motion.Thread t, Point a, Point b, double du,
                                   double dv) {
        double master = Math.abs(b.z() - a.z()) / t.lead() * enc.countsPerRev() * (t.reverse() ? -1 : 1);
        return new double[] {du / master, dv / master};
    }

    /** A gear ratio as GR takes it: four decimals (its resolution, DMC-40x0 command reference). */
    static String ratio(double r) {
        String s = String.format(java.util.Locale.ROOT, "%.4f", r);
        return s.equals("-0.0000") ? "0.0000" : s;
    }

    private void dwell(CheckedBlock b, Motion.Dwell m, BlockWriter out) {
        machine.dwell(b, m.seconds(), out);
    }

    private void finishSequence(BlockWriter out) {
        out.emit(new Command.VectorEnd());
        out.emit(new Command.BeginSequence());
        out.emit(new Command.AwaitSequence(stop));
    }

    /** Why the machine stops after the motion being written alone, when the planner said (a group of one). */
    private gcnc.plan.Stop stop;

    /**
     * The sequence's VS; a feed as fast as a rapid is marked with a {@code NO G01} comment first, so
     * that a replay of the DMC by itself knows it for a feed (docs/dmc-format.md).
     */
    void speedLine(long speed, boolean feed, BlockWriter out) {
        if (feed && speed == GalilNumbers.round(profile.rapidSpeed())) {
            out.emit(new Command.FeedMark());
        }
        out.emit(new Command.VectorSpeed(Fixed.of(speed)));
    }

    /**
     * The vector speed in counts/s at the controller's resolution (even: VS and the segment speeds
     * take multiples of 2, and gcnc rounds down so that no feed runs faster than programmed), or -1
     * (reported) when the controller cannot take it. The rounding is the controller's resolution, as
     * millimetres to counts is the encoder's: not warned of.
     */
    long speed(CheckedBlock b, gcnc.ir.Feed feed) {
        double cps = feed == null ? profile.rapidSpeed() : feed.countsPerSecond();
        long s = GalilNumbers.round(cps);
        if (s < 2) { // VS 2 is the slowest the controller takes
            diagnostics.error(Code.E207_FEED_TOO_SLOW, at(b), GalilNumbers.angle(cps));
            return -1;
        }
        if (!GalilNumbers.inRange(s)) {
            diagnostics.error(Code.E201_GALIL_RANGE, at(b), "VS", s);
            return -1;
        }
        gcnc.machine.ControllerLimits.Rounded even = limits.roundSpeed(s);
        return even.taken();
    }

    boolean inRange(CheckedBlock b, String command, long counts) {
        if (GalilNumbers.inRange(counts)) {
            return true;
        }
        diagnostics.error(Code.E201_GALIL_RANGE, at(b), command, counts);
        return false;
    }

    /** The lesser of the machine's acceleration and deceleration, counts/s² (what a stop within a move is held to). */
    double stopping() {
        return Math.min(profile.acceleration(), profile.deceleration());
    }

    GalilFrame frame() {
        return frame;
    }

    void error(Code code, CheckedBlock b, Object... args) {
        diagnostics.error(code, at(b), args);
    }

    private static Span at(CheckedBlock b) {
        return Span.of(b.line(), 1);
    }
}
