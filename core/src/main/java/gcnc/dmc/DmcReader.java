package gcnc.dmc;

import gcnc.machine.Plane;
import gcnc.diag.Code;
import gcnc.dmc.Command.*;
import gcnc.machine.MachineModel;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The one place that reads a DMC line into a {@link Command} (docs/dmc-format.md): the lines
 * gcnc writes, and the few forms a hand-edited file adds (comments, {@code BG S}, {@code SB 1},
 * blanks around a line). What it cannot read is reported: E300 for an instruction it does not know,
 * E301 for arguments that are not of the command's form, E310 for a count beyond the controller's
 * 32-bit registers. Whether a command makes sense where it stands (the plane, the gearing) is the
 * controller model's to judge, not the reader's.
 */
public final class DmcReader {
    /** How gcnc's feed mark is written. */
    public static final String FEED_MARK = "NO G01";
    /** How the comment of a program verified without a blank is written. */
    public static final String STOCK_NONE = "NO STOCK NONE";

    static final double INT32 = 2147483647;
    private static final Pattern LABEL = Pattern.compile("#[A-Za-z][A-Za-z0-9_]{0,7}");
    private static final Pattern STOCK = Pattern.compile("NO STOCK D([0-9]+(?:\\.[0-9]+)?) L([0-9]+(?:\\.[0-9]+)?)"
            + " S(-?[0-9]+(?:\\.[0-9]+)?)(?: B([0-9]+(?:\\.[0-9]+)?))?");
    private static final Pattern SET = Pattern.compile("([a-z][a-z0-9]{0,7})=(-?[0-9]{1,10})");
    private static final Pattern DEADLINE = Pattern.compile("([a-z][a-z0-9]{0,7})=TIME\\+([0-9]{1,10})");
    private static final Pattern JUMP = Pattern.compile("#([A-Za-z][A-Za-z0-9_]{0,7})(?:,(.+))?");
    private static final Pattern INPUT_IS = Pattern.compile("@IN\\[([0-9]{1,3})\\]=([01])");
    private static final Pattern BEFORE = Pattern.compile("TIME<([a-z][a-z0-9]{0,7})");
    private static final Pattern BUFFER_BELOW = Pattern.compile("_LMS<([0-9]{1,3})");
    private static final Pattern POSITION_OFF = Pattern.compile(
            "@ABS\\[_TP([A-HXYZW])([+-])([0-9]{1,10})\\]>([0-9]{1,10})");
    /** {@code MG "text"} then operands: variables or underscore operands such as {@code _TC}. */
    private static final Pattern MESSAGE = Pattern.compile("\"([^\"]*)\"((?:,(?:[a-z][a-z0-9]{0,7}|_[A-Z]{2,3}[A-HS]?))*)");

    /** Where the reader reports a line it cannot read. */
    @FunctionalInterface
    public interface Faults {
        void fault(Code code, Object... args);
    }

    private DmcReader() {
    }

    /**
     * The statements of a program line, as the controller splits it: at each {@code ;} outside
     * double quotes, blanks around each removed, empty ones dropped; a comment ({@code '},
     * {@code NO}) runs to the end of the line, {@code ;} and all. A line of one command
     * (all gcnc wrote before lines were packed) is one statement.
     */
    public static java.util.List<String> statements(String line) {
        if (line.indexOf(';') < 0) {
            String t = line.strip();
            return t.isEmpty() ? java.util.List.of() : java.util.List.of(t);
        }
        java.util.List<String> out = new java.util.ArrayList<>(8);
        boolean quoted = false;
        int from = 0;
        for (int i = 0; i <= line.length(); i++) {
            char c = i < line.length() ? line.charAt(i) : ';';
            if (c == '"' && i < line.length()) {
                quoted = !quoted;
            } else if (c == ';' && (!quoted || i == line.length())) {
                String st = line.substring(from, i).strip();
                if (isComment(st)) {
                    out.add(line.substring(from).strip());
                    return out;
                }
                if (!st.isEmpty()) {
                    out.add(st);
                }
                from = i + 1;
            }
        }
        return out;
    }

    private static boolean isComment(String st) {
        return st.startsWith("'") || st.equals("NO") || st.startsWith("NO ");
    }

