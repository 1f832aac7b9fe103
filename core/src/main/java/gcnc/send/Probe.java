package gcnc.send;

import gcnc.machine.GalilModel;
import gcnc.machine.ProbeRow;
import gcnc.send.ProbeReport.Result;
import gcnc.send.ProbeReport.Status;
import java.io.IOException;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * {@code gcnc controller probe}: asks a Galil, without moving anything, what the reference says it
 * answers ({@link ProbeRow}), and with {@link Motion} runs three short VP segments on two axes, reading
 * {@code _CSS} and {@code _AVS} on the way (docs/run.md, "The probe"). It downloads no program and
 * changes only what {@code gcnc run} changes too: EO 0 on a serial port, CW 1, CF I, CS S (and, for the
 * motion test, SH and VM on the two axes). Every command is one of COMALL; the rows say which words each
 * answer is held against.
 */
public final class Probe {
    /**
     * The motion test: axes {@code first} and {@code second} (channel letters), each segment
     * {@code distance} counts along the first axis at {@code speed} counts/s, then back.
     */
    public record Motion(char first, char second, int distance, int speed) {
    }

    private final GalilClient client;
    private final GalilModel model;
    private final Map<ProbeRow, Result> results = new EnumMap<>(ProbeRow.class);
    private final Map<String, String> facts = new LinkedHashMap<>();

    public Probe(GalilClient client, GalilModel model) {
        this.client = client;
        this.model = model;
    }

    /** Thrown when the motion test cannot start; the report so far is in {@link #report}. */
    public static final class NotReady extends Exception {
        public NotReady(String why) {
            super(why);
        }
    }

    /** Probes; {@code motion} null for the questions only. */
    public ProbeReport run(Motion motion, char[] axes) throws IOException, NotReady {
        boolean serial = client.link().serial();
        String revision = serial ? serialEcho() : ethernetEcho();
        if (revision == null) {
            return report(""); // no reply can be read: nothing more can be asked
        }
        String found = MachineLink.model(revision);
        set(ProbeRow.REVISION, found.isEmpty() ? Status.CONTRADICTED : Status.CONFIRMED, "DMCnnnn Rev x.yz",
                "'" + GalilClient.printable(revision) + "'");
        client.command("CW 1");
        facts.put("pending error (TC1)", text("TC1"));
        refusals();
        configuration(serial);
        facts.put("labels free (_DL)", num("_DL"));
        facts.put("variables free (_UL)", num("_UL"));
        facts.put("array elements free (DM ?)", text("DM ?"));
        facts.put("program lines (firmware " + (MachineLink.firmware12a(revision) ? "1.2a or later" : "before 1.2a") + ")",
                MachineLink.firmware12a(revision) ? "4000" : "2000");
        boolean running = number("_XQ0") >= 0;
        boolean moving = number("_BGS") != 0;
        facts.put("program running (_XQ0)", running ? "yes" : "no");
        facts.put("sequence moving (_BGS)", moving ? "yes" : "no");
        buffer(running, moving);
        String limits = axes(axes);
        set(ProbeRow.AV_RELATIVE, Status.NOT_CHECKED, "each AV from the last", "not asked: AV is a trippoint, \"Not Valid"
                + " in terminal\", and the probe downloads no program");
        if (motion == null) {
            set(ProbeRow.CS_FROM_ZERO, Status.NOT_CHECKED, "0 during the first segment", "not asked: no --allow-motion");
            set(ProbeRow.AVS_FROM_START, Status.NOT_CHECKED, "the path from the sequence start", "not asked: no --allow-motion");
            return report(revision);
        }
        if (running || moving || limits != null) {
            String why = running ? "a program runs in thread 0 (_XQ0 >= 0)" : moving ? "a sequence moves (_BGS = 1)"
                    : "a limit switch is active (" + limits + ")";
            lastReport = report(revision);
            throw new NotReady(why);
        }
        move(motion);
        return report(revision);
    }

