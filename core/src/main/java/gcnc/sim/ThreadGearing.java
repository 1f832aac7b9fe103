package gcnc.sim;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.Instruction;
import gcnc.machine.Plane;
import java.util.ArrayList;
import java.util.List;

/**
 * The gearing of a thread pass as the DMC sets it up (docs/dmc-format.md, "Thread passes"): the
 * spindle encoder made the plane axes' master (GA), the sync point on its next whole revolution
 * ({@code gsp=...}, MF), the ratios engaged, changed and ended at trip points (GR, MF/MR), the
 * phase error measured and taken out ({@code gpu=...}, IP), the settling move (PA), and the pass
 * all of that makes, which {@link #pass} hands to the controller to run at BG as one cutting
 * sequence. It holds the state of the pass being geared and each thread's phase spread, and moves
 * no axis itself; a gearing command that makes no sense where it stands is reported (E301,
 * E317-E319, E340) through the controller's {@link ReplayListener}.
 */
final class ThreadGearing {
    /** How far apart, in counts, the passes of one thread may start before it is E340 (issue 30: 2 counts). */
    static final double PHASE_TOLERANCE = 2;
    /** The servo sample (COMALL TM default 1000 µs; gcnc never sets TM), seconds. */
    static final double SAMPLE = 0.001;

    /** A geared pass and its settling move: the segments, their speed, and where they leave the plane axes (Galil counts). */
    record GearedPass(List<Segment> segments, double speed, double end1, double end2) {
    }

    private final Plane plane;
    private final ReplayListener out;
    /**
     * The spindle encoder threads are geared to (channel, counts per revolution; -1 when the
     * machine has none), the drive's r/min per volt (for a thread pass's speed) and how far, in
     * counts, a geared pass may end from its settling move before it is E317.
     */
    private final int encoderChannel;
    private final int encoderCounts;
    private final double rpmPerVolt;
    private final double threadTolerance;
    /** The spindle's volts, what turns the master. */
    private double volts;
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
    /**
     * The threads already warned of (E340): a thread is its G-code line in its file (a called
     * program's line 12 is not the main program's), so each thread is warned of once, at its first
     * pass that starts off the helix by more than {@link #PHASE_TOLERANCE}.
     */
    private final java.util.Set<ThreadLine> phaseReported = new java.util.HashSet<>();

    /** A thread's G-code line: its file (null for the program's own) and line number. */
    private record ThreadLine(String file, int line) {
    }

    /**
     * @param encoderChannel the spindle encoder's channel, -1 when the machine has none
     * @param encoderCounts  its counts per revolution
     * @param rpmPerVolt     the spindle drive's r/min per volt
     * @param threadTolerance how far, in counts, a geared pass may end from its settling move (E317)
     */
    ThreadGearing(Plane plane, int encoderChannel, int encoderCounts, double rpmPerVolt, double threadTolerance,
                  ReplayListener out) {
        this.plane = plane;
        this.encoderChannel = encoderChannel;
        this.encoderCounts = encoderCounts;
        this.rpmPerVolt = rpmPerVolt;
        this.threadTolerance = threadTolerance;
        this.out = out;
    }

    /** The spindle was set to {@code volts}: the master turns at what they give from now on. */
    void spindle(double volts) {
        this.volts = volts;
    }

    /** The plane's two channels in plane order (0: the first of VP's arguments). */
    private int planeChannel(int i) {
        return i == 0 ? plane.first() : plane.second();
    }

    /** The plane index (0, 1) of a channel, -1 when it is not a plane axis. */
    private int planeAxis(int channel) {
        return channel == planeChannel(0) ? 0 : channel == planeChannel(1) ? 1 : -1;
    }

