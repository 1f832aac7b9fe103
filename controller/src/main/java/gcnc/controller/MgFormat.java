package gcnc.controller;

import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * MG: strings in quotes, numbers in Galil's format (a sign or a space, four decimals; {@code {Fn.m}} for n
 * digits and m decimals, for the items after it, or after one operand only as in {@code MG _LMS{F3.0}}),
 * {@code {N}} for no CR LF at the end; the items follow each other with nothing between. From the host it
 * is the reply; from a program it is unsolicited output.
 */
final class MgFormat {
    private MgFormat() {
    }

    private static final Pattern FORMAT = Pattern.compile("\\{F(\\d+)\\.(\\d+)\\}");
    private static final Pattern LOCAL_FORMAT = Pattern.compile("(.+?)\\{F(\\d+)\\.(\\d+)\\}");

    /** A number as MG writes it: Galil's default (sign or space, 4 decimals), or {@code {Fn.m}} (n digits, m decimals). */
    private static String formatted(double v, int digits, int decimals) {
        if (digits < 0) {
            return Statements.signed(String.format(Locale.ROOT, "%." + decimals + "f", Math.abs(v)), v);
        }
        String body = String.format(Locale.ROOT, "%0" + (digits + (decimals > 0 ? decimals + 1 : 0)) + "." + decimals + "f",
                Math.abs(v));
        return (v < 0 ? "-" : "") + body;
    }

    static String message(VirtualGalil c, String args, ProgramThread th) throws GalilException {
        StringBuilder b = new StringBuilder();
        boolean newline = true;
        int digits = -1;
        int decimals = 4;
        for (String item : Statements.split(args)) {
            String it = item.strip();
            Matcher f = FORMAT.matcher(it);
            if (it.startsWith("\"")) {
                if (it.length() < 2 || !it.endsWith("\"")) {
                    throw new GalilException(Tc.MISSING_QUOTE);
                }
                b.append(it, 1, it.length() - 1);
            } else if (it.equals("{N}")) {
                newline = false;
            } else if (f.matches()) {
                digits = Integer.parseInt(f.group(1));
                decimals = Integer.parseInt(f.group(2));
            } else if (!it.isEmpty()) {
                // a format right after an operand ({@code MG _LMS{F3.0}}) is for that operand only
                Matcher local = LOCAL_FORMAT.matcher(it);
                if (local.matches()) {
                    b.append(formatted(Expressions.eval(local.group(1), c), Integer.parseInt(local.group(2)),
                            Integer.parseInt(local.group(3))));
                } else {
                    b.append(formatted(Expressions.eval(it, c), digits, decimals));
                }
            }
        }
        String text = b + (newline ? "\r\n" : "");
        if (th != null) {
            c.unsolicited(text);
            return "";
        }
        return text;
    }
}
