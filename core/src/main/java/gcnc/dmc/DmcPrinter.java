package gcnc.dmc;

import gcnc.machine.Plane;
import gcnc.dmc.Command.*;
import gcnc.machine.MachineModel;

/**
 * The one place that spells a {@link Command} as a DMC line (docs/dmc-format.md): upper case, a
 * space between command and arguments, arguments separated by commas without spaces, per-axis
 * arguments at their channels' places with the empty places' commas kept ({@code OF ,,3.0000}).
 * Numbers print as they are held ({@link Fixed}), so the dialect that built them decides their form.
 * {@link DmcReader} reads every line this prints back to an equal command.
 */
public final class DmcPrinter {
    private DmcPrinter() {
    }

    public static String print(Command c) {
        return c.accept(SPELL);
    }

    private static final Visitor<String> SPELL = new Visitor<>() {
        public String label(Label c) {
            return "#" + c.name();
        }

        public String servoHere(ServoHere c) {
            return "SH " + c.axes();
        }

        public String vectorMode(VectorMode c) {
            return "VM " + c.axes();
        }

        public String vectorAcceleration(VectorAcceleration c) {
            return "VA " + c.countsPerSecond2();
        }

        public String vectorDeceleration(VectorDeceleration c) {
            return "VD " + c.countsPerSecond2();
        }

        public String stock(Stock c) {
            if (c.blank().isEmpty()) {
                return DmcReader.STOCK_NONE;
            }
            MachineModel.Blank b = c.blank().get();
            return "NO STOCK D" + Fixed.fourDecimals(b.diameter()) + " L" + Fixed.fourDecimals(b.length())
                    + " S" + Fixed.fourDecimals(b.stickout()) + (b.bore() > 0 ? " B" + Fixed.fourDecimals(b.bore()) : "");
        }

        public String feedMark(FeedMark c) {
            return DmcReader.FEED_MARK;
        }

        public String sourceMark(SourceMark c) {
            return "NO L" + c.line();
        }

        public String remark(Remark c) {
            return c.text();
        }

        public String vectorSpeed(VectorSpeed c) {
            StringBuilder sb = new StringBuilder(16).append("VS ");
            c.countsPerSecond().appendTo(sb); // (no String of the number by itself)
            return sb.toString();
        }

        public String vectorPosition(VectorPosition c) {
            return speeds(new StringBuilder(40).append("VP ").append(c.first()).append(',').append(c.second()), c.speeds());
        }

        public String circularArc(CircularArc c) {
            StringBuilder sb = new StringBuilder(32).append("CR ");
            c.radius().appendTo(sb);
            c.start().appendTo(sb.append(','));
            c.sweep().appendTo(sb.append(','));
            return speeds(sb, c.speeds());
        }

        public String vectorEnd(VectorEnd c) {
            return "VE";
        }

        public String beginSequence(BeginSequence c) {
            return "BGS";
        }

        public String awaitSequence(AwaitSequence c) {
            return "AMS";
        }

        public String afterVector(AfterVector c) {
            return "AV " + c.counts();
        }

        public String offset(Offset c) {
            return atChannel(new StringBuilder(16).append("OF "), c.channel(), c.volts());
        }

        public String await(Wait c) {
            return "WT " + c.milliseconds();
        }

        public String toolNumber(ToolNumber c) {
            return "TOOL=" + c.station();
        }

        public String revolver(Revolver c) {
            return "Revolver " + c.station();
        }

        public String passThroughM(PassThroughM c) {
            return "M" + c.code();
        }

        public String output(Output c) {
            return (c.on() ? "SB" : "CB") + c.bit();
        }

        public String gearMaster(GearMaster c) {
            String m = String.valueOf(c.master());
            return "GA " + places(new char[] {c.first(), c.second()}, m, m);
        }

        public String syncPoint(SyncPoint c) {
            String n = Integer.toString(c.countsPerRev());
            String shift = c.phase() == 0 ? "" : (c.phase() > 0 ? "+" : "") + c.phase();
            return c.variable() + "=(@INT[_TP" + c.encoder() + "/" + n + "]" + (c.reverse() ? "-1" : "+1") + ")*" + n
                    + shift;
        }

        public String waitPast(WaitPast c) {
            String at = c.at() instanceof Operand.Count n ? Long.toString(n.counts())
                    : ((Operand.Variable) c.at()).name();
            return (c.reverse() ? "MR " : "MF ") + places(new char[] {c.axis()}, at);
        }

        public String gearRatio(GearRatio c) {
            return "GR " + places(new char[] {c.first(), c.second()}, c.firstRatio().toString(),
                    c.secondRatio().toString());
        }

        public String phaseError(PhaseError c) {
            String start = c.slaveStart() < 0 ? "+" + -c.slaveStart() : "-" + c.slaveStart();
            return c.variable() + "=(_TP" + c.encoder() + "-" + c.sync() + ")*_GR" + c.slave() + "-(_RP" + c.slave()
                    + start + ")";
        }

        public String incrementPosition(IncrementPosition c) {
            return c.second() == 0 ? "IP " + places(new char[] {c.first()}, c.firstVariable())
                    : "IP " + places(new char[] {c.first(), c.second()}, c.firstVariable(), c.secondVariable());
        }

        public String definePosition(DefinePosition c) {
            return "DP " + places(new char[] {c.axis()}, Long.toString(c.counts()));
        }

        public String positionAbsolute(PositionAbsolute c) {
            return "PA " + places(new char[] {c.first(), c.second()}, Long.toString(c.firstCount()),
                    Long.toString(c.secondCount()));
        }

        public String begin(Begin c) {
            return "BG " + c.axes();
        }

        public String afterMotion(AfterMotion c) {
            return "AM " + c.axes();
        }

        public String end(End c) {
            return "EN";
        }

        public String analogOut(AnalogOut c) {
            StringBuilder sb = new StringBuilder(16).append("AO ").append(c.output()).append(',');
            c.volts().appendTo(sb);
            return sb.toString();
        }

        public String axisSetting(AxisSetting c) {
            return atChannel(new StringBuilder(16).append(c.setting().name()).append(' '), c.channel(), c.value());
        }

        public String softLimit(SoftLimit c) {
            return (c.forward() ? "FL " : "BL ") + places(new char[] {c.first(), c.second()},
                    Long.toString(c.firstCount()), Long.toString(c.secondCount()));
        }

        public String jump(Jump c) {
            return "JP #" + c.label() + c.when().map(w -> "," + condition(w)).orElse("");
        }

        public String call(Call c) {
            return "JS #" + c.label();
        }

        public String message(Message c) {
            StringBuilder sb = new StringBuilder(64).append("MG \"").append(c.text()).append('"');
            for (String o : c.operands()) {
                sb.append(',').append(o);
            }
            return sb.toString();
        }

        public String stop(Stop c) {
            return "ST";
        }

        public String abort(Abort c) {
            return "AB 1";
        }

        public String clearStack(ClearStack c) {
            return "ZS";
        }

        public String setVariable(SetVariable c) {
            return c.name() + "=" + c.value();
        }

        public String setDeadline(SetDeadline c) {
            return c.name() + "=TIME+" + c.samples();
        }
    };