    /** The command on {@code raw}, or null for a blank line or one reported to {@code faults}. */
    public static Command read(String raw, Faults faults) {
        String t = raw.strip();
        if (t.isEmpty()) {
            return null;
        }
        if (isComment(t)) {
            return comment(t);
        }
        if (t.charAt(0) == '#') {
            if (!LABEL.matcher(t).matches()) {
                faults.fault(Code.E301_SIM_BAD_ARGUMENTS, "#", t);
                return null;
            }
            return new Label(t.substring(1));
        }
        if (t.startsWith("TOOL=")) {
            int n = integer(t.substring(5), 0, 9999);
            return n < 0 ? bad(faults, "TOOL", t) : new ToolNumber(n);
        }
        if (t.regionMatches(true, 0, "Revolver ", 0, 9)) {
            int n = integer(t.substring(9).strip(), 0, 9999);
            return n < 0 ? bad(faults, "Revolver", t) : new Revolver(n);
        }
        if (t.length() >= 2 && t.charAt(0) == 'M' && Character.isDigit(t.charAt(1))) {
            int n = integer(t.substring(1), 0, 999);
            return n < 0 ? bad(faults, "M", t) : new PassThroughM(n);
        }
        if (t.length() < 2) {
            faults.fault(Code.E300_SIM_UNKNOWN_INSTRUCTION, t);
            return null;
        }
        if (Character.isLowerCase(t.charAt(0)) && t.indexOf('=') > 0) {
            Matcher set = SET.matcher(t);
            if (set.matches()) {
                return new SetVariable(set.group(1), Long.parseLong(set.group(2)));
            }
            Matcher deadline = DEADLINE.matcher(t);
            if (deadline.matches()) {
                return new SetDeadline(deadline.group(1), Long.parseLong(deadline.group(2)));
            }
            return AxisReader.syncPoint(t, faults);
        }
        return command(t.substring(0, 2), t.substring(2).strip(), t, faults);
    }

    /** A two-letter Galil command {@code cmd} with its arguments {@code args} ({@code t} the whole line). */
    private static Command command(String cmd, String args, String t, Faults faults) {
        return switch (cmd) {
            case "VP", "CR" -> segment(cmd, args, t, faults);
            case "VS" -> positive(args, cmd, t, faults, VectorSpeed::new);
            case "VA" -> positive(args, cmd, t, faults, VectorAcceleration::new);
            case "VD" -> positive(args, cmd, t, faults, VectorDeceleration::new);
            case "BG" -> args.equals("S") ? new BeginSequence() : axes(args) ? new Begin(args) : bad(faults, cmd, t);
            case "AM" -> args.equals("S") ? new AwaitSequence() : axes(args) ? new AfterMotion(args) : bad(faults, cmd, t);
            case "SH" -> axes(args) ? new ServoHere(args) : bad(faults, cmd, t);
            case "VM" -> axes(args) ? new VectorMode(args) : bad(faults, cmd, t);
            case "VE" -> args.isEmpty() ? new VectorEnd() : bad(faults, cmd, t);
            case "EN" -> args.isEmpty() ? new End() : bad(faults, cmd, t);
            case "WT" -> await(args, t, faults);
            case "SB", "CB" -> output(cmd, args, t, faults);
            case "OF" -> AxisReader.offset(args, t, faults);
            case "AV" -> afterVector(args, t, faults);
            case "GA" -> AxisReader.gearMaster(args, t, faults);
            case "MF", "MR" -> AxisReader.waitPast(cmd, args, t, faults);
            case "GR" -> AxisReader.gearRatio(args, t, faults);
            case "PA" -> AxisReader.positionAbsolute(args, t, faults);
            case "IP" -> AxisReader.incrementPosition(args, t, faults);
            case "DP" -> AxisReader.definePosition(args, t, faults);
            case "AO" -> AxisReader.analogOut(args, t, faults);
            case "KP", "KI", "KD", "ER", "IT" -> AxisReader.axisSetting(Setting.valueOf(cmd), args, t, faults);
            case "BL", "FL" -> AxisReader.softLimit(cmd, args, t, faults);
            case "JP", "JS" -> jump(cmd, args, t, faults);
            case "MG" -> message(args, t, faults);
            case "ST" -> args.isEmpty() ? new Stop() : bad(faults, cmd, t);
            case "AB" -> args.equals("1") ? new Abort() : bad(faults, cmd, t); // gcnc aborts the motion only
            case "ZS" -> args.isEmpty() ? new ClearStack() : bad(faults, cmd, t);
            default -> {
                // BGS and AMS are read as BG S and AM S above; anything else is not a command gcnc writes
                faults.fault(Code.E300_SIM_UNKNOWN_INSTRUCTION, t);
                yield null;
            }
        };
    }

