package gcnc.dmc;

/**
 * A decimal number exactly as a DMC line writes it: {@code unscaled / 10^scale}, so that a value
 * read from a line prints back to the same characters ({@code 3.0000} keeps its four zeros,
 * {@code -8.2132} is not a double near it). Counts are whole numbers ({@code scale} 0); volts,
 * angles and gear ratios carry decimals.
 */
public record Fixed(long unscaled, int scale) {
    /** At most 18 digits: the most a long holds whatever they are. */
    static final int MAX_DIGITS = 18;
    private static final long[] TENS = new long[MAX_DIGITS + 1];

    static {
        TENS[0] = 1;
        for (int i = 1; i < TENS.length; i++) {
            TENS[i] = TENS[i - 1] * 10;
        }
    }

    public Fixed {
        if (scale < 0 || scale > MAX_DIGITS) {
            throw new IllegalArgumentException("scale " + scale);
        }
    }

    /** A whole number. */
    public static Fixed of(long whole) {
        return new Fixed(whole, 0);
    }

    /**
     * {@code value} rounded half away from zero to four decimals with trailing zeros dropped: how
     * the galil dialect writes angles and millimetres ({@code 180}, {@code -8.2132}).
     */
    public static Fixed fourDecimals(double value) {
        long t = halfAway(value * 10000);
        int scale = 4;
        while (scale > 0 && t % 10 == 0) {
            t /= 10;
            scale--;
        }
        return new Fixed(t, scale);
    }

    /** {@code value} with exactly {@code scale} decimals, rounded half away from zero: volts ({@code 3.0000}). */
    public static Fixed exactly(double value, int scale) {
        return new Fixed(halfAway(value * TENS[scale]), scale);
    }

    /** Nearest integer, halves away from zero (as the thesis and the galil dialect round). */
    public static long halfAway(double v) {
        double a = Math.abs(v);
        double f = Math.floor(a);
        long n = (long) f + (a - f >= 0.5 ? 1 : 0);
        return v < 0 ? -n : n;
    }

    /**
     * The value, the double nearest the decimal (what {@link Double#parseDouble} gives): below 2^53
     * both the digits and the power of ten are exact doubles, so the one division rounds correctly.
     */
    public double value() {
        if (Math.abs(unscaled) < (1L << 53)) {
            return scale == 0 ? unscaled : unscaled / (double) TENS[scale];
        }
        return Double.parseDouble(toString());
    }

    public boolean isZero() {
        return unscaled == 0;
    }

    /** As a DMC line writes it: sign, digits, and {@code scale} decimals after a point. */
    @Override
    public String toString() {
        StringBuilder sb = new StringBuilder(20);
        appendTo(sb);
        return sb.toString();
    }

    void appendTo(StringBuilder sb) {
        long u = unscaled;
        if (u < 0) {
            sb.append('-');
            u = -u;
        }
        if (scale == 0) {
            sb.append(u);
            return;
        }
        sb.append(u / TENS[scale]).append('.');
        long f = u % TENS[scale];
        for (int d = scale - 1; d > 0 && f < TENS[d]; d--) {
            sb.append('0'); // the fraction's leading zeros: 5 at scale 4 is .0005
        }
        sb.append(f);
    }

    /** The number a DMC line writes as {@code text} ({@code 3.0000}, {@code -12}); IllegalArgumentException if none. */
    public static Fixed of(String text) {
        Fixed f = parse(text, 0, text.length(), false);
        if (f == null) {
            throw new IllegalArgumentException("not a DMC number: " + text);
        }
        return f;
    }

    /**
     * The number in {@code s[from, to)}, blanks around it allowed: {@code [+-]digits[.digits]}, at
     * most 18 digits; null when it is not one. {@code whole} refuses a point.
     */
    static Fixed parse(CharSequence s, int from, int to, boolean whole) {
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
        long digits = 0;
        int count = 0;
        int decimals = -1;
        for (; i < to; i++) {
            char c = s.charAt(i);
            if (c == '.' && decimals < 0 && !whole) {
                decimals = 0;
            } else if (c >= '0' && c <= '9') {
                if (++count > MAX_DIGITS) {
                    return null;
                }
                digits = digits * 10 + (c - '0');
                decimals += decimals >= 0 ? 1 : 0;
            } else {
                return null;
            }
        }
        if (count == 0) {
            return null;
        }
        return new Fixed(negative ? -digits : digits, Math.max(decimals, 0));
    }
}
