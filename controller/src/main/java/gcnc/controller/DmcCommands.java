package gcnc.controller;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.DmcReader;
import gcnc.machine.GalilModel;
import java.util.List;
import java.util.Set;

/**
 * The commands gcnc writes (gcnc.dmc): read by {@link DmcReader}, the one reader of DMC, and executed
 * here as the virtual controller does them, in time. A program on the controller may give their
 * arguments as expressions ({@code WT dwms}, {@code VP p0[i],p1[i]}) and segment speeds
 * ({@code VP a,b <o >p}), which gcnc does not write: the expressions are evaluated and the speeds taken
 * off first ({@link Literal}), then the literal command is read. What the reader refuses is {@code ?}: E300 as TC 1,
 * E301 as TC 4, E310 as TC 6. The commands it does not execute are {@link UnexecutedCommands}'; what a
 * thread waits on after a trippoint, {@link ThreadWaits}.
 */
final class DmcCommands extends UnexecutedCommands {
    /** The heads of the commands of gcnc.dmc that take arguments; {@code TOOL=} too. */
    private static final Set<String> HEADS = Set.of("VP", "CR", "VS", "VA", "VD", "BG", "AM", "SH", "VM", "VE", "EN",
            "WT", "SB", "CB", "OF", "GA", "MF", "MR", "GR", "PA", "AV", "IP");

    private final VirtualGalil c;
    private final ProgramThread th;
    /** The segment's {@code <o} and {@code >p} speeds taken off the command ({@link Literal}), NaN when not given. */
    private double o = Double.NaN;
    private double p = Double.NaN;

    private DmcCommands(VirtualGalil c, ProgramThread th) {
        this.c = c;
        this.th = th;
    }

    /** Is {@code st} one of gcnc's DMC commands (so that this class executes it)? */
    static boolean handles(String st) {
        return st.startsWith("TOOL=") || st.length() >= 2 && HEADS.contains(st.substring(0, 2));
    }

    /** Executes {@code st} (for which {@link #handles} is true) for the host (th null) or a thread. */
    static void execute(String st, VirtualGalil c, ProgramThread th) throws GalilException {
        DmcCommands run = new DmcCommands(c, th);
        Literal lit = Literal.of(st, c);
        run.o = lit.o();
        run.p = lit.p();
        String literal = lit.text();
        GalilException[] refused = new GalilException[1];
        Command command = DmcReader.read(literal, (code, args) -> refused[0] = new GalilException(
                code == Code.E300_SIM_UNKNOWN_INSTRUCTION ? Tc.UNRECOGNIZED : code == Code.E310_SIM_COUNT_RANGE ? Tc.RANGE
                        : Tc.OPERAND));
        if (refused[0] != null) {
            throw refused[0];
        }
        if (command == null) {
            return;
        }
        try {
            command.accept(run);
        } catch (Refused r) {
            throw r.reason;
        }
    }

    private static double range(double v, double min, double max) {
        if (v < min || v > max) {
            throw Refused.refuse(Tc.RANGE);
        }
        return v;
    }

    private void onlyInProgram() {
        if (th == null) {
            throw Refused.refuse(Tc.ONLY_IN_PROGRAM);
        }
    }

    private void waitUntilStill() {
        onlyInProgram();
        th.waitingFor = ThreadWaits.sequenceStill(c.motion);
    }

    @Override
    public Void servoHere(Command.ServoHere x) {
        return Refused.doing(() -> {
            for (int a : c.axes(x.axes())) {
                c.servo[a] = true;
            }
        });
    }

    @Override
    public Void vectorMode(Command.VectorMode x) {
        return Refused.doing(() -> {
            List<Integer> a = c.axes(x.axes());
            if (a.size() != 2) {
                throw new GalilException(Tc.OPERAND);
            }
            if (c.motion.running()) {
                throw new GalilException(Tc.WHILE_RUNNING);
            }
            c.motion.clear();
            c.motion.axis1 = a.get(0);
            c.motion.axis2 = a.get(1);
        });
    }

