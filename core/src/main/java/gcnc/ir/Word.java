package gcnc.ir;

import gcnc.diag.Span;

/**
 * One word of a block as written: its letter (upper case), the exact text of its number (sign and
 * point included: "01" for G01, "1" for g1, "+5." for X+5.) and where it starts. A letter without
 * a number is error 6, reported by the parser, so a well-formed block never has an empty number.
 * {@code comma} marks a word written with a comma before its letter: Haas {@code ,C} {@code ,R}
 * (G01 chamfer and corner rounding) and {@code ,A} (an angle), which are other words than C, R
 * and A (gcnc.check.CornerInsertion reads them before anything else sees the block).
 */
public record Word(Letter letter, String number, Span span, long code, boolean comma) {
    /** What {@link #code} is for a number that is not a plain unsigned integer ("-1", "1.", "+5"). */
    public static final long NOT_INTEGER = -1;

    /** A word as the parser reads it; its {@link #code} is worked out once, here. */
    public Word(Letter letter, String number, Span span) {
        this(letter, number, span, integer(number), false);
    }

    /** A word as the parser reads it, with its integer code given. */
    public Word(Letter letter, String number, Span span, long code) {
        this(letter, number, span, code, false);
    }

    /** A word written with a comma before its letter ({@code ,C1.}). */
    public static Word comma(Letter letter, String number, Span span) {
        return new Word(letter, number, span, integer(number), true);
    }

    private static final double[] POW10 = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

    /**
     * The value of a signed decimal number, or NaN when the text is not one: the thesis's lexer's
     * grammar (reading §3.2) {@code [+-] (digits [. digits*] | . digits)}, read by hand (no regex, no
     * exceptions on the hot path).
     */
    public static double decimal(String s) {
        int n = s.length();
        int i = 0;
        boolean negative = false;
        if (n > 0 && (s.charAt(0) == '+' || s.charAt(0) == '-')) {
            negative = s.charAt(0) == '-';
            i = 1;
        }
        long mantissa = 0;
        int digits = 0;
        int decimals = 0;
        boolean point = false;
        for (; i < n; i++) {
            char c = s.charAt(i);
            if (c >= '0' && c <= '9') {
                digits++;
                mantissa = mantissa * 10 + (c - '0');
                if (point) {
                    decimals++;
                }
                if (digits > 17) {
                    return slow(s);
                }
            } else if (c == '.' && !point) {
                point = true;
            } else {
                return Double.NaN;
            }
        }
        if (digits == 0) {
            return Double.NaN;
        }
        double v = digits <= 15 ? mantissa / POW10[decimals] : slow(s);
        return negative ? -v : v;
    }

    private static double slow(String s) {
        try {
            return Math.abs(Double.parseDouble(s)) * (s.charAt(0) == '-' ? -1 : 1);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    /**
     * The number as a plain unsigned integer (the code of a G or M word: "01" is 1), or
     * {@link #NOT_INTEGER}; saturates far beyond any code.
     */
    public static long integer(String s) {
        int n = s.length();
        if (n == 0) {
            return NOT_INTEGER;
        }
        long v = 0;
        for (int i = 0; i < n; i++) {
            char c = s.charAt(i);
            if (c < '0' || c > '9') {
                return NOT_INTEGER;
            }
            v = v > 100_000_000_000_000L ? Long.MAX_VALUE / 2 : v * 10 + (c - '0');
        }
        return v;
    }

    @Override
    public String toString() {
        return (comma ? "," : "") + letter + number;
    }
}
