package gcnc.check.cycle;

/**
 * What a Fanuc first block ({@code G71 U R}, {@code G72 W R}, {@code G73 U W R}) leaves in force
 * for the next cycles of its kind, as the control's parameters it sets do; NaN where it said
 * nothing.
 *
 * @param depth     G71/G72 depth of cut, program units (a radius for G71)
 * @param retractMm G71/G72 retract, mm
 * @param reliefX   G73 relief along X, program units, a radius
 * @param reliefZ   G73 relief along Z, program units
 * @param passes    G73 number of passes
 */
public record FirstBlock(double depth, double retractMm, double reliefX, double reliefZ, double passes) {
    /** Nothing said yet. */
    public static final FirstBlock NONE = new FirstBlock(Double.NaN, Double.NaN, Double.NaN, Double.NaN, Double.NaN);

    /** This one with what a later first block says over it. */
    public FirstBlock then(FirstBlock later) {
        return new FirstBlock(pick(later.depth, depth), pick(later.retractMm, retractMm), pick(later.reliefX, reliefX),
                pick(later.reliefZ, reliefZ), pick(later.passes, passes));
    }

    private static double pick(double later, double earlier) {
        return Double.isNaN(later) ? earlier : later;
    }
}
