package gcnc.controller;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * One of gcnc's commands as a program on the controller may write it, made literal for
 * {@link gcnc.dmc.DmcReader}: its arguments given as expressions ({@code WT dwms},
 * {@code VP p0[i],p1[i]}) evaluated, and a segment's speeds ({@code VP a,b <o >p}) taken off into
 * {@code o} and {@code p} (NaN when not given), which gcnc writes as numbers but a program may not.
 *
 * @param text the command with literal arguments, as the reader reads it
 * @param o    a segment's {@code <o} speed, counts/s, or NaN
 * @param p    a segment's {@code >p} end speed, counts/s, or NaN
 */
record Literal(String text, double o, double p) {
    /** The commands whose arguments may be expressions here: each is evaluated to a number. */
    private static final Set<String> NUMERIC = Set.of("VP", "CR", "VS", "VA", "VD", "WT", "SB", "CB", "OF", "AV");
    private static final Pattern NUMBER = Pattern.compile("[+-]?[0-9]+(\\.[0-9]+)?");

    /** {@code st} (a command {@link DmcCommands#handles} is true for) with its expressions evaluated, in scope {@code c}. */
    static Literal of(String st, Expressions.Scope c) throws GalilException {
        if (st.startsWith("TOOL=")) {
            String v = st.substring(5).strip();
            return new Literal(NUMBER.matcher(v).matches() ? st : "TOOL=" + whole(Expressions.eval(v, c)),
                    Double.NaN, Double.NaN);
        }
        String head = st.substring(0, 2);
        String args = st.substring(2).strip();
        if (!NUMERIC.contains(head)) {
            return new Literal(st, Double.NaN, Double.NaN);
        }
        double o = Double.NaN;
        double p = Double.NaN;
        if (head.equals("VP") || head.equals("CR")) {
            int lt = depthZero(args, '<');
            int gt = depthZero(args, '>');
            if (lt >= 0) {
                o = Expressions.eval(args.substring(lt + 1, gt > lt ? gt : args.length()), c);
            }
            if (gt >= 0) {
                p = Expressions.eval(args.substring(gt + 1, lt > gt ? lt : args.length()), c);
            }
            int cut = lt >= 0 ? (gt >= 0 ? Math.min(lt, gt) : lt) : gt;
            args = cut >= 0 ? args.substring(0, cut).strip() : args;
        }
        List<String> out = new ArrayList<>();
        for (String a : Statements.split(args)) {
            if (a.isEmpty() || NUMBER.matcher(a).matches()) {
                out.add(a);
            } else {
                double v = Expressions.eval(a, c);
                // VP, WT, SB and CB take whole numbers: Galil truncates a fraction
                out.add(head.equals("CR") || head.equals("OF") || head.startsWith("V") && !head.equals("VP")
                        ? decimal(v) : whole(v));
            }
        }
        String text = head + (out.isEmpty() || out.size() == 1 && out.get(0).isEmpty() ? "" : " " + String.join(",", out));
        return new Literal(text, o, p);
    }

    private static String whole(double v) {
        return Long.toString((long) v);
    }

    private static String decimal(double v) {
        String s = String.format(Locale.ROOT, "%.4f", v);
        return s.contains(".") ? s.replaceAll("0+$", "").replaceAll("\\.$", "") : s;
    }

    /** The first {@code want} outside parentheses and brackets, or -1. */
    static int depthZero(String s, char want) {
        int depth = 0;
        for (int i = 0; i < s.length(); i++) {
            char ch = s.charAt(i);
            if (ch == '(' || ch == '[') {
                depth++;
            } else if (ch == ')' || ch == ']') {
                depth--;
            } else if (ch == want && depth == 0) {
                return i;
            }
        }
        return -1;
    }
}
