package gcnc.check.geom;

/**
 * The number text of a word, read by hand (no regex, no exceptions on the hot path).
 * Grammar of the thesis's lexer (reading §3.2): {@code [+-] (digits [. digits*] | . digits)}.
 */
public final class NumberText {
    private static final double[] POW10 = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

    /** Returned by {@link #integer} for text that is not a plain unsigned integer. */
    public static final long NOT_INTEGER = gcnc.ir.Word.NOT_INTEGER;

    private NumberText() {
    }

    /** The value of a signed decimal number, or NaN when the text is not one. */
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

    /** An unsigned integer (digits only), {@link #NOT_INTEGER} otherwise; huge values saturate. */
    public static long integer(String s) {
        return gcnc.ir.Word.integer(s);
    }

    /** Whether a number was written with a decimal point (Fanuc: changes its meaning). */
    public static boolean hasPoint(String s) {
        return s.indexOf('.') >= 0;
    }

    /** A value as a person writes it: 0.042, 42, -1.5 (no exponent, no trailing zeros). */
    public static String plain(double v) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        return java.math.BigDecimal.valueOf(v).stripTrailingZeros().toPlainString();
    }

    /** The same, rounded half up to {@code decimals} digits after the point (exactly, at any size). */
    public static String plain(double v, int decimals) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        return java.math.BigDecimal.valueOf(v).setScale(decimals, java.math.RoundingMode.HALF_UP)
                .stripTrailingZeros().toPlainString();
    }
}