    /**
     * Over a serial link: whether the unit echoes until {@code EO 0} (sent first), and that it no longer
     * does; the reply to {@code ^R^V}, or null when it is not readable.
     */
    private String serialEcho() throws IOException {
        boolean echoed = client.disableEcho();
        set(ProbeRow.ECHO_SERIAL, echoed == model.serialEcho() ? Status.CONFIRMED : Status.CONTRADICTED,
                model.serialEcho() ? "echo until EO 0" : "no echo", echoed ? "echoed EO 0" : "no echo");
        String revision = revisionOrGarbage();
        set(ProbeRow.ECHO_OFF, revision != null ? Status.CONFIRMED : Status.CONTRADICTED, "no echo after EO 0",
                revision != null ? "no echo" : "the reply to ^R^V was not readable");
        return revision;
    }

    /**
     * Over Ethernet: that the unit does not echo, and refuses {@code EO}; the reply to {@code ^R^V},
     * or null when the unit echoes (every further reply would carry the echo) or that reply is not
     * readable (the revision's row says so).
     */
    private String ethernetEcho() throws IOException {
        // the first question, before ^R^V (whose echoed control bytes are no protocol): an echo shows as its text
        GalilClient.Reply r = client.query("MG 20261127");
        boolean echoed = r.data().startsWith("MG");
        set(ProbeRow.NO_ECHO_ETHERNET, echoed ? Status.CONTRADICTED : Status.CONFIRMED, "no echo",
                echoed ? "echoed: '" + GalilClient.printable(r.data()) + "'" : "no echo");
        if (echoed) {
            return null;
        }
        GalilClient.Reply eo = client.command("EO 0");
        if (!eo.ok()) {
            client.query("TC1");
        }
        set(ProbeRow.EO_SERIAL_ONLY, eo.ok() ? Status.CONTRADICTED : Status.CONFIRMED, "? (not accepted over Ethernet)",
                eo.ok() ? ":" : "?");
        String revision = revisionOrGarbage();
        if (revision == null) {
            set(ProbeRow.REVISION, Status.CONTRADICTED, "DMCnnnn Rev x.yz", "the reply to ^R^V was not readable");
        }
        return revision;
    }

    /** The reference's own example of an unknown command and its TC1 text, and a command refused in the terminal. */
    private void refusals() throws IOException {
        GalilClient.Reply bad = client.command("GF32");
        String tc = text("TC1");
        set(ProbeRow.TC1_TEXT, !bad.ok() && tc.equals("1 Unrecognized command") ? Status.CONFIRMED : Status.CONTRADICTED,
                "? then 1 Unrecognized command", (bad.ok() ? ":" : "?") + " then " + tc);
        GalilClient.Reply wt = client.command("WT 2");
        String wtTc = wt.ok() ? "" : text("TC1");
        set(ProbeRow.NOT_IN_TERMINAL, !wt.ok() && wtTc.startsWith("2 ") ? Status.CONFIRMED : Status.CONTRADICTED,
                "? then 2 Command only valid from program", wt.ok() ? ":" : "? then " + wtTc);
    }

    /** Where the unit sends its unsolicited messages ({@code _CF}): serial at power-up, this port after {@code CF I}. */
    private void configuration(boolean serial) throws IOException {
        double cf = number("_CF");
        if (cf == 'S') {
            set(ProbeRow.CF_DEFAULT_SERIAL, Status.CONFIRMED, "83 (S)", "83 (S)");
        } else {
            set(ProbeRow.CF_DEFAULT_SERIAL, Status.NOT_CHECKED, "83 (S) at power-up", letter(cf)
                    + ": set since power-up (by gcnc run's CF I, or a host's CF)");
        }
        GalilClient.Reply cfi = client.command("CF I");
        String port = serial ? "S" : handle();
        double after = cfi.ok() ? number("_CF") : -1;
        set(ProbeRow.CF_THIS_PORT, cfi.ok() && port.length() == 1 && after == port.charAt(0) ? Status.CONFIRMED
                : Status.CONTRADICTED, "_CF = this port (" + port + ")", cfi.ok() ? letter(after) : "CF I refused");
    }

