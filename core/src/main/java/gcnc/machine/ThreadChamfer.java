package gcnc.machine;

/**
 * The chamfered pull-out at the end of each pass of a G76 or G92 thread while Haas's M23 is in
 * force (docs/threading.md, docs/profiles.md): over the last {@code leads} leads of the pass's Z
 * travel the tool moves out in X at {@code angle} degrees to the Z axis, still geared to the
 * spindle. Haas Settings 95 (Thread Chamfer Size, in leads, 1.0 as shipped) and 96 (Thread
 * Chamfer Angle, 45 degrees as shipped); the profile keys {@code thread.chamfer_leads} and
 * {@code thread.chamfer_angle}.
 *
 * @param leads how many leads of the pass's Z travel the chamfer takes, 0 to {@link #MAX_LEADS};
 *              0 pulls straight out even under M23 (Haas Setting 95 = 0)
 * @param angle degrees between the chamfer and the Z axis, more than 0 and less than 90
 */
public record ThreadChamfer(double leads, double angle) {
    /** What a Haas lathe ships with: one lead at 45 degrees. */
    public static final ThreadChamfer HAAS = new ThreadChamfer(1.0, 45);
    /** The longest chamfer a profile may give, in leads. */
    public static final double MAX_LEADS = 100;

    public ThreadChamfer {
        if (!(leads >= 0 && leads <= MAX_LEADS) || !(angle > 0 && angle < 90)) {
            throw new IllegalArgumentException("thread chamfer " + leads + " leads at " + angle + " degrees");
        }
    }

    /** Whether M23 chamfers at all (a chamfer of zero leads is a straight pull-out). */
    public boolean cuts() {
        return leads > 0;
    }

    /** How far X moves out per unit of Z along the chamfer. */
    public double slope() {
        return Math.tan(Math.toRadians(angle));
    }
}
