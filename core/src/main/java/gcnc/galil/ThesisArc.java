package gcnc.galil;

import gcnc.ir.Motion;

/**
 * The thesis's arc arithmetic, {@code GenCirInterp} (seed L4351-4455) and the CR radius of
 * {@code GenOutputRecord} (L4043-4064), reproduced with its bugs (thesis-reading §8): the radius
 * printed is the chord, the start angle is about the machine origin, the sweep is the chord's
 * direction, and the I/K case intersects a line whose slope is an angle. Positions, angles and
 * the intersection are kept in float as the thesis declares them.
 *
 * <p>Where the thesis divides by zero (start on x = 0, or an arc with no X travel), C++Builder
 * raised an unhandled FPU exception. gcnc takes the limit of the thesis's own formula instead:
 * atan(+-inf) = +-90 degrees, and an angle of 0 for 0/0.
 */
final class ThesisArc {
    /** What to print: one CR, or (two-piece) a CR to (xm, zm) followed by a VP to the end. */
    record Result(double radius, float theta, float delta, boolean twoPiece, float xm, float zm) {
    }

    private static final double PI = 3.14159265358979; // the thesis's constant

    private ThesisArc() {
    }

    /** The output of an arc, or null when the I/K formula has no real solution. */
    static Result of(Motion.Arc a) {
        float x1 = (float) a.from().x();
        float z1 = (float) a.from().z();
        float incX = (float) (a.to().x() - a.from().x());
        float incZ = (float) (a.to().z() - a.from().z());
        float x2 = x1 + incX;
        float z2 = z1 + incZ;
        boolean g03 = !a.clockwise();
        double chord = Math.sqrt(incX * incX + incZ * incZ);
        Motion.ArcWords w = a.words();
        if (w.r() != null) {
            double delta = degrees(z2 - z1, x2 - x1);
            if (w.r() < 0) {
                delta = 360 - delta;
            }
            return single(chord, degrees(z1, x1), g03 ? -delta : delta);
        }
        float i = w.i() == null ? 0 : w.i().floatValue();
        float k = w.k() == null ? 0 : w.k().floatValue();
        float r2 = i * i + k * k;
        float xc = x1 + i;
        float zc = z1 + k;
        float dist2 = (float) Math.sqrt((z2 - zc) * (z2 - zc) + (x2 - xc) * (x2 - xc));
        if ((float) Math.sqrt(r2) == dist2) {
            double delta = degrees(z2 - z1, x2 - x1);
            return single(chord, degrees(z1, x1), g03 ? -delta : delta);
        }
        float m = (float) Math.atan((z2 - zc) / (x2 - xc)); // the angle used as a slope (thesis bug)
        float b0 = z2 - m * x2;
        float qa = m * m + 1;
        float qb = 2 * m * b0 - 2 * xc - 2 * m * zc;
        float qc = zc * zc + b0 * b0 - 2 * zc * b0 - r2; // xc*xc is missing in the thesis too (L4414)
        double disc = (double) qb * qb - 4.0 * qa * qc;
        if (!(disc >= 0)) {
            return null;
        }
        float xf = (float) ((-qb + Math.sqrt(disc)) / (2 * qa));
        if (!(xf >= xc && xf <= x2)) {
            xf = (float) ((-qb - Math.sqrt(disc)) / (2 * qa));
        }
        float zf = m * xf + b0;
        double delta = degrees(zf - z1, xf - x1);
        float theta = (float) degrees(z1, x1);
        float d = (float) (g03 ? -delta : delta);
        if (xf == 0 && zf == 0) {
            return single(chord, theta, d); // the thesis tests (xm, zm) != (0, 0) for two pieces
        }
        double radius = Math.sqrt((double) (xf - x1) * (xf - x1) + (double) (zf - z1) * (zf - z1));
        return new Result(radius, theta, d, true, xf, zf);
    }

    private static Result single(double chord, double theta, double delta) {
        return new Result(chord, (float) theta, (float) delta, false, 0, 0);
    }

    /** atan(num/den) in degrees with the thesis's pi; the limits where it divided by zero. */
    static double degrees(double num, double den) {
        if (den == 0) {
            return num == 0 ? 0 : (num > 0 ? 90 : -90);
        }
        return Math.atan(num / den) * 180 / PI;
    }
}
