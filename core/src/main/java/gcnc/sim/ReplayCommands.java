package gcnc.sim;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.machine.Plane;

/**
 * What each DMC command does in the replay (docs/dmc-format.md, both dialects), one visit per
 * command: the vector motion it buffers or starts ({@link VectorBuffer}), the gearing of a thread
 * pass it sets up ({@link ThreadGearing}), the speeds and the program's end it keeps here, and
 * what the machine does, handed to the {@link ReplayListener}. A command that makes no sense where
 * it stands (another plane, anything after EN) is reported, never skipped silently. When a command
 * runs is the {@link ReplayController}'s: it defers the trip points of a sequence fed while it runs.
 */
final class ReplayCommands extends FlowCommands {
    private final Plane plane;
    private final VectorBuffer buffer;
    private final ThreadGearing gearing;
    /** Starts a sequence BGS began before its VE, and runs the trip points deferred while it was fed. */
    private final Runnable startBegun;
    private final int spindleChannel;
    /**
     * The analog output that drives the spindle ({@code spindle.output = AO n}), or -1 when the
     * spindle is the OF of its channel.
     */
    private final int spindleAnalog;
    private double speed;
    private double acceleration;
    private double deceleration;
    /** When a G-code block is there to compare with, conformance reports zero sweeps instead. */
    private boolean checkedByCaller;

    ReplayCommands(Plane plane, VectorBuffer buffer, ThreadGearing gearing, double acc, double dec, double speed,
                   char spindleAxis, int spindleAnalog, Runnable startBegun, ReplayListener out) {
        super(out);
        this.plane = plane;
        this.buffer = buffer;
        this.gearing = gearing;
        this.acceleration = acc;
        this.deceleration = dec;
        this.speed = speed;
        this.spindleChannel = Plane.channel(spindleAxis);
        this.spindleAnalog = spindleAnalog;
        this.startBegun = startBegun;
    }

    /** Starts the sequence buffered (if any) at the vector speed, located at the instruction being run. */
    void startSequence() {
        buffer.start(speed, source());
    }

    double acceleration() {
        return acceleration;
    }

    double deceleration() {
        return deceleration;
    }

    void checkedByCaller(boolean checked) {
        checkedByCaller = checked;
    }

    /**
     * The command being run comes after an AV trip point: the listener hears where on the path
     * (the segments within a count of the trip point: the one it falls in, and its neighbour when it
     * is at their joint).
     */
    private void onTheWay() {
        java.util.List<gcnc.dmc.Source> around = buffer.around();
        if (around != null) {
            out.onTheWay(source(), around, buffer.trip(), text());
        }
    }

    /** The spindle's volts (OF on its channel, or its AO): set on the way, heard by the gearing and the listener. */
    private void spindle(double volts) {
        gearing.spindle(volts);
        onTheWay();
        out.spindleVolts(volts, line());
    }

    public Void feedMark(Command.FeedMark c) {
        buffer.markFeed();
        return null;
    }

    public Void servoHere(Command.ServoHere c) {
        boolean spindle = c.axes().length() == 1 && Plane.channel(c.axes().charAt(0)) == spindleChannel;
        if (!spindle && !plane.sameChannels(c.axes())) {
            out.report(Code.E313_SIM_VECTOR_PLANE, source(), "SH", c.axes(), plane.letters());
        }
        return null;
    }

    public Void vectorMode(Command.VectorMode c) {
        if (!plane.sameChannels(c.axes())) {
            out.report(Code.E313_SIM_VECTOR_PLANE, source(), "VM", c.axes(), plane.letters());
        }
        return null;
    }

    public Void vectorAcceleration(Command.VectorAcceleration c) {
        acceleration = c.countsPerSecond2().value();
        return null;
    }

    public Void vectorDeceleration(Command.VectorDeceleration c) {
        deceleration = c.countsPerSecond2().value();
        return null;
    }

    public Void vectorSpeed(Command.VectorSpeed c) {
        speed = c.countsPerSecond().value();
        buffer.open();
        return null;
    }

    public Void vectorPosition(Command.VectorPosition c) {
        buffer.vp(c, instruction());
        return null;
    }

    public Void circularArc(Command.CircularArc c) {
        if (c.sweep().value() == 0 && !checkedByCaller) {
            out.report(Code.E309_SIM_ZERO_SWEEP_ARC, source(), text());
        }
        buffer.cr(c, instruction());
        return null;
    }

