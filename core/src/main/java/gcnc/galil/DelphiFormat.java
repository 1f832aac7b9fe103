package gcnc.galil;

/**
 * The thesis's number printing, Delphi's {@code FloatToStrF(v, ffFixed, precision, digits)}
 * (thesis-reading §7.3): one rounding, half away from zero, at the coarser of the last
 * significant digit and the last decimal; then exactly {@code digits} decimals. A value that
 * rounds to zero prints without a sign. More integer digits than {@code precision} would switch
 * Delphi to scientific notation; callers check {@link #fits} first.
 */
public final class DelphiFormat {
    private DelphiFormat() {
    }

    /** {@code FloatToStrF(v, ffFixed, 8, 0)}: VP, VS, CR radius, WT. */
    public static String fmt8(double v) {
        return fixed(v, 8, 0);
    }

    /** {@code FloatToStrF(v, ffFixed, 3, 4)}: the CR angles. */
    public static String fmt3x4(double v) {
        return fixed(v, 3, 4);
    }

    /** Whether {@code v} prints in fixed notation with this precision (no scientific switch). */
    public static boolean fits(double v, int precision) {
        return Math.abs(v) < Math.pow(10, precision);
    }

    public static String fixed(double v, int precision, int digits) {
        double a = Math.abs(v);
        int q = -digits;
        if (a != 0) {
            int e = (int) Math.floor(Math.log10(a)) + 1; // integer digits (may be <= 0)
            q = Math.max(e - precision, -digits);
        }
        long units = roundHalfUp(a, q);            // |v| in units of 10^q
        long scaledToDigits = units;
        for (int i = q; i > -digits; i--) {
            scaledToDigits *= 10;                  // re-express in units of 10^-digits
        }
        StringBuilder sb = new StringBuilder(16);
        if (v < 0 && scaledToDigits != 0) {
            sb.append('-');
        }
        long pow = 1;
        for (int i = 0; i < digits; i++) {
            pow *= 10;
        }
        sb.append(scaledToDigits / pow);
        if (digits > 0) {
            String frac = Long.toString(scaledToDigits % pow);
            sb.append('.');
            for (int i = frac.length(); i < digits; i++) {
                sb.append('0');
            }
            sb.append(frac);
        }
        return sb.toString();
    }

    /** round(a / 10^q) half up, a >= 0. */
    private static long roundHalfUp(double a, int q) {
        double scaled = q >= 0 ? a / Math.pow(10, q) : a * Math.pow(10, -q);
        double f = Math.floor(scaled);
        return (long) f + (scaled - f >= 0.5 ? 1 : 0);
    }
}
