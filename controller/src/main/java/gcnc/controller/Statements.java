package gcnc.controller;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Executes one Galil statement for the host (thread null) or for a program thread: the commands gcnc
 * writes go to {@link DmcCommands} (read by gcnc.dmc), program flow to {@link ThreadFlow}, MG to
 * {@link MgFormat}; the protocol's own commands, variables and arrays are here. The command set is what a
 * gcnc program (downloaded, or streamed with its resident program) and its sender use, listed in
 * docs/virtual-controller.md; anything else is {@code ?} with TC 1, never ignored.
 */
final class Statements {
    private final VirtualGalil c;

    final ThreadFlow flow;

    Statements(VirtualGalil c) {
        this.c = c;
        this.flow = new ThreadFlow(c, this);
    }

    /** {@code name=expr}, {@code name[i]=expr}, {@code KPC=0}; group 1 the target, 2 the index, 3 the value. */
    private static final Pattern ASSIGNMENT = Pattern.compile("([A-Za-z][A-Za-z0-9]{0,7})\\s*(?:\\[(.*)\\])?\\s*=(.*)");

    /** Commands with a per-axis assignment form ({@code OFC=0}); the value is accepted and, but for OF, not used. */
    private static final java.util.Set<String> AXIS_ASSIGNABLE = java.util.Set.of("KP", "KI", "KD", "ER", "OF", "BL",
            "FL", "TL", "AC", "DC", "SP", "IT", "OE");

    /** Accepted and stored nowhere: servo tuning, soft limits (not modelled; docs say so). IT: {@link VirtualGalil#smooth}. */
    private static final java.util.Set<String> NO_EFFECT = java.util.Set.of("KP", "KI", "KD", "ER", "BL", "FL", "TL",
            "OE", "NO");

    String execute(String st, ProgramThread th) throws GalilException {
        if (st.isEmpty()) {
            return "";
        }
        Matcher m = ASSIGNMENT.matcher(st);
        boolean tool = st.startsWith("TOOL=") && st.length() > 5;
        if (!(m.matches() && !tool)) {
            // "Not Valid in terminal" / "Not Valid in program" (tables/galil_terminal.csv)
            CommandRules.check(st, th);
        }
        if (st.equals("\u0012\u0016")) {
            return c.model.revision + "\r\n";
        }
        if (st.charAt(0) == '#') {
            return ""; // a label line in a program (CommandRules refused it from the host)
        }
        if (word(st, "IF") || st.equals("ELSE") || st.equals("ENDIF")) {
            if (th == null) {
                throw new GalilException(Tc.ONLY_IN_PROGRAM);
            }
            flow.flow(st, th);
            return "";
        }
        if (m.matches() && !tool) {
            return assign(m.group(1), m.group(2), m.group(3).strip(), th);
        }
        if (tool || DmcCommands.handles(st)) {
            DmcCommands.execute(st, c, th);
            return "";
        }
        if (st.length() < 2 || !upper(st.charAt(0)) || !upper(st.charAt(1))) {
            throw new GalilException(Tc.UNRECOGNIZED);
        }
        String cmd = st.substring(0, 2);
        String args = st.substring(2).strip();
        return command(cmd, args, th);
    }

    private static boolean upper(char ch) {
        return ch >= 'A' && ch <= 'Z';
    }

    static boolean word(String st, String w) {
        return st.startsWith(w) && (st.length() == w.length() || st.charAt(w.length()) == ' '
                || st.charAt(w.length()) == '(');
    }

    private double eval(String e) throws GalilException {
        return Expressions.eval(e, c);
    }