    /** That {@code CS S} empties the vector buffer ({@code _LMS} the whole buffer after it); not asked while anything runs. */
    private void buffer(boolean running, boolean moving) throws IOException {
        int whole = (int) model.range(GalilModel.Limit.BUFFER_SEGMENTS).max();
        if (!running && !moving) {
            GalilClient.Reply cs = client.command("CS S");
            int free = cs.ok() ? (int) number("_LMS") : -1;
            set(ProbeRow.CS_CLEARS_BUFFER, free == whole ? Status.CONFIRMED : Status.CONTRADICTED, "_LMS = " + whole,
                    cs.ok() ? "_LMS = " + free : "CS S refused");
        } else {
            set(ProbeRow.CS_CLEARS_BUFFER, Status.NOT_CHECKED, "_LMS = " + whole, "not asked: CS S is not valid while in motion");
        }
    }

    /**
     * Each axis's limit switches ({@code _LF}, {@code _LR}: 0 or 1) and smoothing ({@code _IT}: 1, none);
     * the switches as read when one is active, else null.
     */
    private String axes(char[] axes) throws IOException {
        boolean readable = true;
        boolean smoothing = false;
        StringBuilder limits = new StringBuilder();
        StringBuilder its = new StringBuilder();
        boolean active = false;
        for (char a : axes) {
            double lf = number("_LF" + a);
            double lr = number("_LR" + a);
            readable &= (lf == 0 || lf == 1) && (lr == 0 || lr == 1);
            active |= lf == 0 || lr == 0;
            limits.append(limits.length() > 0 ? ", " : "").append(a).append(": _LF ").append(num(lf)).append(" _LR ")
                    .append(num(lr));
            double it = number("_IT" + a);
            smoothing |= it != 1;
            its.append(its.length() > 0 ? ", " : "").append("_IT").append(a).append(' ').append(num(it));
        }
        set(ProbeRow.LIMITS_READABLE, readable ? Status.CONFIRMED : Status.CONTRADICTED, "0 or 1", limits.toString());
        set(ProbeRow.NO_SMOOTHING, smoothing ? Status.CONTRADICTED : Status.CONFIRMED, "1", its.toString());
        return active ? limits.toString() : null;
    }

    private ProbeReport lastReport;
    /** What {@link #moving()} says (null: no move begun, or back at rest). */
    private String moving;

    /** The report as far as it got when {@link NotReady} was thrown. */
    public ProbeReport report() {
        return lastReport;
    }

    /** One sample of the motion test. */
    private record Sample(int css, double avs) {
    }

    /** Three VP segments along the first axis, polled for _CSS and _AVS, then the same way back. */
    private void move(Motion m) throws IOException {
        int d = m.distance();
        String plane = "" + m.first() + m.second();
        require("SH " + plane);
        require("VM " + plane);
        require("VS " + m.speed());
        int accel = Math.max(1024, (m.speed() * 10) / 1024 * 1024);
        require("VA " + accel);
        require("VD " + accel);
        for (int k = 1; k <= 3; k++) {
            require("VP " + k * d + ",0");
        }
        require("VE");
        moving = "the motion test had started (BGS): axis " + m.first() + " may stand up to " + 3 * d
                + " counts (3 x --distance) from where it was, or still move; ST before anything else";
        require("BGS");
        List<Sample> samples = new ArrayList<>();
        long until = System.currentTimeMillis() + 5000L + 3000L * d / Math.max(1, m.speed()) * 3;
        while (System.currentTimeMillis() < until) {
            double[] v = client.numbers("MG _CSS,_AVS,_BGS");
            if (v.length < 3) {
                throw new LinkFault(LinkFault.Kind.GARBAGE, "MG _CSS,_AVS,_BGS", v.length + " numbers where 3 belong");
            }
            samples.add(new Sample((int) v[0], v[1]));
            if (v[2] == 0) {
                break;
            }
        }
        double end = number("_AVS");
        judge(samples, d, end);
        require("VP " + -3 * d + ",0");
        require("VE");
        require("BGS");
        while (System.currentTimeMillis() < until + 10_000 && number("_BGS") != 0) {
            client.query("MG _BGS");
        }
        moving = null;
    }