    /** The model's range of a limit (tables/galil_models.csv), TC 6 outside it. */
    private double within(double v, GalilModel.Limit limit) {
        GalilModel.Range r = c.model.galil.range(limit);
        if (!r.holds(v, limit.below())) {
            throw Refused.refuse(Tc.RANGE);
        }
        return v;
    }

    /** VA and VD: rounded down to a multiple of the step, 1,024 (command reference VA: "VA 20000" reads 19456). */
    private double acceleration(double v) {
        long step = c.model.galil.range(GalilModel.Limit.ACCELERATION).step();
        return Math.floor(within(v, GalilModel.Limit.ACCELERATION) / step) * step;
    }

    @Override
    public Void vectorAcceleration(Command.VectorAcceleration x) {
        c.motion.va = acceleration(x.countsPerSecond2().value());
        c.motion.changed();
        return null;
    }

    @Override
    public Void vectorDeceleration(Command.VectorDeceleration x) {
        if (c.motion.running()) {
            throw Refused.refuse(Tc.WHILE_RUNNING); // "VD Not Valid while in motion"
        }
        c.motion.vd = acceleration(x.countsPerSecond2().value());
        c.motion.changed();
        return null;
    }

    @Override
    public Void vectorSpeed(Command.VectorSpeed x) {
        c.motion.vs = within(x.countsPerSecond().value(), GalilModel.Limit.VECTOR_SPEED);
        c.motion.changed();
        return null;
    }

    @Override
    public Void vectorPosition(Command.VectorPosition x) {
        return Refused.doing(() -> c.motion.vp(x.first(), x.second(), o, p));
    }

    @Override
    public Void circularArc(Command.CircularArc x) {
        return Refused.doing(() -> c.motion.cr(x.radius().value(), x.start().value(), x.sweep().value(), o, p));
    }

    @Override
    public Void vectorEnd(Command.VectorEnd x) {
        return Refused.doing(c.motion::ve);
    }

    @Override
    public Void beginSequence(Command.BeginSequence x) {
        return Refused.doing(() -> {
            VectorMotion mo = c.motion;
            if (mo.axis1 < 0) {
                throw new GalilException(Tc.NO_SEQUENCE);
            }
            if (!c.servo[mo.axis1] || !c.servo[mo.axis2]) {
                throw new GalilException(Tc.MOTOR_OFF);
            }
            if (c.limitTripped) {
                throw new GalilException(Tc.LIMIT_SWITCH);
            }
            mo.begin();
        });
    }

    @Override
    public Void awaitSequence(Command.AwaitSequence x) {
        waitUntilStill();
        return null;
    }

    /** {@code AV n}: the thread waits for the trip point ({@link ThreadWaits#afterVector}). */
    @Override
    public Void afterVector(Command.AfterVector x) {
        onlyInProgram();
        th.waitingFor = ThreadWaits.afterVector(c, x.counts());
        return null;
    }

    @Override
    public Void offset(Command.Offset x) {
        if (x.channel() >= c.model.axes) {
            throw Refused.refuse(Tc.OPERAND);
        }
        c.offsets[x.channel()] = range(x.volts().value(), -9.9982, 9.9982);
        return null;
    }

    @Override
    public Void await(Command.Wait x) {
        onlyInProgram();
        // WT: 2 to 2,147,483,646 ms (command reference WT)
        double until = c.time() + within(x.milliseconds(), GalilModel.Limit.DWELL) / 1000;
        th.waitingFor = ThreadWaits.until(c, until);
        return null;
    }

    @Override
    public Void toolNumber(Command.ToolNumber x) {
        return Refused.doing(() -> c.assign("TOOL", x.station()));
    }

    @Override
    public Void output(Command.Output x) {
        int n = (int) range(x.bit(), 1, c.model.outputs);
        c.setOutput(n, x.on());
        return null;
    }

    // Thread passes: gearing to the spindle encoder and the settling move (Gearing; docs/virtual-controller.md)

    /** An axis letter as the reader names a place (X Y Z W, E..H), TC 4 beyond the model. */
    private int axis(char letter) {
        int a = c.axis(letter);
        if (a < 0) {
            throw Refused.refuse(Tc.OPERAND);
        }
        return a;
    }

