package gcnc.sim;

import java.util.Optional;

/**
 * The stock header a program may open with, as EMCO controls write it: a comment on the first
 * line holding numbers, of which the first two are the blank's length and diameter in mm, e.g.
 * bishop's {@code (120.00 22.00 5.00 5.00)}. Further numbers are ignored. Anything else in the
 * comment (a word, a single number) means the line is not a stock header. A Denford / MIRAC
 * set-up line {@code [BILLET X50 Z100} on the first line is one too: X the diameter, Z the length,
 * in mm (docs/language.md, E261).
 */
public final class StockHeader {
    private StockHeader() {
    }

    /** The blank of a first line, with the stick-out taken from the profile's default. */
    public static Optional<StockSize> parse(String firstLine, double stickout) {
        String t = firstLine.strip();
        if (t.regionMatches(true, 0, "[BILLET", 0, 7)) {
            return billet(t.substring(7), stickout);
        }
        if (!t.startsWith("(") || !t.endsWith(")")) {
            return Optional.empty();
        }
        String[] parts = t.substring(1, t.length() - 1).trim().split("[\\s,]+");
        if (parts.length < 2) {
            return Optional.empty();
        }
        double[] v = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            try {
                v[i] = Double.parseDouble(parts[i]);
            } catch (NumberFormatException e) {
                return Optional.empty();
            }
            if (!(v[i] > 0) && i < 2) {
                return Optional.empty();
            }
        }
        // a blank shorter than the machine's usual stickout cannot stick out further than its length
        return Optional.of(new StockSize(v[1], v[0], Math.min(stickout, v[0])));
    }

    /** The words after {@code [BILLET}: X the diameter and Z the length, both more than zero, or nothing. */
    private static Optional<StockSize> billet(String words, double stickout) {
        double d = Double.NaN;
        double l = Double.NaN;
        for (String w : words.trim().split("[\\s,]+")) {
            if (w.length() < 2) {
                continue;
            }
            double v;
            try {
                v = Double.parseDouble(w.substring(1));
            } catch (NumberFormatException e) {
                return Optional.empty();
            }
            char c = Character.toUpperCase(w.charAt(0));
            if (c == 'X') {
                d = v;
            } else if (c == 'Z') {
                l = v;
            }
        }
        if (!(d > 0) || !(l > 0)) {
            return Optional.empty();
        }
        return Optional.of(new StockSize(d, l, Math.min(stickout, l)));
    }
}