    public Void vectorEnd(Command.VectorEnd c) {
        if (buffer.begun()) {
            startBegun.run(); // a sequence fed while it ran: its last segment came before this VE
        } else {
            buffer.end();
        }
        return null;
    }

    public Void beginSequence(Command.BeginSequence c) {
        // BGS after the first fill, VE after the last segment (a sequence longer than the
        // buffer, fed while it runs: COMALL VM): replayed whole at its VE, once the wait for
        // room that gcnc writes right after such a BGS (JS #LMWAIT) says it is one
        if (buffer.begin()) {
            buffer.start(speed, source());
        }
        return null;
    }

    public Void awaitSequence(Command.AwaitSequence c) {
        startBegun.run(); // (a hand-written BGS without VE: replayed as it stands)
        if (c.why() != null) {
            out.stopped(c.why(), line());
        }
        buffer.atRest(); // what follows is at rest
        return null;
    }

    public Void afterVector(Command.AfterVector c) {
        // the sequence has been replayed whole at BGS: what follows acts on the state after it
        buffer.afterVector(c, source());
        return null;
    }

    public Void offset(Command.Offset c) {
        if (c.channel() == spindleChannel && spindleAnalog < 0) {
            spindle(c.volts().value());
        }
        return null;
    }

    public Void await(Command.Wait c) {
        out.dwell(c.milliseconds() / 1000.0, line());
        return null;
    }

    public Void toolNumber(Command.ToolNumber c) {
        out.tool(c.station(), source());
        return null;
    }

    public Void revolver(Command.Revolver c) {
        out.tool(c.station(), source());
        return null;
    }

    public Void output(Command.Output c) {
        onTheWay();
        out.output(c.bit(), c.on(), line());
        return null;
    }

    public Void gearMaster(Command.GearMaster c) {
        buffer.open();
        gearing.master(c, instruction());
        return null;
    }

    public Void syncPoint(Command.SyncPoint c) {
        gearing.syncPoint(c, instruction());
        return null;
    }

    public Void waitPast(Command.WaitPast c) {
        gearing.waitPast(c, instruction());
        return null;
    }

    public Void gearRatio(Command.GearRatio c) {
        gearing.ratio(c, instruction(), buffer.galil1(), buffer.galil2());
        return null;
    }

    public Void positionAbsolute(Command.PositionAbsolute c) {
        gearing.settle(c, instruction());
        return null;
    }

    public Void phaseError(Command.PhaseError c) {
        gearing.phaseError(c, instruction());
        return null;
    }

    public Void incrementPosition(Command.IncrementPosition c) {
        gearing.phaseCorrection(c, instruction());
        return null;
    }

    public Void definePosition(Command.DefinePosition c) {
        gearing.definePosition(c, instruction());
        return null;
    }

    public Void begin(Command.Begin c) {
        if (plane.sameChannels(c.axes()) && gearing.settling()) {
            ThreadGearing.GearedPass pass = gearing.pass(source());
            buffer.run(pass.segments(), pass.speed(), pass.end1(), pass.end2(), source());
        } else {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, source(), "BG", text());
        }
        return null;
    }

    public Void afterMotion(Command.AfterMotion c) {
        if (!plane.sameChannels(c.axes())) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, source(), "AM", text());
        }
        buffer.waited();
        return null;
    }

    public Void analogOut(Command.AnalogOut c) {
        if (c.output() == spindleAnalog) {
            spindle(c.volts().value());
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
        if (c.setting() == Command.Setting.IT) {
            if (c.value().value() != 1) {
                out.report(Code.E336_SIM_SMOOTHING, source(), text());
            }
            return null;
        }
        if (c.channel() != spindleChannel) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, source(), c.setting().name(), text());
        }
        return null;
    }

    public Void softLimit(Command.SoftLimit c) {
        if (!plane.sameChannels("" + c.first() + c.second())) {
            out.report(Code.E313_SIM_VECTOR_PLANE, source(), c.forward() ? "FL" : "BL", "" + c.first() + c.second(),
                    plane.letters());
        }
        return null;
    }

    /** A call of a wait routine (spindle at speed, turret in position): the replay's machine answers at once. */
    public Void call(Command.Call c) {
        if (buffer.begun() && c.label().equals(gcnc.dmc.StreamSplit.BUFFER_WAIT)) {
            buffer.feed();
        }
        if (c.label().equals(gcnc.dmc.ProgramStop.LABEL)) {
            out.programStop(line());
        }
        return null;
    }
}
