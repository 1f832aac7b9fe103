package gcnc.sim;

import gcnc.diag.Code;
import java.util.ArrayList;
import java.util.List;

/**
 * Replays the DMC that gcnc emits (docs/dmc-format.md, both dialects), one line at a time, and
 * hands what the machine does to a {@link Listener}: vector sequences when BGS starts them,
 * dwells, tool changes, output changes. An instruction it does not know, or bad arguments, is
 * reported (E300/E301), never skipped silently. Positions are Galil coordinates in the vector
 * plane; {@link Plane} turns them into machine counts.
 */
final class DmcInterpreter {
    /** What the replayed program makes the machine do. */
    interface Listener {
        void sequence(List<Segment> segments, double speed, int line, String text);

        void dwell(double seconds, int line);

        void tool(int n, int line);

        void output(int bit, boolean on, int line);

        void spindleVolts(double volts, int line);

        void report(Code code, int line, Object... args);
    }

    private static final double INT32 = 2147483647;
    /** The comment gcnc writes before a feed at the rapid speed ({@link #feedMarked}). */
    static final String FEED_MARK = "NO G01";

    private final Plane plane;
    private final Listener out;
    private double g1;
    private double g2;
    private double seqStart1;
    private double seqStart2;
    private double cursor1;
    private double cursor2;
    private final List<Segment> pending = new ArrayList<>();
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
    private String gearLine = "";
    /**
     * The geared segments of the pass before the current ratios: one per change of the ratios
     * while geared (a chamfered pull-out's corner, docs/threading.md); empty for a straight pass.
     */
    private final List<Segment> geared = new ArrayList<>(1);
    /** The encoder counts the master turned over those segments (for the pass's speed). */
    private double masterTurned;

    DmcInterpreter(Plane plane, double x, double z, double acc, double dec, double speed, char spindleAxis,
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

    void line(String raw, int line) {
        String t = raw.strip();
        if (t.equals(FEED_MARK)) {
            feedMarked = true;
            return;
        }
        if (t.isEmpty() || t.startsWith("'") || t.equals("NO") || t.startsWith("NO ")) {
            return;
        }
        if (t.startsWith("#")) {
            if (!t.matches("#[A-Za-z][A-Za-z0-9_]{0,7}")) {
                out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "#", t);
            }
            return;
        }
        if (ended) {
            out.report(Code.E312_SIM_AFTER_END, line, t);
            return;
        }
        if (t.startsWith("TOOL=")) {
            out.tool(integer(t.substring(5), "TOOL", t, line, 0, 9999), line);
            return;
        }
        if ((t.charAt(0) == 'R' || t.charAt(0) == 'r') && t.regionMatches(true, 0, "Revolver ", 0, 9)) {
            out.tool(integer(t.substring(9).strip(), "Revolver", t, line, 0, 9999), line);
            return;
        }
        if (t.length() >= 2 && t.charAt(0) == 'M' && Character.isDigit(t.charAt(1))) {
            integer(t.substring(1), "M", t, line, 0, 999); // thesis pass-through: no output, no effect
            return;
        }
        if (t.length() < 2) {
            out.report(Code.E300_SIM_UNKNOWN_INSTRUCTION, line, t);
            return;
        }
        if (Character.isLowerCase(t.charAt(0)) && t.indexOf('=') > 0) {
            assignment(t, line);
            return;
        }
        // the commands of nearly every line, read in place: no substrings for 5 lines a block
        char c0 = t.charAt(0);
        char c1 = t.charAt(1);
        if (c0 == 'V' && c1 == 'P') {
            vp(t, 2, t, line);
        } else if (c0 == 'C' && c1 == 'R') {
            cr(t, 2, t, line);
        } else if (c0 == 'V' && c1 == 'S') {
            speed = positive(t, 2, "VS", t, line, speed);
        } else if (t.equals("BGS")) {
            begin(line, t);
        } else if (!t.equals("AMS")) {
            command(t.substring(0, 2), t.substring(2).strip(), t, line);
        }
    }