    private String assign(String name, String index, String value, ProgramThread th) throws GalilException {
        if (index == null && name.length() == 3 && AXIS_ASSIGNABLE.contains(name.substring(0, 2))
                && c.axis(name.charAt(2)) >= 0) {
            int a = c.axis(name.charAt(2));
            double v = eval(value);
            if (name.startsWith("OF")) {
                if (Math.abs(v) > 9.9982) {
                    throw new GalilException(Tc.RANGE);
                }
                c.offsets[a] = v;
            } else if (name.startsWith("IT")) {
                c.smooth(a, v);
            }
            return "";
        }
        if (index != null) {
            double[] arr = c.arrays.get(name);
            if (arr == null) {
                throw new GalilException(Tc.BAD_FUNCTION);
            }
            double i = eval(index);
            if (i < 0 || i != Math.rint(i) || i >= arr.length) {
                throw new GalilException(Tc.BAD_INDEX);
            }
            if (value.isEmpty()) {
                return number(arr[(int) i]) + "\r\n";
            }
            arr[(int) i] = eval(value);
            return "";
        }
        if (value.isEmpty()) {
            return number(c.variable(name)) + "\r\n";
        }
        c.assign(name, eval(value));
        return "";
    }

    /**
     * Galil's number format for MG and interrogations: a sign or a space, then 4 decimals. The sign is
     * the rounded number's: COMALL's {@code MG @SIN[360]} prints {@code 0.0000}, not {@code -0.0000}.
     */
    static String number(double v) {
        return signed(String.format(Locale.ROOT, "%.4f", Math.abs(v)), v);
    }

    /** {@code digits} (the magnitude as printed) after a minus, or after a space when it prints as zero or more. */
    static String signed(String digits, double v) {
        boolean zero = digits.chars().noneMatch(ch -> ch >= '1' && ch <= '9');
        return (v < 0 && !zero ? "-" : " ") + digits;
    }

    private String command(String cmd, String args, ProgramThread th) throws GalilException {
        VectorMotion mo = c.motion;
        switch (cmd) {
            case "IT": {
                // IT n,n,...: one value per axis in order, an empty place leaves that axis as it is
                String[] places = args.split(",", -1);
                for (int i = 0; i < places.length; i++) {
                    if (!places[i].isBlank()) {
                        c.smooth(i, eval(places[i].strip()));
                    }
                }
                return "";
            }
            case "TC": {
                double n = args.isEmpty() ? 0 : eval(args);
                Tc e = c.lastError;
                c.lastError = Tc.NONE;
                return (n == 1 && e != Tc.NONE ? e.code + " " + e.text : String.valueOf(e.code)) + "\r\n";
            }
            case "MG":
                return MgFormat.message(c, args, th);
            case "CW": {
                List<String> a = split(args);
                double n = eval(a.get(0));
                if (n != 1 && n != 2) {
                    throw new GalilException(Tc.RANGE);
                }
                c.cw = (int) n;
                return "";
            }
            case "CF":
                return configureUnsolicited(args, th);
            case "EO":
                return echo(args, th);
            case "WH":
                if (th != null) {
                    throw new GalilException(Tc.NOT_IN_PROGRAM); // COMALL WH: Not Valid in program
                }
                return (c.port == 'S' ? "SERIAL" : "IH" + c.port) + "\r\n";
            case "XQ":
                return flow.execute(args);
            case "HX":
                return flow.halt(args);
            case "UL":
                if (th != null) {
                    throw new GalilException(Tc.NOT_IN_PROGRAM);
                }
                return c.program.upload() + "\\";
            case "DL":
                throw new GalilException(th != null ? Tc.NOT_IN_PROGRAM : Tc.UNRECOGNIZED);
            case "ZS":
                // zero the subroutine stack (COMALL ZS): an error routine's EN then ends the thread
                // instead of returning into the motion it interrupted (gcnc's #FAULT does this)
                onlyInProgram(th);
                th.stack.clear();
                return "";
            case "RE":
                onlyInProgram(th); // COMALL RE: "Not Valid in terminal"
                th.back();
                return "";
            case "JP":
            case "JS":
                return flow.jump(cmd, args, th);
            case "MO":
                for (int a : axesOrAll(args)) {
                    c.servo[a] = false;
                    if (a == mo.axis1 || a == mo.axis2) {
                        mo.abort(0, c.time());
                    }
                }
                c.gearing.stop();
                return "";
            case "CA":
                if (!args.equals("S")) {
                    throw new GalilException(Tc.S_OPERAND);
                }
                return "";
            case "VR":
                mo.vr = range(eval(args), 0, 10);
                mo.changed();
                return "";
            case "MC":
                onlyInProgram(th);
                th.waitingFor = ThreadWaits.sequenceStill(mo);
                return "";
            case "AI": {
                onlyInProgram(th);
                int n = (int) eval(args);
                int bit = Math.abs(n);
                c.io("IN", bit);
                th.waitingFor = ThreadWaits.input(c, bit, n > 0);
                return "";
            }
            case "ST":
                if (args.isEmpty()) {
                    for (ProgramThread t : c.threads) {
                        if (t != th) {
                            t.halt();
                        }
                    }
                }
                mo.stop(4);
                c.gearing.stop(); // gearing off, a settling move ends where it is (assumed: docs/virtual-controller.md)
                return "";
            case "AB": {
                double n = args.isEmpty() ? 0 : eval(args);
                if (n != 1) {
                    for (ProgramThread t : c.threads) {
                        if (t != th) {
                            t.halt();
                        }
                    }
                }
                mo.abort(7, c.time());
                c.gearing.stop();
                return "";
            }
            case "CS":
                if (!args.isEmpty() && !args.equals("S")) {
                    throw new GalilException(Tc.S_OPERAND);
                }
                mo.clear();
                return "";
            case "DP":
                return define(args);
            case "TP":
            case "RP":
                return tell(args);
            case "OB": {
                List<String> a = split(args);
                if (a.size() != 2) {
                    throw new GalilException(Tc.OPERAND);
                }
                int n = (int) range(eval(a.get(0)), 1, c.model.outputs);
                boolean on = eval(a.get(1)) != 0;
                c.setOutput(n, on);
                return "";
            }
            case "LM":
                if (args.equals("?")) {
                    return mo.free() + "\r\n";
                }
                throw new GalilException(Tc.UNRECOGNIZED); // LM/LI linear mode is not modelled
            case "DM":
                return dimension(args);
            case "RS":
                if (th != null) {
                    throw new GalilException(Tc.NOT_IN_PROGRAM); // COMALL RS: "Not Valid in program"
                }
                return reset();
            default:
                if (NO_EFFECT.contains(cmd)) {
                    return "";
                }
                throw new GalilException(Tc.UNRECOGNIZED);
        }
    }

