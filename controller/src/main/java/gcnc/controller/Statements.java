package gcnc.controller;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Executes one Galil statement for the host (thread null) or for a program thread: the commands gcnc
 * writes go to {@link DmcCommands} (read by gcnc.dmc), program flow to {@link ThreadFlow}, MG to
 * {@link MgFormat}, the controller's own two-letter commands to {@link OwnCommands}; assignments to
 * variables, arrays and axis settings are here. The command set is what a
 * gcnc program (downloaded, or streamed with its resident program) and its sender use, listed in
 * docs/virtual-controller.md; anything else is {@code ?} with TC 1, never ignored.
 */
final class Statements {
    private final VirtualGalil c;

    final ThreadFlow flow;
    private final OwnCommands own;

    Statements(VirtualGalil c) {
        this.c = c;
        this.flow = new ThreadFlow(c, this);
        this.own = new OwnCommands(c, flow);
    }

    /** {@code name=expr}, {@code name[i]=expr}, {@code KPC=0}; group 1 the target, 2 the index, 3 the value. */
    private static final Pattern ASSIGNMENT = Pattern.compile("([A-Za-z][A-Za-z0-9]{0,7})\\s*(?:\\[(.*)\\])?\\s*=(.*)");

    /** Commands with a per-axis assignment form ({@code OFC=0}); the value is accepted and, but for OF, not used. */
    private static final java.util.Set<String> AXIS_ASSIGNABLE = java.util.Set.of("KP", "KI", "KD", "ER", "OF", "BL",
            "FL", "TL", "AC", "DC", "SP", "IT", "OE");

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
        return own.command(cmd, args, th);
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
                own.smooth(a, v);
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