    /** {@code WT n}: n ms. */
    private static Command await(String args, String t, Faults faults) {
        int ms = integer(args, 0, Integer.MAX_VALUE);
        return ms < 0 ? bad(faults, "WT", t) : new Wait(ms);
    }

    /** {@code SB n} (on) or {@code CB n} (off): a digital output. */
    private static Command output(String cmd, String args, String t, Faults faults) {
        int bit = integer(args, 0, 999);
        return bit < 0 ? bad(faults, cmd, t) : new Output(bit, cmd.equals("SB"));
    }

    /** {@code AV n}: a trip point n counts along the sequence's path (never negative). */
    private static Command afterVector(String args, String t, Faults faults) {
        Fixed n = Fixed.parse(args, 0, args.length(), true);
        return n == null || n.unscaled() < 0 ? bad(faults, "AV", t) : new AfterVector(n.unscaled());
    }

    /** {@code MG "text",op,...}: a message with the operands after it. */
    private static Command message(String args, String t, Faults faults) {
        Matcher m = MESSAGE.matcher(args);
        if (!m.matches()) {
            return bad(faults, "MG", t);
        }
        String ops = m.group(2);
        return new Message(m.group(1), ops.isEmpty() ? java.util.List.of() : java.util.List.of(ops.substring(1).split(",")));
    }

    /** A segment, {@code VP a,b} or {@code CR r,θ,δ}, with its own speeds after its arguments ({@code <o >p}). */
    private static Command segment(String cmd, String args, String t, Faults faults) {
        int lt = args.indexOf('<');
        int gt = args.indexOf('>');
        int cut = lt < 0 ? gt : gt < 0 ? lt : Math.min(lt, gt);
        Command.Speeds speeds = Command.Speeds.NONE;
        String operands = args;
        if (cut >= 0) {
            speeds = speeds(args.substring(cut));
            if (speeds == null) {
                return bad(faults, cmd, t);
            }
            operands = args.substring(0, cut).strip();
        }
        if (cmd.equals("VP")) {
            VectorPosition v = vectorPosition(operands, t, faults);
            return v == null || !speeds.any() ? v : new VectorPosition(v.first(), v.second(), speeds);
        }
        CircularArc a = arc(operands, t, faults);
        return a == null || !speeds.any() ? a : new CircularArc(a.radius(), a.start(), a.sweep(), speeds);
    }

    private static Command comment(String t) {
        if (t.equals(FEED_MARK)) {
            return new FeedMark();
        }
        if (t.equals(STOCK_NONE)) {
            return new Stock(Optional.empty());
        }
        if (t.startsWith("NO L") && t.length() > 4 && t.length() < 14 && t.substring(4).chars().allMatch(Character::isDigit)) {
            return new SourceMark(Integer.parseInt(t.substring(4)));
        }
        MachineModel.Blank b = blank(t);
        return b != null ? new Stock(Optional.of(b)) : new Remark(t);
    }

    /** The blank of a {@code NO STOCK} comment, or null when the line is not one gcnc writes. */
    private static MachineModel.Blank blank(String t) {
        Matcher m = STOCK.matcher(t);
        if (!m.matches()) {
            return null;
        }
        double bore = m.group(4) == null ? 0 : Double.parseDouble(m.group(4));
        if (!(bore < Double.parseDouble(m.group(1)))) {
            return null; // a bore as wide as the blank: not a comment gcnc writes
        }
        return new MachineModel.Blank(Double.parseDouble(m.group(1)), Double.parseDouble(m.group(2)),
                Double.parseDouble(m.group(3)), bore);
    }

    static Command bad(Faults faults, String cmd, String text) {
        faults.fault(Code.E301_SIM_BAD_ARGUMENTS, cmd, text);
        return null;
    }

    /** Axis letters: one to eight of A-H, X, Y, Z, W. */
    static boolean axes(String s) {
        if (s.isEmpty() || s.length() > 8) {
            return false;
        }
        for (int i = 0; i < s.length(); i++) {
            if (Plane.channel(s.charAt(i)) < 0) {
                return false;
            }
        }
        return true;
    }