    @Override
    public Void gearMaster(Command.GearMaster x) {
        int m = axis(x.master());
        return Refused.doing(() -> {
            c.gearing.master(axis(x.first()), m);
            c.gearing.master(axis(x.second()), m);
        });
    }

    /** {@code gsp=(@INT[_TPC/4096]+1)*4096+2048}, as Galil evaluates it (@INT truncates). */
    @Override
    public Void syncPoint(Command.SyncPoint x) {
        double tp = Math.rint(c.motion.position[axis(x.encoder())]);
        double turns = tp / x.countsPerRev();
        turns = turns < 0 ? Math.ceil(turns) : Math.floor(turns);
        double value = (turns + (x.reverse() ? -1 : 1)) * x.countsPerRev() + x.phase();
        return Refused.doing(() -> c.assign(x.variable(), value));
    }

    /** {@code MF}/{@code MR}: the thread waits until the axis has passed the count forward (backward). */
    @Override
    public Void waitPast(Command.WaitPast x) {
        onlyInProgram();
        int a = axis(x.axis());
        double at = x.at() instanceof Command.Operand.Count n ? n.counts()
                : doingValue(((Command.Operand.Variable) x.at()).name());
        th.waitingFor = ThreadWaits.past(c, a, at, x.reverse()); // accurate to 2 samples (ThreadWaits.past)
        return null;
    }

    private double doingValue(String variable) {
        return Refused.reading(() -> c.variable(variable));
    }

    @Override
    public Void gearRatio(Command.GearRatio x) {
        int a = axis(x.first());
        int b = axis(x.second());
        return Refused.doing(() -> {
            // COMALL GR: "Min -127, Max 127, Resolution 1/65,536"
            c.gearing.ratio(a, range(x.firstRatio().value(), -127, 127));
            c.gearing.ratio(b, range(x.secondRatio().value(), -127, 127));
        });
    }

    /**
     * {@code IP gpu,gpv}: on a geared slave, the variable's counts "superimposed on top of the
     * existing gearing motion" at AC, DC and SP (COMALL IP); on an axis that is not geared, not
     * modelled (gcnc writes IP only right after GR).
     */
    @Override
    public Void incrementPosition(Command.IncrementPosition x) {
        int a = axis(x.first());
        int b = x.second() == 0 ? -1 : axis(x.second());
        double na = doingValue(x.firstVariable());
        double nb = b < 0 ? 0 : doingValue(x.secondVariable());
        return Refused.doing(() -> {
            c.gearing.increment(a, Math.rint(na));
            if (b >= 0) {
                c.gearing.increment(b, Math.rint(nb));
            }
        });
    }

    @Override
    public Void positionAbsolute(Command.PositionAbsolute x) {
        int a = axis(x.first());
        int b = axis(x.second());
        return Refused.doing(() -> {
            c.gearing.target(a, x.firstCount());
            c.gearing.target(b, x.secondCount());
        });
    }

    /** {@code BG XY}: independent moves of these axes to their PA targets; not while their sequence runs (TC 21). */
    @Override
    public Void begin(Command.Begin x) {
        return Refused.doing(() -> {
            List<Integer> axes = c.axes(x.axes());
            for (int a : axes) {
                if (c.motion.running() && (a == c.motion.axis1 || a == c.motion.axis2)) {
                    throw new GalilException(Tc.BEGIN_WHILE_RUNNING);
                }
            }
            for (int a : axes) {
                c.gearing.begin(a);
            }
        });
    }

    /** {@code AM XY}: the thread waits until these axes' moves are complete (the vector sequence's too for its axes). */
    @Override
    public Void afterMotion(Command.AfterMotion x) {
        return Refused.doing(() -> {
            onlyInProgram();
            List<Integer> axes = c.axes(x.axes());
            th.waitingFor = ThreadWaits.axesStill(c, axes);
        });
    }

    @Override
    public Void end(Command.End x) {
        if (th == null) {
            throw Refused.refuse(Tc.ONLY_IN_PROGRAM); // COMALL EN: "Not Valid in terminal"
        }
        th.back();
        return null;
    }
}
