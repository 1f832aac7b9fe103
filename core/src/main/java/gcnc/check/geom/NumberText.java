package gcnc.check.geom;

/**
 * The number text of a word, read by hand (no regex, no exceptions on the hot path).
 * Grammar of the thesis's lexer (reading §3.2): {@code [+-] (digits [. digits*] | . digits)}.
 */
public final class NumberText {
    /** Returned by {@link #integer} for text that is not a plain unsigned integer. */
    public static final long NOT_INTEGER = gcnc.ir.Word.NOT_INTEGER;

    private NumberText() {
    }

    /** The value of a signed decimal number, or NaN when the text is not one ({@link gcnc.ir.Word#decimal}). */
    public static double decimal(String s) {
        return gcnc.ir.Word.decimal(s);
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