    /**
     * After a fault during the motion test, where axis {@code first} may be and what to do first; null
     * when the test had not begun a move, or had come back to rest.
     */
    public String moving() {
        return moving;
    }

    private void judge(List<Sample> samples, int d, double end) {
        List<String> first = new ArrayList<>();
        List<String> second = new ArrayList<>();
        boolean fromZero = true;
        boolean seen = false;
        double last = -1;
        boolean rising = true;
        for (Sample s : samples) {
            rising &= s.avs() >= last;
            last = s.avs();
            if (s.avs() > 0.05 * d && s.avs() < 0.9 * d) {
                seen = true;
                fromZero &= s.css() == 0;
                first.add(Integer.toString(s.css()));
            } else if (s.avs() > 1.1 * d && s.avs() < 1.9 * d) {
                fromZero &= s.css() == 1;
                second.add(Integer.toString(s.css()));
            }
        }
        String observed = "first segment _CSS " + distinct(first) + "; second " + distinct(second);
        set(ProbeRow.CS_FROM_ZERO, !seen ? Status.NOT_CHECKED : fromZero ? Status.CONFIRMED : Status.CONTRADICTED,
                "0 during the first segment, 1 during the second", seen ? observed : "no sample inside the first segment"
                        + " (slower --speed)");
        boolean atEnd = Math.abs(end - 3.0 * d) <= 2;
        set(ProbeRow.AVS_FROM_START, rising && atEnd ? Status.CONFIRMED : Status.CONTRADICTED,
                "rising to " + 3 * d + " at the end", (rising ? "rising" : "not rising") + " to " + num(end));
    }

    private static String distinct(List<String> v) {
        return v.isEmpty() ? "(no sample)" : String.join(",", new java.util.LinkedHashSet<>(v));
    }

    private void require(String command) throws IOException {
        if (!client.command(command).ok()) {
            throw new GalilClient.Rejected(command);
        }
    }

    /** ^R^V's text, or null when the reply cannot be read (an echo still on). */
    private String revisionOrGarbage() throws IOException {
        try {
            GalilClient.Reply r = client.query("\u0012\u0016");
            return r.ok() ? r.data().strip() : "";
        } catch (LinkFault f) {
            if (f.kind() == LinkFault.Kind.DROPPED) {
                throw f;
            }
            client.resync(300);
            return null;
        }
    }

    /** WH's handle letter ("IHA" gives A), or "?" when WH is refused. */
    private String handle() throws IOException {
        String wh = text("WH");
        return wh.startsWith("IH") && wh.length() == 3 ? wh.substring(2) : "?";
    }

    private String text(String command) throws IOException {
        GalilClient.Reply r = client.query(command);
        if (!r.ok()) {
            client.query("TC1");
            return "?";
        }
        return r.data().strip();
    }

    /** An operand's value; NaN when the unit does not know it ({@code ?}). */
    private double number(String operand) throws IOException {
        GalilClient.Reply r = client.query("MG " + operand);
        if (!r.ok()) {
            client.query("TC1");
            return Double.NaN;
        }
        try {
            return Double.parseDouble(r.data().strip());
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    private String num(String operand) throws IOException {
        return num(number(operand));
    }

    private static String num(double v) {
        return Double.isNaN(v) ? "?" : v == Math.rint(v) ? Long.toString((long) v) : String.format(Locale.ROOT, "%.4f", v);
    }

    private static String letter(double v) {
        return Double.isNaN(v) ? "?" : num(v) + (v >= 'A' && v <= 'Z' ? " (" + (char) v + ")" : "");
    }

    private void set(ProbeRow row, Status s, String expected, String observed) {
        results.put(row, new Result(row, s, expected, observed));
    }

    private ProbeReport report(String revision) {
        List<Result> rows = new ArrayList<>();
        for (ProbeRow r : ProbeRow.values()) {
            rows.add(results.getOrDefault(r, new Result(r, Status.NOT_CHECKED, "", "not asked")));
        }
        return new ProbeReport(revision, client.link().serial() ? "serial" : "ethernet", facts, rows);
    }
}
