package gcnc.galil;

/** Number printing for the galil dialect: integer counts, angles and volts with 4 decimals. */
public final class GalilNumbers {
    /** Largest magnitude of a Galil position, distance or radius: a signed 32-bit register. */
    public static final long MAX_COUNT = Integer.MAX_VALUE;

    private GalilNumbers() {
    }

    /** Nearest integer, halves away from zero (as the thesis rounds). */
    public static long round(double v) {
        double a = Math.abs(v);
        double f = Math.floor(a);
        long n = (long) f + (a - f >= 0.5 ? 1 : 0);
        return v < 0 ? -n : n;
    }

    /** Whether a count fits the controller's 32-bit registers. */
    public static boolean inRange(long counts) {
        return counts >= -MAX_COUNT && counts <= MAX_COUNT;
    }

    /** Degrees with at most 4 decimals, trailing zeros dropped: {@code 180}, {@code -8.2132}. */
    public static String angle(double degrees) {
        long tenThousandths = round(degrees * 10000);
        StringBuilder sb = new StringBuilder(12);
        if (tenThousandths < 0) {
            sb.append('-');
            tenThousandths = -tenThousandths;
        }
        sb.append(tenThousandths / 10000);
        long frac = tenThousandths % 10000;
        if (frac != 0) {
            int width = 4;
            while (frac % 10 == 0) {
                frac /= 10;
                width--;
            }
            String f = Long.toString(frac);
            sb.append('.');
            for (int i = f.length(); i < width; i++) {
                sb.append('0');
            }
            sb.append(f);
        }
        return sb.toString();
    }

    /** The value an {@link #angle} string stands for (what the controller reads). */
    public static double printedAngle(double degrees) {
        return round(degrees * 10000) / 10000.0;
    }

    /** Volts with exactly 4 decimals: {@code 3.0000}. */
    public static String volts(double v) {
        long t = round(v * 10000);
        StringBuilder sb = new StringBuilder(10);
        if (t < 0) {
            sb.append('-');
            t = -t;
        }
        sb.append(t / 10000).append('.');
        String f = Long.toString(t % 10000);
        for (int i = f.length(); i < 4; i++) {
            sb.append('0');
        }
        return sb.append(f).toString();
    }
}
