package gcnc.galil;

import gcnc.dmc.Fixed;

/**
 * Number printing for the galil dialect: integer counts, angles and volts with 4 decimals, as
 * {@link Fixed} holds them in a command (the messages spell a number as the DMC line does).
 */
public final class GalilNumbers {
    /** Largest magnitude of a Galil position, distance or radius: a signed 32-bit register. */
    public static final long MAX_COUNT = Integer.MAX_VALUE;

    private GalilNumbers() {
    }

    /** Nearest integer, halves away from zero (as the thesis rounds). */
    public static long round(double v) {
        return Fixed.halfAway(v);
    }

    /** Whether a count fits the controller's 32-bit registers. */
    public static boolean inRange(long counts) {
        return counts >= -MAX_COUNT && counts <= MAX_COUNT;
    }

    /** Degrees with at most 4 decimals, trailing zeros dropped: {@code 180}, {@code -8.2132}. */
    public static String angle(double degrees) {
        return Fixed.fourDecimals(degrees).toString();
    }

    /** The value an {@link #angle} string stands for (what the controller reads). */
    public static double printedAngle(double degrees) {
        return round(degrees * 10000) / 10000.0;
    }

    /** Volts with exactly 4 decimals: {@code 3.0000}. */
    public static String volts(double v) {
        return Fixed.exactly(v, 4).toString();
    }
}