    /**
     * CF: where unsolicited messages go (COMALL CF): {@code CF S} the main serial port (the power-up
     * value), {@code CF A}..{@code CF H} an Ethernet handle, {@code CF I} the port the command came in on
     * ("Not valid in program"). The reference offers {@code T} for an aux serial port the virtual
     * controller does not have.
     */
    private String configureUnsolicited(String args, ProgramThread th) throws GalilException {
        String a = args.strip();
        if (a.equals("I")) {
            if (th != null) {
                throw new GalilException(Tc.NOT_IN_PROGRAM);
            }
            c.cf = c.port;
        } else if (a.equals("S") || a.length() == 1 && a.charAt(0) >= 'A' && a.charAt(0) <= 'H') {
            c.cf = a.charAt(0);
        } else {
            throw new GalilException(Tc.OPERAND);
        }
        return "";
    }

    /**
     * EO: the serial port's echo (COMALL EO: "defaulted to EO1", "accepted over the serial port only";
     * "The ethernet port will not echo commands"). From an Ethernet handle it is refused: the reference
     * does not say with which code, TC 1 is assumed (docs/virtual-controller.md).
     */
    private String echo(String args, ProgramThread th) throws GalilException {
        if (th == null && c.port != 'S') {
            throw new GalilException(Tc.UNRECOGNIZED);
        }
        double n = eval(args.isEmpty() ? "1" : args);
        if (n != 0 && n != 1) {
            throw new GalilException(Tc.RANGE);
        }
        c.echo = n == 1;
        return "";
    }

    static void onlyInProgram(ProgramThread th) throws GalilException {
        if (th == null) {
            throw new GalilException(Tc.ONLY_IN_PROGRAM);
        }
    }