    /** Any command but VP, CR and VS, which {@link #line} reads in place. */
    private void command(String cmd, String args, String text, int line) {
        switch (cmd) {
            case "SH", "VM" -> {
                if (!plane.sameChannels(args)) {
                    out.report(Code.E313_SIM_VECTOR_PLANE, line, cmd, args, plane.letters);
                }
            }
            case "VA" -> acceleration = positive(args, 0, cmd, text, line, acceleration);
            case "VD" -> deceleration = positive(args, 0, cmd, text, line, deceleration);
            case "VE", "EN" -> {
                if (!args.isEmpty()) {
                    out.report(Code.E301_SIM_BAD_ARGUMENTS, line, cmd, text);
                }
                ended = cmd.equals("EN");
            }
            case "BG" -> {
                if (args.equals("S")) {
                    begin(line, text);
                } else if (plane.sameChannels(args) && !Double.isNaN(target1)) {
                    threadPass(line, text);
                } else {
                    out.report(Code.E301_SIM_BAD_ARGUMENTS, line, cmd, text);
                }
            }
            case "AM" -> {
                if (!args.equals("S") && !plane.sameChannels(args)) {
                    out.report(Code.E301_SIM_BAD_ARGUMENTS, line, cmd, text);
                }
            }
            case "GA" -> gearAxes(args, text, line);
            case "MF", "MR" -> tripPoint(cmd, args, text, line);
            case "GR" -> gearRatio(args, text, line);
            case "PA" -> settle(args, text, line);
            case "WT" -> out.dwell(integer(args, cmd, text, line, 0, Integer.MAX_VALUE) / 1000.0, line);
            case "SB", "CB" -> {
                int bit = integer(args, cmd, text, line, 0, 999);
                if (bit >= 0) {
                    out.output(bit, cmd.equals("SB"), line);
                }
            }
            case "OF" -> of(args, text, line);
            default -> out.report(Code.E300_SIM_UNKNOWN_INSTRUCTION, line, text);
        }
    }

