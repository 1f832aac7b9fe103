package gcnc.tables;

import java.util.OptionalDouble;
import java.util.regex.Pattern;

/**
 * The numbers table and profile files hold: decimal, optionally signed, with an optional exponent
 * ({@code 12}, {@code -0.5}, {@code .25}, {@code 1e6}). {@link Double#parseDouble} alone would also
 * take {@code NaN}, {@code Infinity}, hexadecimal and Java's {@code d}/{@code f} suffixes; a NaN
 * passes every range check ({@code NaN < min} is false) and an infinity breaks every later sum, so
 * neither may reach a machine model.
 */
public final class Decimal {
    private static final Pattern FORM = Pattern.compile("[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?");

    private Decimal() {
    }

    /** The finite value of {@code text}, or empty when it is not a decimal number (or overflows). */
    public static OptionalDouble parse(String text) {
        if (!FORM.matcher(text).matches()) {
            return OptionalDouble.empty();
        }
        double v = Double.parseDouble(text);
        return Double.isFinite(v) ? OptionalDouble.of(v) : OptionalDouble.empty();
    }
}