    static double range(double v, double min, double max) throws GalilException {
        if (Double.isNaN(v) || v < min || v > max) {
            throw new GalilException(Tc.RANGE);
        }
        return v;
    }

    private List<Integer> axesOrAll(String args) throws GalilException {
        if (args.isEmpty()) {
            List<Integer> all = new ArrayList<>();
            for (int i = 0; i < c.model.axes; i++) {
                all.add(i);
            }
            return all;
        }
        return c.axes(args);
    }

    private String define(String args) throws GalilException {
        if (c.motion.running()) {
            throw new GalilException(Tc.WHILE_RUNNING);
        }
        List<String> a = split(args);
        if (a.size() > c.model.axes) {
            throw new GalilException(Tc.OPERAND);
        }
        for (int i = 0; i < a.size(); i++) {
            if (!a.get(i).isEmpty()) {
                c.motion.position[i] = (long) eval(a.get(i));
            }
        }
        c.motion.clear();
        return "";
    }

    private String tell(String args) throws GalilException {
        List<Integer> axes = axesOrAll(args);
        StringBuilder b = new StringBuilder();
        for (int a : axes) {
            b.append(b.length() == 0 ? "" : ", ").append((long) Math.rint(c.motion.position[a]));
        }
        return b + "\r\n";
    }

    /** DM name[n], ...; {@code DM ?} answers the array elements still free (a sender's pre-flight). */
    private String dimension(String args) throws GalilException {
        if (args.equals("?")) {
            return (int) c.operand("DM") + "\r\n";
        }
        for (String d : split(args)) {
            Matcher m = Pattern.compile("([A-Za-z][A-Za-z0-9]{0,7})\\[(.+)\\]").matcher(d);
            if (!m.matches()) {
                throw new GalilException(Tc.OPERAND);
            }
            int n = (int) range(eval(m.group(2)), 1, c.model.arrayElements);
            int used = 0;
            for (double[] arr : c.arrays.values()) {
                used += arr.length;
            }
            double[] old = c.arrays.get(m.group(1));
            if (used - (old == null ? 0 : old.length) + n > c.model.arrayElements) {
                throw new GalilException(Tc.ARRAY_SPACE);
            }
            if (old == null && c.arrays.size() >= Model.ARRAYS) {
                throw new GalilException(Tc.TOO_MANY_VARIABLES);
            }
            c.arrays.put(m.group(1), new double[n]);
        }
        return "";
    }

    /** RS: motion, threads, variables, arrays, outputs and errors back to power-up; the program stays; #AUTO runs. */
    private String reset() {
        for (ProgramThread t : c.threads) {
            t.halt();
        }
        c.motion.abort(7, c.time());
        c.gearing.stop();
        c.variables.clear();
        c.arrays.clear();
        c.outputs = 0;
        java.util.Arrays.fill(c.offsets, 0);
        java.util.Arrays.fill(c.servo, false);
        c.lastError = Tc.NONE;
        c.cw = 2;
        c.cf = 'S';
        c.echo = c.model.galil.serialEcho();
        java.util.Arrays.fill(c.smoothing, 1);
        int auto = c.program.label("AUTO");
        if (auto >= 0) {
            c.threads[0].start(auto);
        }
        return "";
    }

    // ---- argument lists ----

    /** The arguments split at commas outside quotes, parentheses and brackets (blanks kept inside). */
    static List<String> split(String args) {
        List<String> out = new ArrayList<>();
        int depth = 0;
        boolean quoted = false;
        int from = 0;
        for (int i = 0; i < args.length(); i++) {
            char ch = args.charAt(i);
            if (ch == '"') {
                quoted = !quoted;
            } else if (!quoted && (ch == '(' || ch == '[' || ch == '{')) {
                depth++;
            } else if (!quoted && (ch == ')' || ch == ']' || ch == '}')) {
                depth--;
            } else if (!quoted && depth == 0 && ch == ',') {
                out.add(args.substring(from, i).strip());
                from = i + 1;
            }
        }
        out.add(args.substring(from).strip());
        return out;
    }
}