    /** {@code GA}: the spindle encoder's channel is the master of both plane axes, and of nothing else. */
    void master(Command.GearMaster c, Instruction at) {
        if (encoderChannel < 0 || Plane.channel(c.master()) != encoderChannel
                || !plane.sameChannels("" + c.first() + c.second())) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, at.source(), "GA", at.text());
            return;
        }
        gearMaster = true;
    }

    /**
     * {@code gsp=(@INT[_TPC/4096]+1)*4096}: the encoder count of the next whole revolution, or
     * ({@code ...*4096+2048}) a start angle past it, less than one revolution (a multi-start thread).
     */
    void syncPoint(Command.SyncPoint c, Instruction at) {
        if (encoderChannel < 0 || Plane.channel(c.encoder()) != encoderChannel || c.countsPerRev() != encoderCounts
                || Math.abs(c.phase()) >= encoderCounts) {
            out.report(Code.E300_SIM_UNKNOWN_INSTRUCTION, at.source(), at.text());
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
    void waitPast(Command.WaitPast c, Instruction at) {
        String cmd = c.reverse() ? "MR" : "MF";
        int ch = Plane.channel(c.axis());
        if (ch == encoderChannel && c.at() instanceof Command.Operand.Variable v && v.name().equals(syncVariable)) {
            synchronised = true;
            return;
        }
        int axis = planeAxis(ch);
        if (axis < 0 || !(c.at() instanceof Command.Operand.Count n) || !engaged) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, at.source(), cmd, at.text());
            return;
        }
        if (phaseLag[0] >= 0) {
            closePhase(at.source());
        }
        tripAxis = axis;
        trip = n.counts();
    }

    /**
     * {@code gpu=(_TPC-gsp)*_GRX-(_RPX-start)} right after the engagement: the phase error of a
     * geared plane axis measured against the helix from the sync variable, from where the axis
     * stood when GR engaged it; anything else is E301 (another start, variable or master).
     */
    void phaseError(Command.PhaseError c, Instruction at) {
        int axis = planeAxis(Plane.channel(c.slave()));
        double start = axis == 0 ? engaged1 : engaged2;
        if (!engaged || axis < 0 || Plane.channel(c.encoder()) != encoderChannel || !c.sync().equals(syncVariable)
                || c.slaveStart() != Math.rint(start) || phaseLag[axis] < 0) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, at.source(), "phase error", at.text());
            return;
        }
        phaseVariable[axis] = c.variable();
    }

    /** {@code IP gpu,gpv}: the measured phase errors added while geared: each axis is then on the helix to half a count. */
    void phaseCorrection(Command.IncrementPosition c, Instruction at) {
        char[] axes = c.second() == 0 ? new char[] {c.first()} : new char[] {c.first(), c.second()};
        String[] vars = {c.firstVariable(), c.secondVariable()};
        for (int i = 0; i < axes.length; i++) {
            int axis = planeAxis(Plane.channel(axes[i]));
            if (!engaged || axis < 0 || !vars[i].equals(phaseVariable[axis])) {
                out.report(Code.E301_SIM_BAD_ARGUMENTS, at.source(), "IP", at.text());
                return;
            }
            phaseLag[axis] = 0.5;
            phaseVariable[axis] = null;
        }
    }

    /**
     * The pass's first trip point: its phase offset is what it is now. The thread's phase spread
     * is the largest over its passes (docs/threading.md, "One groove"), so the first pass above
     * the tolerance is the one to warn at.
     */
    private void closePhase(gcnc.dmc.Source at) {
        double lag = Math.max(phaseLag[0], phaseLag[1]);
        if (lag > PHASE_TOLERANCE && phaseReported.add(new ThreadLine(at.file(), at.line()))) {
            out.report(Code.E340_SIM_THREAD_PHASE, at, String.format(java.util.Locale.ROOT, "%.0f", lag));
        }
        phaseLag[0] = -1;
        phaseLag[1] = -1;
    }

    /** {@code DP}: gcnc defines the spindle count only. */
    void definePosition(Command.DefinePosition c, Instruction at) {
        if (Plane.channel(c.axis()) != encoderChannel) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, at.source(), "DP", at.text());
        }
    }

    /**
     * {@code GR}: engages the plane axes at their ratios from where they stand ({@code g1, g2},
     * Galil counts), or ({@code GR 0,0}) disengages them at the trip point.
     */
    void ratio(Command.GearRatio c, Instruction at, double g1, double g2) {
        boolean firstIsFirst = Plane.channel(c.first()) == planeChannel(0);
        double r1 = (firstIsFirst ? c.firstRatio() : c.secondRatio()).value();
        double r2 = (firstIsFirst ? c.secondRatio() : c.firstRatio()).value();
        if (!plane.sameChannels("" + c.first() + c.second()) || Math.abs(r1) > gcnc.machine.SpindleEncoder.MAX_RATIO
                || Math.abs(r2) > gcnc.machine.SpindleEncoder.MAX_RATIO) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, at.source(), "GR", at.text());
            return;
        }
        if (r1 == 0 && r2 == 0) {
            if (engaged) {
                disengage(at);
            }
            return;
        }
        if (engaged) {
            change(r1, r2, at);
            return;
        }
        if (!gearMaster) {
            out.report(Code.E318_SIM_THREAD_NO_MASTER, at.source(), at.text());
        } else if (!synchronised) {
            out.report(Code.E319_SIM_THREAD_UNSYNCHRONISED, at.source(), at.text());
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
        gearLine = at;
        geared.clear();
        masterTurned = 0;
    }

    /**
     * {@code GR} with other ratios while geared: at the MF/MR point on a plane axis the ratios
     * change and the master goes on (a chamfered pull-out, docs/threading.md). The segment geared so
     * far is kept; the next starts where it ended.
     */
    private void change(double r1, double r2, Instruction at) {
        double[] end = tripped(at, " (no MF/MR point on a geared axis says where the ratios change)");
        if (end == null) {
            return;
        }
        geared.add(segment(engaged1, engaged2, end[0], end[1]));
        engaged1 = end[0];
        engaged2 = end[1];
        ratio1 = r1;
        ratio2 = r2;
        tripAxis = -1;
        gearLine = at;
    }

    /** A straight piece of the pass between two points in Galil counts, from the GR that geared it. */
    private Segment segment(double from1, double from2, double to1, double to2) {
        return new Segment(plane.machineX(from1, from2), plane.machineZ(from1, from2),
                plane.machineX(to1, to2), plane.machineZ(to1, to2), false, 0, 0, 0, 0, 0, gearLine);
    }

    /** Where the geared axes stand when the trip axis reaches its point (the master turned the same counts for both). */
    private void disengage(Instruction at) {
        engaged = false;
        double[] end = tripped(at, " (no MF/MR point on a geared axis ends the pass)");
        if (end != null) {
            geared1 = end[0];
            geared2 = end[1];
        }
    }

    /**
     * {first plane axis, second, master counts turned} when the trip axis reaches its point from
     * where the current ratios began, the master's counts added to {@link #masterTurned}; null
     * after E301 when no MF/MR on a geared axis gave the point ({@code why}).
     */
    private double[] tripped(Instruction at, String why) {
        double r = tripAxis == 0 ? ratio1 : ratio2;
        if (tripAxis < 0 || r == 0) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, at.source(), "GR", at.text() + why);
            return null;
        }
        double master = (trip - (tripAxis == 0 ? engaged1 : engaged2)) / r;
        masterTurned += Math.abs(master);
        return new double[] {engaged1 + ratio1 * master, engaged2 + ratio2 * master, master};
    }

    /** {@code PA}: the settling move to the pass's exact end, started by {@code BG} on the plane. */
    void settle(Command.PositionAbsolute c, Instruction at) {
        boolean firstIsFirst = Plane.channel(c.first()) == planeChannel(0);
        long p = firstIsFirst ? c.firstCount() : c.secondCount();
        long q = firstIsFirst ? c.secondCount() : c.firstCount();
        if (!plane.sameChannels("" + c.first() + c.second()) || Double.isNaN(geared1) || engaged) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, at.source(), "PA", at.text());
            return;
        }
        target1 = p;
        target2 = q;
    }

    /** Whether a settling move (PA) is there for BG to start. */
    boolean settling() {
        return !Double.isNaN(target1);
    }

    /**
     * The geared pass and its settling move as one cutting sequence from where the gearing began to
     * the PA target, at the speed the spindle gives it; E317 when the gearing ended further than the
     * tolerance from that target (the ratios make the wrong lead or taper). The gearing is then done.
     */
    GearedPass pass(gcnc.dmc.Source at) {
        double off = Math.hypot(geared1 - target1, geared2 - target2);
        if (off > threadTolerance) {
            double zOff = Math.abs(plane.machineZ(geared1, geared2) - plane.machineZ(target1, target2));
            out.report(Code.E317_SIM_THREAD_LEAD, at, String.format(java.util.Locale.ROOT, "%.1f", off),
                    zOff > threadTolerance ? "Z" : "X");
        }
        double rpm = volts * rpmPerVolt;
        Segment last = segment(engaged1, engaged2, target1, target2);
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
        GearedPass pass = new GearedPass(one, speed, target1, target2);
        target1 = Double.NaN;
        target2 = Double.NaN;
        geared1 = Double.NaN;
        geared2 = Double.NaN;
        return pass;
    }
}
