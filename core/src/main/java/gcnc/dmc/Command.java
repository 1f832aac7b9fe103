package gcnc.dmc;

import gcnc.machine.MachineModel;
import java.util.Optional;

/**
 * One DMC command, as a value: everything gcnc writes for a Galil controller, one command per line
 * (docs/dmc-format.md). {@link DmcPrinter} is the only place that spells a command as text and
 * {@link DmcReader} the only place that reads one back; the backend builds commands, the simulator
 * and the sender consume them. A new command is a new record here, and the compiler then names
 * every {@link Visitor} that must learn it.
 *
 * <p>Per-axis commands ({@code GA}, {@code GR}, {@code PA}, {@code MF}/{@code MR}) name their axes
 * by Galil letter; the printer puts each value at its channel's place ({@code GA ,C,C}), the reader
 * names a place by its letter X, Y, Z, W, E..H.
 */
public sealed interface Command {
    <R> R accept(Visitor<R> v);

    /** {@code #NAME}: a program label (gcnc writes {@code #GCNC} first). */
    record Label(String name) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.label(this);
        }
    }

    /** {@code SH XY}: servo on for these axes. */
    record ServoHere(String axes) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.servoHere(this);
        }
    }

    /** {@code VM XY}: vector mode on this plane. */
    record VectorMode(String axes) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.vectorMode(this);
        }
    }

    /** {@code VA n}: vector acceleration, counts/s². */
    record VectorAcceleration(Fixed countsPerSecond2) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.vectorAcceleration(this);
        }
    }

    /** {@code VD n}: vector deceleration, counts/s². */
    record VectorDeceleration(Fixed countsPerSecond2) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.vectorDeceleration(this);
        }
    }

    /**
     * {@code NO STOCK D<d> L<l> S<s>[ B<bore>]} or {@code NO STOCK NONE}: the blank the program was
     * verified against, mm (empty: verified without one), so that a replay of the DMC by itself
     * cuts the same blank. A Galil comment: the controller ignores it.
     */
    record Stock(Optional<MachineModel.Blank> blank) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.stock(this);
        }
    }

    /**
     * {@code NO G01}: the next {@code VS} is a feed although it equals the rapid speed, which a
     * replay of the DMC by itself could not tell otherwise. A Galil comment: the controller ignores it.
     */
    record FeedMark() implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.feedMark(this);
        }
    }

    /** {@code NO L<line>}: the inline source map ({@code --source-map}); the lines after it come from this G-code line. */
    record SourceMark(int line) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.sourceMark(this);
        }
    }

    /** Any other comment ({@code NO text}, {@code 'text}), as written: gcnc writes none, a hand-edited file may. */
    record Remark(String text) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.remark(this);
        }
    }

    /** {@code VS n}: the vector speed of the segments that follow, counts/s. */
    record VectorSpeed(Fixed countsPerSecond) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.vectorSpeed(this);
        }
    }

    /**
     * {@code VP a,b <o >p}: a straight segment to this point, counts, measured from the sequence's
     * start; at speed o and ending at speed p (counts/s, {@link Speeds#NONE}: the sequence's VS
     * and no slowing at its end).
     */
    record VectorPosition(long first, long second, Speeds speeds) implements Command {
        public VectorPosition(long first, long second) {
            this(first, second, Speeds.NONE);
        }

        public <R> R accept(Visitor<R> v) {
            return v.vectorPosition(this);
        }
    }

    /**
     * {@code CR r,θ,Δθ <o >p}: an arc segment of radius r counts from start angle θ through a signed
     * sweep, degrees, with its speeds as {@link VectorPosition}'s.
     */
    record CircularArc(Fixed radius, Fixed start, Fixed sweep, Speeds speeds) implements Command {
        public CircularArc(Fixed radius, Fixed start, Fixed sweep) {
            this(radius, start, sweep, Speeds.NONE);
        }

        public <R> R accept(Visitor<R> v) {
            return v.circularArc(this);
        }

        /**
         * The arc a Galil draws for {@code CR r,θ,Δθ} from (p1, p2) in the vector plane: the centre from
         * the start angle (0° along the first plane axis, counter-clockwise positive), the end from
         * θ + Δθ; {centre1, centre2, end1, end2}. The one place of this arithmetic for the simulator's
         * replay (gcnc.sim.Segment.cr) and the virtual controller (gcnc.controller), so that both end every
         * arc on the same double and their paths compare count for count.
         */
        public static double[] geometry(double p1, double p2, double r, double startDeg, double sweepDeg) {
            double th = Math.toRadians(startDeg);
            double to = Math.toRadians(startDeg + sweepDeg);
            double c1 = p1 - r * Math.cos(th);
            double c2 = p2 - r * Math.sin(th);
            return new double[] {c1, c2, c1 + r * Math.cos(to), c2 + r * Math.sin(to)};
        }
    }

    /**
     * A segment's own speeds ({@code <o >p}, Galil's per-segment vector speeds, counts/s at the
     * default sample time): {@code speed} commanded from the segment's start, {@code end} reached at
     * its end; 0 where the command gives none.
     */
    record Speeds(long speed, long end) {
        public static final Speeds NONE = new Speeds(0, 0);

        public boolean any() {
            return speed != 0 || end != 0;
        }
    }

    /** {@code VE}: the sequence has no more segments. */
    record VectorEnd() implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.vectorEnd(this);
        }
    }

    /** {@code BGS}: begin the sequence. */
    record BeginSequence() implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.beginSequence(this);
        }
    }

    /**
     * {@code AMS}: wait until the sequence's motion is complete. {@code why} is why the machine
     * stops there, as the planner decided (null when not known: a file read back); it is not printed,
     * the source map records it.
     */
    record AwaitSequence(gcnc.plan.Stop why) implements Command {
        public AwaitSequence() {
            this(null);
        }

        public <R> R accept(Visitor<R> v) {
            return v.awaitSequence(this);
        }
    }

    /**
     * {@code AV n}: wait until the sequence has run n more counts along its path, measured from its
     * start for its first AV and from the last AV's trip point after that (Galil's command reference
     * AV: "from the start of a coordinated move sequence or from the last AV command"; DMC-40x0 User
     * Manual p.86, "After Relative Vector distance"); a trippoint of a program thread, the motion goes
     * on: what follows happens there. The trip point from the sequence's start is the sum of the
     * sequence's AVs so far, what {@code _AVS} reads there.
     */
    record AfterVector(long counts) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.afterVector(this);
        }
    }

    /** {@code OF ,,v}: the offset (volts) of the channel at {@code channel} (0 = A/X); the spindle's drive voltage. */
    record Offset(int channel, Fixed volts) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.offset(this);
        }
    }

    /** {@code WT n}: wait n ms. */
    record Wait(long milliseconds) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.await(this);
        }
    }

    /** {@code TOOL=n}: the tool in the cutting position (a DMC variable). */
    record ToolNumber(int station) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.toolNumber(this);
        }
    }

    /** {@code Revolver n}: the thesis's tool change (thesis dialect only; not a Galil command). */
    record Revolver(int station) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.revolver(this);
        }
    }

    /** {@code M5}: the thesis's pass-through of an M function with no outputs (thesis dialect only). */
    record PassThroughM(int code) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.passThroughM(this);
        }
    }

    /** {@code SBn} (on) or {@code CBn} (off): a digital output. */
    record Output(int bit, boolean on) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.output(this);
        }
    }

    /** {@code GA C,C}: the channel {@code master} (the spindle encoder) becomes the gearing master of both axes. */
    record GearMaster(char master, char first, char second) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.gearMaster(this);
        }
    }

    /**
     * {@code gsp=(@INT[_TPC/4096]+1)*4096+2048}: the encoder count of the next whole revolution
     * ({@code -1} when the spindle turns backwards), plus a start angle in counts (a multi-start thread).
     */
    record SyncPoint(String variable, char encoder, int countsPerRev, boolean reverse, long phase) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.syncPoint(this);
        }
    }

    /** {@code MF}/{@code MR} (reverse): wait until {@code axis} passes a count or a variable's value. */
    record WaitPast(boolean reverse, char axis, Operand at) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.waitPast(this);
        }
    }

    /** {@code GR r1,r2}: the gear ratios of two axes (4 decimals; {@code GR 0,0} disengages). */
    record GearRatio(char first, Fixed firstRatio, char second, Fixed secondRatio) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.gearRatio(this);
        }
    }

    /**
     * {@code gpz=(_TPC-gsp)*_GRX-(_RPX-35480)}: how far the geared slave {@code slave} stands behind
     * the helix that starts at the sync point, in its counts: the master's counts past the sync
     * variable times the slave's ratio as the controller holds it ({@code _GR}), less the slave's
     * commanded travel since it stood at {@code slaveStart} (COMALL GR, _RP; docs/threading.md).
     */
    record PhaseError(String variable, char encoder, String sync, char slave, long slaveStart) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.phaseError(this);
        }
    }

    /**
     * {@code IP gpz,gpx}: the variables' counts added to the two geared slaves' commanded positions,
     * "superimposed on top of the existing gearing motion" (COMALL IP); {@code second} is 0 (no
     * letter) when only the first slave is corrected.
     */
    record IncrementPosition(char first, String firstVariable, char second, String secondVariable) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.incrementPosition(this);
        }
    }

    /** {@code DP ,,0}: the axis's position (main encoder and commanded) defined as {@code counts} (COMALL DP). */
    record DefinePosition(char axis, long counts) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.definePosition(this);
        }
    }

    /** {@code PA a,b}: absolute targets of two axes, counts. */
    record PositionAbsolute(char first, long firstCount, char second, long secondCount) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.positionAbsolute(this);
        }
    }

    /** {@code BG XY}: begin independent motion of these axes. */
    record Begin(String axes) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.begin(this);
        }
    }

    /** {@code AM XY}: wait until these axes' motion is complete. */
    record AfterMotion(String axes) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.afterMotion(this);
        }
    }

    /** {@code EN}: end of program. */
    record End() implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.end(this);
        }
    }

    // ---- The machine around the motion (docs/galil.md "Spindle", "Tool changes", "Homing", "Handlers") ----

    /** {@code AO n,v}: analog output n at v volts; the spindle drive's speed reference on a controller with analog outputs. */
    record AnalogOut(int output, Fixed volts) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.analogOut(this);
        }
    }

    /**
     * The settings gcnc writes for one channel: the gains and the position error limit (the spindle's), and
     * IT, the smoothing filter, at 1 ("1 means no filtering", command reference IT) on the plane axes.
     */
    enum Setting { KP, KI, KD, ER, IT }

    /**
     * {@code KP ,,0}: a setting of the channel at {@code channel} (0 = A/X). gcnc writes
     * {@code KP/KI/KD 0} and {@code ER -1} on the spindle's channel only, so that {@code OF} there is
     * an open-loop voltage and the turning spindle is no position error, and {@code IT 1} on each plane
     * axis in the header, so that no smoothing burned into the unit filters the vector motion.
     */
    record AxisSetting(Setting setting, int channel, Fixed value) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.axisSetting(this);
        }
    }

    /** {@code BL a,b} (reverse) or {@code FL a,b} (forward): the software travel limits of two axes, counts. */
    record SoftLimit(boolean forward, char first, long firstCount, char second, long secondCount) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.softLimit(this);
        }
    }

    /** {@code JP #L} or {@code JP #L,condition}: jump to a label (when the condition holds). */
    record Jump(String label, Optional<Condition> when) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.jump(this);
        }
    }

    /** {@code JS #L}: call the routine at a label; its {@code EN} returns here. */
    record Call(String label) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.call(this);
        }
    }

    /** {@code MG "text",a,b}: a message to the host, the text then the values of the operands (variables, {@code _TC}). */
    record Message(String text, java.util.List<String> operands) implements Command {
        public Message {
            operands = java.util.List.copyOf(operands);
        }

        public <R> R accept(Visitor<R> v) {
            return v.message(this);
        }
    }

    /** {@code ST}: a decelerating stop of every axis. */
    record Stop() implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.stop(this);
        }
    }

    /** {@code AB 1}: abort the motion at once, not the program (the program goes on to report and end). */
    record Abort() implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.abort(this);
        }
    }

    /** {@code ZS}: clear the subroutine stack, so that an error routine's {@code EN} ends the program instead of returning. */
    record ClearStack() implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.clearStack(this);
        }
    }

    /** {@code name=n}: a DMC variable set to a whole number (gcnc's {@code gline}: the G-code line running). */
    record SetVariable(String name, long value) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.setVariable(this);
        }
    }

    /** {@code name=TIME+n}: a deadline n samples (about 1 ms each at TM 1000) from now, for a wait with a timeout. */
    record SetDeadline(String name, long samples) implements Command {
        public <R> R accept(Visitor<R> v) {
            return v.setDeadline(this);
        }
    }

    /** What a conditional {@code JP} tests. */
    sealed interface Condition {
        /** {@code @IN[n]=1} (on) or {@code @IN[n]=0}. */
        record InputIs(int input, boolean on) implements Condition {
        }

        /** {@code TIME<name}: the deadline in the variable is not reached yet. */
        record Before(String deadline) implements Condition {
        }

        /** {@code @ABS[_TPX-340000]>10}: the axis stands further than the tolerance from a count. */
        record PositionOff(char axis, long counts, long tolerance) implements Condition {
        }

        /** {@code gstop=1}: a DMC variable holds a whole number (the host's continue clears gcnc's {@code gstop}). */
        record VariableIs(String name, long value) implements Condition {
        }

        /**
         * {@code _LMS<n}: fewer than n slots of the vector buffer are free (COMALL LM: "_LMm contains
         * the number of spaces available in the sequence buffer"), the wait for room of a fed sequence.
         */
        record BufferBelow(int slots) implements Condition {
        }
    }

    /** What {@code MF}/{@code MR} waits for: a count, or a variable's value. */
    sealed interface Operand {
        record Count(long counts) implements Operand {
        }

        record Variable(String name) implements Operand {
        }
    }

    /** One method per command: a new command does not compile until every visitor handles it. */
    interface Visitor<R> {
        R label(Label c);

        R servoHere(ServoHere c);

        R vectorMode(VectorMode c);

        R vectorAcceleration(VectorAcceleration c);

        R vectorDeceleration(VectorDeceleration c);

        R stock(Stock c);

        R feedMark(FeedMark c);

        R sourceMark(SourceMark c);

        R remark(Remark c);

        R vectorSpeed(VectorSpeed c);

        R vectorPosition(VectorPosition c);

        R circularArc(CircularArc c);

        R vectorEnd(VectorEnd c);

        R beginSequence(BeginSequence c);

        R awaitSequence(AwaitSequence c);

        R afterVector(AfterVector c);

        R offset(Offset c);

        R await(Wait c);

        R toolNumber(ToolNumber c);

        R revolver(Revolver c);

        R passThroughM(PassThroughM c);

        R output(Output c);

        R gearMaster(GearMaster c);

        R syncPoint(SyncPoint c);

        R waitPast(WaitPast c);

        R gearRatio(GearRatio c);

        R phaseError(PhaseError c);

        R incrementPosition(IncrementPosition c);

        R definePosition(DefinePosition c);

        R positionAbsolute(PositionAbsolute c);

        R begin(Begin c);

        R afterMotion(AfterMotion c);

        R end(End c);

        R analogOut(AnalogOut c);

        R axisSetting(AxisSetting c);

        R softLimit(SoftLimit c);

        R jump(Jump c);

        R call(Call c);

        R message(Message c);

        R stop(Stop c);

        R abort(Abort c);

        R clearStack(ClearStack c);

        R setVariable(SetVariable c);

        R setDeadline(SetDeadline c);
    }
}
