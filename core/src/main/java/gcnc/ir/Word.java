package gcnc.ir;

import gcnc.diag.Span;

/**
 * One word of a block as written: its letter (upper case), the exact text of its number (sign and
 * point included: "01" for G01, "1" for g1, "+5." for X+5.) and where it starts. A letter without
 * a number is error 6, reported by the parser, so a well-formed block never has an empty number.
 */
public record Word(Letter letter, String number, Span span, long code) {
    /** What {@link #code} is for a number that is not a plain unsigned integer ("-1", "1.", "+5"). */
    public static final long NOT_INTEGER = -1;

    /** A word as the parser reads it; its {@link #code} is worked out once, here. */
    public Word(Letter letter, String number, Span span) {
        this(letter, number, span, integer(number));
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
        return letter + number;
    }
}
