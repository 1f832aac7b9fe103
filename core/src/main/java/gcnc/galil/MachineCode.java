package gcnc.galil;

import gcnc.machine.Plane;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.dmc.Command;
import gcnc.dmc.Fixed;
import gcnc.dmc.Instruction;
import gcnc.dmc.Source;
import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import gcnc.ir.Motion;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import gcnc.machine.MachineIo;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * The machine around the motion (docs/galil.md, "Spindle", "Tool changes", "Homing and soft
 * limits", "Error handlers"): everything the galil dialect writes besides the path, from the
 * profile's {@link MachineIo}.
 * <ul>
 * <li>header: the spindle's output made a real ±10 V output and zeroed, {@code BL}/{@code FL}
 *     from the travel, the refusal to start away from home;</li>
 * <li>each block: {@code gline=<line>} first, so that a handler can say which G-code line was
 *     running; the spindle's volts; the wait for speed before the next feed; the turret's sequence;
 *     zero volts at the spindle stop; the dwell;</li>
 * <li>footer: zero volts, {@code EN}, then the routines the program jumps to and the automatic
 *     error subroutines, which stop the motion, zero the spindle, say the line and end.</li>
 * </ul>
 * GalilDialect calls it at begin, block, end; a planner that blends moves calls
 * {@link #spindleSpeed} for each speed change it places (G96 along a group).
 */
final class MachineCode {
    /** The DMC variable holding the G-code line whose commands run; the host reads it with {@code MG gline}. */
    static final String LINE = "gline";
    /** The deadline variable of the waits with a timeout. */
    static final String DEADLINE = "twt";
    /** The routine labels (at most 7 characters, Galil's label length). */
    static final String NOHOME = "NOHOME";
    static final String SPINDLE_WAIT = "SPWAIT";
    static final String TURRET = "TURRET";
    static final String FAULT = "FAULT";
    /** The program stop's wait routine (M00; M01 with the optional stop switch on). */
    static final String PROGRAM_STOP = gcnc.dmc.ProgramStop.LABEL;
    /** The DMC variable a program stop waits on: 1 while it waits; the host's continue sets it to 0. */
    static final String STOP_FLAG = gcnc.dmc.ProgramStop.FLAG;
    /** The wait for room in the vector buffer of a sequence fed while it runs (GroupWriter). */
    static final String BUFFER_WAIT = gcnc.dmc.StreamSplit.BUFFER_WAIT;
    /** The automatic subroutines gcnc installs, with what each says: DMC-40x0 command reference, pp. 12-21. */
    static final List<String> HANDLERS = List.of("CMDERR", "LIMSWI", "POSERR", "AMPERR");

    /** The OF/AO output range (galil-notes.md §1); a request up to 10 V is clamped with a warning. */
    private static final double MAX_VOLTS = 9.998;
    private static final double CLAMP_LIMIT = 10.0;
    /**
     * With an at-speed input, a speed change of more than this fraction of the last speed is waited
     * for too: the small steps of G96 along a cut are followed on the move, as the spindle follows
     * them, and do not stop the feed (nor end a blended group) at every block.
     */
    private static final double SPEED_STEP = 0.1;
    /** WT's smallest argument, ms (COMALL WT: 2 to 2,147,483,646). */
    static final long MIN_WAIT_MS = 2;

    private final MachineProfile profile;
    private final Plane plane;
    private final Diagnostics diagnostics;
    private final MachineIo io;
    /** The direction the spindle turns (M03's or M04's role), null when stopped. */
    private MRole turning;
    /** The drive's speed reference is at zero (M05, the start): an M03 must set the last speed again. */
    private boolean zeroed = true;
    private double rpm = Double.NaN;
    private boolean waitForSpeed;
    private boolean spindleWaitUsed;
    private boolean turretUsed;
    private boolean stopUsed;

    MachineCode(MachineProfile profile, Plane plane, Diagnostics diagnostics) {
        this.profile = profile;
        this.plane = plane;
        this.diagnostics = diagnostics;
        this.io = MachineIo.of(profile);
    }

    /** After the vector setup: the spindle's output, the soft limits, the homing check. */
    void setup(Consumer<Instruction> out) {
        Consumer<Command> emit = c -> out.accept(new Instruction(c, Source.NONE));
        emit.accept(new Command.SetVariable(LINE, 0));
        if (io.drive() instanceof MachineIo.SpindleDrive.Offset) {
            // zero gains: the motor command output is OF itself (Galil's OF page); ER -1: the
            // turning spindle's encoder is no position error, so #POSERR stays for the axes
            int c = profile.spindleChannel();
            emit.accept(new Command.AxisSetting(Command.Setting.KP, c, Fixed.of(0)));
            emit.accept(new Command.AxisSetting(Command.Setting.KI, c, Fixed.of(0)));
            emit.accept(new Command.AxisSetting(Command.Setting.KD, c, Fixed.of(0)));
            emit.accept(new Command.AxisSetting(Command.Setting.ER, c, Fixed.of(-1)));
            emit.accept(new Command.ServoHere(String.valueOf(profile.spindleAxis())));
        }
        emit.accept(volts(0));
        // the spindle encoder's count from 0 where the program starts (COMALL DP; docs/threading.md):
        // _TPC is 32-bit, and a count never reset reaches 2^31 after ~8.7 h at 1,000 r/min × 4,096
        profile.encoder().ifPresent(enc -> emit.accept(new Command.DefinePosition(enc.channel(), 0)));
        char p1 = plane.letters().charAt(0);
        char p2 = plane.letters().charAt(1);
        long[] low = new long[2];
        long[] high = new long[2];
        for (int i = 0; i < 2; i++) {
            gcnc.machine.Axis a = axis(plane.letters().charAt(i));
            long lo = GalilNumbers.round(a.sign() * a.min());
            long hi = GalilNumbers.round(a.sign() * a.max());
            low[i] = Math.min(lo, hi);
            high[i] = Math.max(lo, hi);
        }
        emit.accept(new Command.SoftLimit(false, p1, low[0], p2, low[1]));
        emit.accept(new Command.SoftLimit(true, p1, high[0], p2, high[1]));
        List<Command> proof = io.homing().accept(new MachineIo.Homing.Visitor<>() {
            public List<Command> position(MachineIo.Homing.Position pos) {
                long home1 = GalilNumbers.round(plane.galil1(profile.home()));
                long home2 = GalilNumbers.round(plane.galil2(profile.home()));
                return List.of(homeCheck(p1, home1, pos.toleranceMm()), homeCheck(p2, home2, pos.toleranceMm()));
            }

            public List<Command> input(MachineIo.Homing.Input in) {
                return List.of(new Command.Jump(NOHOME, Optional.of(new Command.Condition.InputIs(in.input(), false))));
            }

            public List<Command> none(MachineIo.Homing.None none) {
                return List.of();
            }
        });
        proof.forEach(emit);
    }

    private gcnc.machine.Axis axis(char letter) {
        return Plane.sameChannel(letter, profile.x().galil()) ? profile.x() : profile.z();
    }

    private Command homeCheck(char letter, long home, double toleranceMm) {
        long tolerance = Math.max(1, GalilNumbers.round(toleranceMm * axis(letter).countsPerMm()));
        return new Command.Jump(NOHOME, Optional.of(new Command.Condition.PositionOff(letter, home, tolerance)));
    }

    /**
     * {@code sink}, with {@code gline=<line>} before the block's first command (after its
     * {@code NO L} mark): nothing for a block that writes nothing.
     */
    Consumer<Instruction> marking(CheckedBlock b, Consumer<Instruction> sink) {
        return new Consumer<>() {
            private boolean marked;

            @Override
            public void accept(Instruction i) {
                if (!marked && !(i.command() instanceof Command.SourceMark)) {
                    marked = true;
                    sink.accept(new Instruction(new Command.SetVariable(LINE, b.line()),
                            new Source(b.origin(), b.line(), -1)));
                }
                sink.accept(i);
            }
        };
    }

    /**
     * The spindle's speed reference for {@code rpm}: OF on its channel or AO (E203/E251 above 10 V,
     * clamped with E204/E252 between 9.998 and 10 V). With an at-speed input, a change of more than
     * 10% while the spindle turns is waited for before the next feed; with a dwell only such a
     * change in a block that does not move (a G97 S of its own), never the G96 speeds that come
     * with the moves (a fixed dwell at every G96 jump of a roughing cycle would add seconds a pass).
     * A planner placing G96 speeds along a blended group calls this for each.
     */
    void spindleSpeed(CheckedBlock b, double rpm, BlockWriter out) {
        double v = rpm / profile.rpmPerVolt();
        boolean analog = io.drive() instanceof MachineIo.SpindleDrive.Analog;
        String name = analog ? String.valueOf(((MachineIo.SpindleDrive.Analog) io.drive()).output()) : "";
        if (v > CLAMP_LIMIT) {
            if (analog) {
                diagnostics.error(Code.E251_SPINDLE_AO_VOLTS, at(b), GalilNumbers.round(rpm), GalilNumbers.volts(v), name);
            } else {
                diagnostics.error(Code.E203_SPINDLE_VOLTS, at(b), GalilNumbers.round(rpm), GalilNumbers.volts(v));
            }
            return;
        }
        if (v > MAX_VOLTS) {
            diagnostics.report(analog
                    ? Diagnostic.warning(Code.E252_SPINDLE_AO_CLAMPED, at(b), GalilNumbers.round(rpm), GalilNumbers.volts(v), name)
                    : Diagnostic.warning(Code.E204_SPINDLE_VOLTS_CLAMPED, at(b), GalilNumbers.round(rpm), GalilNumbers.volts(v)));
            v = MAX_VOLTS;
        }
        boolean step = Double.isNaN(this.rpm) || Math.abs(rpm - this.rpm) > SPEED_STEP * this.rpm;
        if (turning != null && step && (io.atSpeed() instanceof MachineIo.AtSpeed.Input || b.motions().isEmpty())) {
            waitForSpeed = true;
        }
        this.rpm = rpm;
        out.emit(volts(v));
        zeroed = v == 0;
    }

    private Command volts(double v) {
        Fixed f = Fixed.exactly(v, 4);
        return io.drive() instanceof MachineIo.SpindleDrive.Analog a ? new Command.AnalogOut(a.output(), f)
                : new Command.Offset(profile.spindleChannel(), f);
    }

    /**
     * What an M function adds to its outputs: the spindle stop zeroes the speed reference (a drive
     * left at its last volts would start again on its own); a start restores the last speed after
     * a stop and is waited for before the next feed.
     */
    void afterM(CheckedBlock b, MCall m, BlockWriter out) {
        MFunction f = profile.control().m().get(m.code());
        MRole role = f == null ? null : f.role();
        if (role == MRole.SPINDLE_STOP) {
            turning = null;
            waitForSpeed = false;
            if (!zeroed) {
                out.emit(volts(0));
                zeroed = true;
            }
        } else if (role == MRole.SPINDLE_CW || role == MRole.SPINDLE_CCW) {
            if (zeroed && !Double.isNaN(rpm) && rpm > 0) {
                spindleSpeed(b, rpm, out);
            }
            // a start, or a reversal (the spindle stops and runs up the other way): wait
            waitForSpeed |= role != turning && !(io.atSpeed() instanceof MachineIo.AtSpeed.None);
            turning = role;
        }
    }

    /** The free slots {@code #LMWAIT} waits for; 0 while no sequence has needed feeding. */
    private int bufferWait;

    /** {@code JS #LMWAIT}: the program waits until {@code slots} slots of the vector buffer are free. */
    void awaitBuffer(int slots, BlockWriter out) {
        bufferWait = slots;
        out.emit(new Command.Call(BUFFER_WAIT));
    }

    /** Before a motion (an alone one, or a group's first): the wait for speed, when it is pending and the motion feeds. */
    void beforeMotion(Motion m, BlockWriter out) {
        if (!waitForSpeed || !feeds(m)) {
            return;
        }
        waitForSpeed = false;
        Command wait = io.atSpeed().accept(new MachineIo.AtSpeed.Visitor<>() {
            public Command input(MachineIo.AtSpeed.Input in) {
                spindleWaitUsed = true;
                return new Command.Call(SPINDLE_WAIT);
            }

            public Command dwell(MachineIo.AtSpeed.Dwell d) {
                return new Command.Wait(Math.max(MIN_WAIT_MS, GalilNumbers.round(d.seconds() * 1000)));
            }

            public Command none(MachineIo.AtSpeed.None none) {
                return null; // no wait: the drive is fast, or the operator waits
            }
        });
        if (wait != null) {
            out.emit(wait);
        }
    }

    private static boolean feeds(Motion m) {
        return m instanceof Motion.Arc || m instanceof Motion.Thread || m instanceof Motion.Linear l && !l.rapid();
    }

    /**
     * A tool change: with turret outputs, the station in binary, the strobe on, and the wait for
     * the in-position input ({@code JS #TURRET}, which clears the strobe); then {@code TOOL=n},
     * the station in the cutting position for the host and the simulator.
     */
    void toolChange(CheckedBlock b, int station, BlockWriter out) {
        if (io.turret().isPresent() && station > 0) {
            MachineIo.Turret t = io.turret().get();
            for (int i = 0; i < t.stationOutputs().size(); i++) {
                out.emit(new Command.Output(t.stationOutputs().get(i), (station >> i & 1) == 1));
            }
            out.emit(new Command.Output(t.strobe(), true));
            out.emit(new Command.Call(TURRET));
            turretUsed = true;
        }
        out.emit(new Command.ToolNumber(station));
    }

    /**
     * G04: {@code WT ms}. Below WT's 2 ms (G04 P1) the DMC waits 2 ms with warning E250: a dwell
     * is a least time, so a machinist expects at least what was asked, never an alarm for it. An
     * odd dwell is the even one above (E237), one beyond the model's WT is E226 (ControllerLimits).
     * A zero dwell waits for nothing and writes nothing.
     */
    void dwell(CheckedBlock b, double seconds, BlockWriter out) {
        long ms = GalilNumbers.round(seconds * 1000);
        if (ms == 0) {
            return;
        }
        if (ms < MIN_WAIT_MS) {
            diagnostics.report(Diagnostic.warning(Code.E250_DWELL_BELOW_WT, at(b), ms));
            ms = MIN_WAIT_MS;
        }
        // the model's WT: an odd dwell is written as the even one above (E237), beyond its range E226
        gcnc.machine.ControllerLimits limits = profile.controllerLimits();
        gcnc.machine.ControllerLimits.Rounded even = limits.roundDwell(ms);
        gcnc.machine.ControllerLimits.report(even, at(b), diagnostics);
        java.util.Optional<gcnc.machine.ControllerLimits.Violation> beyond = limits.dwell(even.taken());
        if (beyond.isPresent()) {
            gcnc.machine.ControllerLimits.report(beyond, at(b), diagnostics);
            return;
        }
        out.emit(new Command.Wait(even.taken()));
    }

    /**
     * The wait of a program stop: {@code gstop=1}, then {@code JS #PSTOP}, which says the line
     * ({@code MG}) and loops until the host sets {@code gstop=0} or the cycle start input is pressed
     * (docs/galil.md, "Program stops").
     */
    void programStop(BlockWriter out) {
        out.emit(new Command.SetVariable(STOP_FLAG, 1));
        out.emit(new Command.Call(PROGRAM_STOP));
        stopUsed = true;
    }

    /** The spindle zeroed, EN, the routines the program jumps to, and the error handlers. */
    void finish(Consumer<Instruction> sink) {
        List<Command> c = new ArrayList<>();
        if (!zeroed) {
            c.add(volts(0)); // a program that ends without M05 leaves no voltage on the drive
        }
        c.add(new Command.End());
        if (!(io.homing() instanceof MachineIo.Homing.None)) {
            c.add(new Command.Label(NOHOME));
            c.add(new Command.Message("NOT AT HOME: HOME THE MACHINE THEN START AGAIN", List.of()));
            c.add(new Command.End());
        }
        if (spindleWaitUsed && io.atSpeed() instanceof MachineIo.AtSpeed.Input in) {
            Subroutines.waitFor(c, SPINDLE_WAIT, "SPW", in.input(), in.timeoutSeconds(), List.of(), "SPINDLE NOT AT SPEED");
        }
        if (bufferWait > 0) {
            // #LMWAIT: back to itself while fewer slots are free than the next batch needs (COMALL VM, LM)
            c.add(new Command.Label(BUFFER_WAIT));
            c.add(new Command.Jump(BUFFER_WAIT, Optional.of(new Command.Condition.BufferBelow(bufferWait))));
            c.add(new Command.End());
        }
        if (turretUsed) {
            MachineIo.Turret t = io.turret().get();
            Subroutines.waitFor(c, TURRET, "TUW", t.inPosition(), t.timeoutSeconds(), List.of(new Command.Output(t.strobe(), false)),
                    "TURRET NOT IN POSITION");
        }
        if (stopUsed) {
            Subroutines.stopRoutine(c, io.cycleStart());
        }
        Subroutines.handler(c, "CMDERR", false, "COMMAND ERROR", LINE, "_TC");
        Subroutines.handler(c, "LIMSWI", false, "LIMIT SWITCH", LINE);
        Subroutines.handler(c, "POSERR", true, "POSITION ERROR", LINE);
        Subroutines.handler(c, "AMPERR", true, "AMPLIFIER FAULT", LINE);
        c.add(new Command.Label(FAULT));
        c.add(new Command.Stop());
        c.add(new Command.AfterMotion(plane.letters()));
        c.add(volts(0));
        MRole stop = MRole.SPINDLE_STOP;
        profile.control().mFor(stop).ifPresent(f -> c.addAll(MFunctions.directives(profile, f.code())));
        c.add(new Command.ClearStack()); // EN then ends the program, not the interrupted routine
        c.add(new Command.End());
        for (Command x : c) {
            sink.accept(new Instruction(x, Source.NONE));
        }
    }

    private static Span at(CheckedBlock b) {
        return Span.of(b.line(), 1);
    }
}
