package gcnc.galil;

import gcnc.machine.Plane;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Command;
import gcnc.dmc.Fixed;
import gcnc.dmc.Instruction;
import gcnc.dmc.Source;
import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import gcnc.plan.Step;
import java.util.List;
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
    /** One writer a block, and the blocks of the run counted. */
    private final BlockWriters writers;
    private final Plane plane;
    private final gcnc.machine.ControllerLimits limits;
    long posU;
    long posV;
    /** The spindle, the turret, the dwell, the soft limits, the homing check and the handlers. */
    private final MachineCode machine;
    /** The M functions' output directives and program stops. */
    private final MFunctions mFunctions;
    /** The thread passes, geared to the spindle encoder. */
    private final ThreadPass threads;

    GalilDialect(MachineProfile profile, Diagnostics diagnostics, boolean inlineSourceMap) {
        this.profile = profile;
        this.diagnostics = diagnostics;
        this.writers = new BlockWriters(inlineSourceMap);
        this.plane = Plane.of(profile);
        this.limits = profile.controllerLimits();
        this.machine = new MachineCode(profile, plane, diagnostics);
        this.posU = GalilNumbers.round(plane.galil1(profile.home()));
        this.posV = GalilNumbers.round(plane.galil2(profile.home()));
        this.threads = new ThreadPass(this, profile);
        this.mFunctions = new MFunctions(profile, machine);
    }

    @Override
    public void begin(Consumer<Instruction> out) {
        String letters = plane.letters();
        out.accept(new Instruction(new Command.Label("GCNC"), Source.NONE));
        out.accept(new Instruction(new Command.ServoHere(letters), Source.NONE));
        out.accept(new Instruction(new Command.VectorMode(letters), Source.NONE));
        // IT 1 on both plane axes: no smoothing. IT is burnable and "also filters the individual axes during
        // Vector Mode (VM)", which "results in longer motion time" (command reference IT): a unit with a
        // smaller value burned in would round the corners and stretch the times the simulator verified
        for (int i = 0; i < 2; i++) {
            out.accept(new Instruction(new Command.AxisSetting(Command.Setting.IT,
                    i == 0 ? plane.first() : plane.second(), Fixed.of(1)), Source.NONE));
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
        step.accept(new Step.Visitor() {
            @Override
            public void before(Step.Before s) {
                CheckedBlock b = s.block();
                BlockWriter out = writer(b, sink);
                if (b.spindleRpm().isPresent()) {
                    spindle(b, b.spindleRpm().getAsDouble(), out);
                }
                if (b.tool().isPresent()) {
                    machine.toolChange(b, b.tool().getAsInt(), out);
                }
                outputs(b, b.before(), out);
            }

            @Override
            public void alone(Step.Alone s) {
                BlockWriter out = writer(s.block(), sink);
                out.motion(s.motion());
                machine.beforeMotion(s.block().motions().get(s.motion()), out); // the wait for spindle speed
                motion(s.block(), s.block().motions().get(s.motion()), out);
                out.motion(-1);
            }

            @Override
            public void group(Step.Group g) {
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
                        sequence = new GroupWriter(GalilDialect.this, sink);
                        sequence.write(g);
                    } finally {
                        grouping = false;
                    }
                }
            }

            @Override
            public void after(Step.After s) {
                BlockWriter out = writer(s.block(), sink);
                out.motion(-1);
                outputs(s.block(), s.block().after(), out);
            }
        });
    }

    /**
     * The writer of block {@code b}'s instructions ({@link BlockWriters}); a new block's, outside a
     * multi-motion group, sets gline=<line> before its first instruction ({@link MachineCode#marking}).
     */
    BlockWriter writer(CheckedBlock b, Consumer<Instruction> sink) {
        BlockWriter w = writers.current(b);
        return w != null ? w : writers.start(b, grouping ? sink : machine.marking(b, sink));
    }

    /** Goes on writing with {@code w} (its block's writer), after trip points written for earlier blocks in between. */
    void resume(BlockWriter w) {
        writers.resume(w);
    }

    /** The writer of the last sequence begun: a sequence that goes on is written on by it. */
    private GroupWriter sequence;
    /** A multi-motion group is being written: its blocks after the first get no gline=<line> (MachineCode). */
    private boolean grouping;

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
                threads.write(b, t, out);
                return null;
            }
        });
    }

    /**
     * The M functions' output directives and what they do to the spindle (also on the way,
     * GroupWriter); a program stop among them (M00, M01 with the switch on) comes after the others.
     */
    void outputs(CheckedBlock b, List<MCall> calls, BlockWriter out) {
        mFunctions.outputs(b, calls, out);
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

    private void linear(CheckedBlock b, Motion.Linear m, BlockWriter out) {
        straight(b, m.to(), m.rapid() ? null : m.feed(), out);
    }

    /** One VP sequence to {@code to} (feed null = rapid); nothing when it is the same count. */
    private void straight(CheckedBlock b, Point to, gcnc.ir.Feed feed, BlockWriter out) {
        long tu = GalilNumbers.round(plane.galil1(to));
        long tv = GalilNumbers.round(plane.galil2(to));
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
        long tu = GalilNumbers.round(plane.galil1(m.to()));
        long tv = GalilNumbers.round(plane.galil2(m.to()));
        if (!inRange(b, "CR", tu) || !inRange(b, "CR", tv) || !inRange(b, "CR", GalilNumbers.round(m.radius()))) {
            return;
        }
        ArcPlanner.Written written = ArcPlanner.forMotion(plane, posU, posV, m);
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

    Plane plane() {
        return plane;
    }

    void error(Code code, CheckedBlock b, Object... args) {
        diagnostics.error(code, at(b), args);
    }

    private static Span at(CheckedBlock b) {
        return Span.of(b.line(), 1);
    }
}