    /** VP with its arguments in args from {@code from} on. */
    private void vp(String args, int from, String text, int line) {
        int comma = args.indexOf(',', from);
        long p = comma < 0 ? BAD : parseLong(args, from, comma);
        long q = comma < 0 ? BAD : parseLong(args, comma + 1, args.length());
        if (p == BAD || q == BAD) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "VP", text);
            return;
        }
        if (Math.abs(p) > INT32 || Math.abs(q) > INT32) {
            out.report(Code.E310_SIM_COUNT_RANGE, line, text);
            return;
        }
        startIfNeeded();
        double e1 = seqStart1 + p;
        double e2 = seqStart2 + q;
        add(new Segment(plane.machineX(cursor1, cursor2), plane.machineZ(cursor1, cursor2),
                plane.machineX(e1, e2), plane.machineZ(e1, e2), false, 0, 0, 0, 0, 0, text), e1, e2, line);
    }

    /** CR with its arguments in args from {@code from} on: three numbers between commas. */
    private void cr(String args, int from, String text, int line) {
        double[] v = new double[3];
        int at = from;
        boolean ok = true;
        for (int i = 0; ok && i < 3; i++) {
            int comma = args.indexOf(',', at);
            int end = i < 2 ? comma : args.length();
            ok = end >= 0 && (i < 2 || comma < 0);
            v[i] = ok ? decimal(args, at, end, false) : Double.NaN;
            ok = ok && !Double.isNaN(v[i]);
            at = end + 1;
        }
        if (!ok || v[0] <= 0 || Math.abs(v[2]) > 360 * 1000) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "CR", text);
            return;
        }
        if (v[2] == 0 && !checkedByCaller) {
            out.report(Code.E309_SIM_ZERO_SWEEP_ARC, line, text);
        }
        startIfNeeded();
        double[] end = new double[2];
        Segment arc = plane.cr(cursor1, cursor2, v[0], v[1], v[2], text, end);
        add(arc, end[0], end[1], line);
    }

    private void startIfNeeded() {
        if (pending.isEmpty()) {
            seqStart1 = g1;
            seqStart2 = g2;
            cursor1 = g1;
            cursor2 = g2;
        }
    }

    private void add(Segment s, double e1, double e2, int line) {
        if (Math.abs(e1) > INT32 || Math.abs(e2) > INT32) {
            out.report(Code.E310_SIM_COUNT_RANGE, line, "the end point of '" + s.text() + "'");
        }
        pending.add(s);
        cursor1 = e1;
        cursor2 = e2;
    }

    private void begin(int line, String text) {
        if (pending.isEmpty()) {
            return;
        }
        // The controller's position is whole counts: an arc that ends a fraction off its target
        // leaves the axes at the nearest count, and the next sequence starts from there.
        g1 = Math.rint(cursor1);
        g2 = Math.rint(cursor2);
        // The listener reads the segments during the call and keeps none of them.
        out.sequence(pending, speed, line, text);
        pending.clear();
        feedMarked = false;
    }

    private void of(String args, String text, int line) {
        String[] a = args.split(",", -1);
        for (int i = 0; i < a.length; i++) {
            if (a[i].isBlank()) {
                continue;
            }
            double v = number(a[i]);
            if (Double.isNaN(v) || Math.abs(v) > 9.998) {
                out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "OF", text);
                return;
            }
            if (i == spindleChannel) {
                volts = v;
                out.spindleVolts(v, line);
            }
        }
    }

    /** Per-channel arguments (GA, MF, GR, PA): the value at each channel's place, "" where empty. */
    private static String[] places(String args) {
        String[] a = args.split(",", -1);
        String[] slots = new String[8];
        java.util.Arrays.fill(slots, "");
        for (int i = 0; i < a.length && i < 8; i++) {
            slots[i] = a[i].strip();
        }
        return a.length > 8 ? null : slots;
    }

    /** The plane's two channels in plane order (0: the first of VP's arguments). */
    private int planeChannel(int i) {
        return Plane.channel(plane.letters.charAt(i));
    }

    /** {@code GA}: the spindle encoder's channel is the master of both plane axes, and of nothing else. */
    private void gearAxes(String args, String text, int line) {
        String[] slots = places(args);
        boolean ok = slots != null && encoderChannel >= 0;
        for (int i = 0; ok && i < 8; i++) {
            boolean inPlane = i == planeChannel(0) || i == planeChannel(1);
            ok = inPlane ? slots[i].length() == 1 && Plane.channel(slots[i].charAt(0)) == encoderChannel
                    : slots[i].isEmpty();
        }
        if (!ok) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "GA", text);
            return;
        }
        gearMaster = true;
    }

    /**
     * {@code gsp=(@INT[_TPC/4096]+1)*4096}: the encoder count of the next whole revolution, or
     * ({@code ...*4096+2048}) a start angle past it, less than one revolution (a multi-start thread).
     */
    private void assignment(String t, int line) {
        java.util.regex.Matcher m = SYNC.matcher(t);
        if (!m.matches() || encoderChannel < 0 || Plane.channel(m.group(2).charAt(0)) != encoderChannel
                || Integer.parseInt(m.group(3)) != encoderCounts || Integer.parseInt(m.group(5)) != encoderCounts
                || m.group(6) != null && Math.abs(Long.parseLong(m.group(6))) >= encoderCounts) {
            out.report(Code.E300_SIM_UNKNOWN_INSTRUCTION, line, t);
            return;
        }
        syncVariable = m.group(1);
        synchronised = false;
    }

    private static final java.util.regex.Pattern SYNC = java.util.regex.Pattern.compile(
            "([a-z][a-z0-9]{0,7})=\\(@INT\\[_TP([A-HXYZW])/([0-9]{1,7})\\]([+-]1)\\)\\*([0-9]{1,7})([+-][0-9]{1,7})?");

    /**
     * {@code MF}/{@code MR}: on the encoder's channel with the sync variable, the wait for the whole
     * revolution (the pass will start at the same spindle angle as every other); on a plane axis
     * while geared, the point where the pass ends.
     */
    private void tripPoint(String cmd, String args, String text, int line) {
        String[] slots = places(args);
        int at = -1;
        for (int i = 0; slots != null && i < 8; i++) {
            if (!slots[i].isEmpty()) {
                at = at == -1 ? i : -2;
            }
        }
        if (at >= 0 && at == encoderChannel && slots[at].equals(syncVariable)) {
            synchronised = true;
            return;
        }
        int axis = at < 0 ? -1 : at == planeChannel(0) ? 0 : at == planeChannel(1) ? 1 : -1;
        long v = axis < 0 ? BAD : parseLong(slots[at], 0, slots[at].length());
        if (v == BAD || !engaged) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, cmd, text);
            return;
        }
        tripAxis = axis;
        trip = v;
    }

    /** {@code GR}: engages the plane axes at their ratios, or ({@code GR 0,0}) disengages them at the trip point. */
    private void gearRatio(String args, String text, int line) {
        String[] slots = places(args);
        double r1 = slots == null ? Double.NaN : slots[planeChannel(0)].isEmpty() ? 0 : number(slots[planeChannel(0)]);
        double r2 = slots == null ? Double.NaN : slots[planeChannel(1)].isEmpty() ? 0 : number(slots[planeChannel(1)]);
        if (Double.isNaN(r1) || Double.isNaN(r2) || Math.abs(r1) > gcnc.machine.SpindleEncoder.MAX_RATIO
                || Math.abs(r2) > gcnc.machine.SpindleEncoder.MAX_RATIO) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "GR", text);
            return;
        }
        if (r1 == 0 && r2 == 0) {
            if (engaged) {
                disengage(line, text);
            }
            return;
        }
        if (engaged) {
            change(r1, r2, line, text);
            return;
        }
        if (!gearMaster) {
            out.report(Code.E318_SIM_THREAD_NO_MASTER, line, text);
        } else if (!synchronised) {
            out.report(Code.E319_SIM_THREAD_UNSYNCHRONISED, line, text);
        }
        engaged = true;
        synchronised = false;
        ratio1 = r1;
        ratio2 = r2;
        engaged1 = g1;
        engaged2 = g2;
        tripAxis = -1;
        gearLine = text;
        geared.clear();
        masterTurned = 0;
    }

    /**
     * {@code GR} with other ratios while geared: at the MF/MR point on a plane axis the ratios
     * change and the master goes on (a chamfered pull-out, docs/threading.md). The segment geared so
     * far is kept; the next starts where it ended.
     */
    private void change(double r1, double r2, int line, String text) {
        double[] at = tripped(line, text, " (no MF/MR point on a geared axis says where the ratios change)");
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
        gearLine = text;
    }

    /** Where the geared axes stand when the trip axis reaches its point (the master turned the same counts for both). */
    private void disengage(int line, String text) {
        engaged = false;
        double[] at = tripped(line, text, " (no MF/MR point on a geared axis ends the pass)");
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
    private double[] tripped(int line, String text, String why) {
        double r = tripAxis == 0 ? ratio1 : ratio2;
        if (tripAxis < 0 || r == 0) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "GR", text + why);
            return null;
        }
        double master = (trip - (tripAxis == 0 ? engaged1 : engaged2)) / r;
        masterTurned += Math.abs(master);
        return new double[] {engaged1 + ratio1 * master, engaged2 + ratio2 * master, master};
    }

    /** {@code PA}: the settling move to the pass's exact end, started by {@code BG} on the plane. */
    private void settle(String args, String text, int line) {
        String[] slots = places(args);
        long p = slots == null ? BAD : parseLong(slots[planeChannel(0)], 0, slots[planeChannel(0)].length());
        long q = slots == null ? BAD : parseLong(slots[planeChannel(1)], 0, slots[planeChannel(1)].length());
        if (p == BAD || q == BAD || Double.isNaN(geared1) || engaged) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, "PA", text);
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
    private void threadPass(int line, String text) {
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
        out.sequence(one, speed, line, text);
        feedMarked = false;
    }

    /** The positive number in s from {@code from} on, else E301 and {@code otherwise}. */
    private double positive(String s, int from, String cmd, String text, int line, double otherwise) {
        double v = decimal(s, from, s.length(), false);
        if (Double.isNaN(v) || v <= 0) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, cmd, text);
            return otherwise;
        }
        if (v > INT32) {
            out.report(Code.E310_SIM_COUNT_RANGE, line, cmd + " " + s.substring(from).strip());
        }
        return v;
    }

    /** The integer, or -1 after reporting E301 when it is not one in [min, max]. */
    private int integer(String s, String cmd, String text, int line, int min, int max) {
        int v = integerOrNan(s);
        if (v == Integer.MIN_VALUE || v < min || v > max) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, line, cmd, text);
            return -1;
        }
        return v;
    }

    private static final long BAD = Long.MIN_VALUE;

    /** The optionally signed decimal integer in s[from, to) (at most 15 digits), or BAD. */
    private static long parseLong(String s, int from, int to) {
        double v = decimal(s, from, to, true);
        return Double.isNaN(v) ? BAD : (long) v;
    }

    /** Integer.MIN_VALUE when s is not an integer that fits 32 bits. */
    private static int integerOrNan(String s) {
        long v = parseLong(s, 0, s.length());
        return v == BAD || v > INT32 || v < -INT32 ? Integer.MIN_VALUE : (int) v;
    }

    private static final double[] TENS = {1, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12,
        1e13, 1e14, 1e15};

    /** The plain decimal number in s ([+-]digits[.digits], blanks around it), or NaN. */
    static double number(String s) {
        return decimal(s, 0, s.length(), false);
    }

    /**
     * The number in s[from, to), blanks (spaces, tabs) around it allowed, or NaN; {@code integer} refuses a point
     * and more than 15 digits. Up to 15 digits the value is digits / 10^k, both exact in a double,
     * so the one division rounds correctly: the value Double.parseDouble gives, without its cost
     * on every VP, CR and VS.
     */
    private static double decimal(String s, int from, int to, boolean integer) {
        int i = from;
        while (i < to && s.charAt(i) <= ' ') {
            i++;
        }
        while (to > i && s.charAt(to - 1) <= ' ') {
            to--;
        }
        boolean negative = false;
        if (i < to && (s.charAt(i) == '-' || s.charAt(i) == '+')) {
            negative = s.charAt(i) == '-';
            i++;
        }
        int start = i;
        long digits = 0;
        int count = 0;
        int decimals = -1;
        for (; i < to; i++) {
            char c = s.charAt(i);
            if (c == '.' && decimals < 0 && !integer) {
                decimals = 0;
            } else if (c >= '0' && c <= '9') {
                digits = digits * 10 + (c - '0');
                count++;
                decimals += decimals >= 0 ? 1 : 0;
            } else {
                return Double.NaN;
            }
        }
        if (count == 0 || count > 15 && integer) {
            return Double.NaN;
        }
        if (count > 15) {
            double v = Double.parseDouble(s.substring(start, to));
            return negative ? -v : v;
        }
        double v = decimals > 0 ? digits / TENS[decimals] : digits;
        return negative ? -v : v;
    }
}