    /** {@code <o >p}, {@code <o} or {@code >p}: whole numbers of 2 to 15,000,000; null when not of that form. */
    private static Command.Speeds speeds(String s) {
        long o = 0;
        long p = 0;
        for (String part : s.strip().split("\\s+")) {
            if (part.length() < 2 || part.charAt(0) != '<' && part.charAt(0) != '>') {
                return null;
            }
            Fixed v = Fixed.parse(part, 1, part.length(), true);
            if (v == null || v.unscaled() < 1 || (part.charAt(0) == '<' ? o : p) != 0) {
                return null;
            }
            if (part.charAt(0) == '<') {
                o = v.unscaled();
            } else {
                p = v.unscaled();
            }
        }
        return new Command.Speeds(o, p);
    }

    private static VectorPosition vectorPosition(String args, String text, Faults faults) {
        int comma = args.indexOf(',');
        Fixed p = comma < 0 ? null : Fixed.parse(args, 0, comma, true);
        Fixed q = comma < 0 ? null : Fixed.parse(args, comma + 1, args.length(), true);
        if (p == null || q == null) {
            bad(faults, "VP", text);
            return null;
        }
        if (Math.abs(p.unscaled()) > INT32 || Math.abs(q.unscaled()) > INT32) {
            faults.fault(Code.E310_SIM_COUNT_RANGE, text);
            return null;
        }
        return new VectorPosition(p.unscaled(), q.unscaled());
    }

    private static CircularArc arc(String args, String text, Faults faults) {
        String[] a = args.split(",", -1);
        Fixed[] v = new Fixed[3];
        for (int i = 0; a.length == 3 && i < 3; i++) {
            v[i] = Fixed.parse(a[i], 0, a[i].length(), false);
        }
        if (v[2] == null || v[0] == null || v[1] == null || v[0].value() <= 0 || Math.abs(v[2].value()) > 360 * 1000) {
            bad(faults, "CR", text);
            return null;
        }
        return new CircularArc(v[0], v[1], v[2]);
    }

    private static Command positive(String args, String cmd, String text, Faults faults,
                                    java.util.function.Function<Fixed, Command> make) {
        Fixed v = Fixed.parse(args, 0, args.length(), false);
        if (v == null || v.value() <= 0) {
            return bad(faults, cmd, text);
        }
        if (v.value() > INT32) {
            faults.fault(Code.E310_SIM_COUNT_RANGE, cmd + " " + args);
        }
        return make.apply(v);
    }

    private static Command jump(String cmd, String args, String text, Faults faults) {
        Matcher m = JUMP.matcher(args);
        if (!m.matches() || cmd.equals("JS") && m.group(2) != null) {
            return bad(faults, cmd, text);
        }
        if (cmd.equals("JS")) {
            return new Call(m.group(1));
        }
        if (m.group(2) == null) {
            return new Jump(m.group(1), Optional.empty());
        }
        Condition when = condition(m.group(2));
        return when == null ? bad(faults, cmd, text) : new Jump(m.group(1), Optional.of(when));
    }

    /** The conditions gcnc writes after {@code JP #L,}; null for any other. */
    private static Condition condition(String c) {
        Matcher m = INPUT_IS.matcher(c);
        if (m.matches()) {
            return new Condition.InputIs(Integer.parseInt(m.group(1)), m.group(2).equals("1"));
        }
        m = BEFORE.matcher(c);
        if (m.matches()) {
            return new Condition.Before(m.group(1));
        }
        m = SET.matcher(c);
        if (m.matches()) {
            return new Condition.VariableIs(m.group(1), Long.parseLong(m.group(2)));
        }
        m = BUFFER_BELOW.matcher(c);
        if (m.matches()) {
            return new Condition.BufferBelow(Integer.parseInt(m.group(1)));
        }
        m = POSITION_OFF.matcher(c);
        if (m.matches()) {
            long n = Long.parseLong(m.group(3));
            if (n == 0 && m.group(2).equals("+")) {
                return null; // gcnc writes _TPX-0
            }
            return new Condition.PositionOff(m.group(1).charAt(0), m.group(2).equals("-") ? n : -n,
                    Long.parseLong(m.group(4)));
        }
        return null;
    }

    /** The whole number in s within [min, max], or -1. */
    static int integer(String s, int min, int max) {
        Fixed v = Fixed.parse(s, 0, s.length(), true);
        return v == null || v.unscaled() < min || v.unscaled() > max ? -1 : (int) v.unscaled();
    }
}