    /** A {@code JP} condition as DMC writes it. */
    static String condition(Condition w) {
        if (w instanceof Condition.InputIs in) {
            return "@IN[" + in.input() + "]=" + (in.on() ? 1 : 0);
        }
        if (w instanceof Condition.Before b) {
            return "TIME<" + b.deadline();
        }
        if (w instanceof Condition.VariableIs v) {
            return v.name() + "=" + v.value();
        }
        if (w instanceof Condition.BufferBelow b) {
            return "_LMS<" + b.slots();
        }
        Condition.PositionOff p = (Condition.PositionOff) w;
        String at = p.counts() < 0 ? "+" + (-p.counts()) : "-" + p.counts();
        return "@ABS[_TP" + p.axis() + at + "]>" + p.tolerance();
    }

    /** {@code <o >p} after a segment's arguments, each only when given. */
    private static String speeds(StringBuilder sb, Speeds s) {
        if (s.speed() != 0) {
            sb.append(" <").append(s.speed());
        }
        if (s.end() != 0) {
            sb.append(" >").append(s.end());
        }
        return sb.toString();
    }

    /** One value at its channel's place (0 = A/X), a comma for each place before it: {@code ,,3.0000}. */
    private static String atChannel(StringBuilder sb, int channel, Fixed value) {
        for (int i = 0; i < channel; i++) {
            sb.append(',');
        }
        value.appendTo(sb);
        return sb.toString();
    }

    /** Values at their axes' channel places, the places before the last one empty where no value goes. */
    private static String places(char[] axes, String... values) {
        int last = -1;
        int[] at = new int[axes.length];
        for (int i = 0; i < axes.length; i++) {
            at[i] = Plane.channel(axes[i]);
            if (at[i] < 0) {
                throw new IllegalArgumentException("not a Galil axis: " + axes[i]);
            }
            last = Math.max(last, at[i]);
        }
        String[] slots = new String[last + 1];
        java.util.Arrays.fill(slots, "");
        for (int i = 0; i < axes.length; i++) {
            slots[at[i]] = values[i];
        }
        return String.join(",", slots);
    }
}
