package gcnc.sim;

/**
 * One of the slowest corners of a run (docs/galil.md, "The corner report"): where it is, how fast
 * the machine takes it, how fast the moves on either side go, and why it is not faster.
 *
 * @param file       the G-code file the corner's block is written in; null for the program itself
 * @param line       the line of the motion that ends at the corner
 * @param number     that block's N word as written ("110"), or null
 * @param speedMmMin the speed the machine takes the corner at (0: it stops), mm/min
 * @param feedMmMin  the faster of the two moves' own speeds, mm/min: what the corner costs
 * @param why        what sets the corner's speed
 * @param angleDeg   how far the path turns there, degrees (0 straight on, 180 straight back)
 * @param deviationMm the junction deviation the corner's speed comes from ({@code corner.deviation}), mm
 * @param radiusMm   {@link Why#ARC}: the arc's radius, mm; else NaN
 * @param lengthMm   {@link Why#ACCELERATION}: the short segment the machine slows over, mm; else NaN
 */
public record Corner(String file, int line, String number, double speedMmMin, double feedMmMin, Why why,
                     double angleDeg, double deviationMm, double radiusMm, double lengthMm) {
    /** What sets a corner's speed. */
    public enum Why {
        /** The junction-deviation speed of the angle the path turns by (Grbl's model). */
        JUNCTION,
        /** An arc's centripetal limit √(a·r), below the feed. */
        ARC,
        /** A segment too short to reach the corner's own speed, or to stop from it, with the machine's acceleration. */
        ACCELERATION,
        /** The path turns back: the machine stops (a sequence ends there). */
        REVERSAL;

        /** The name in the JSON report: the constant's, in lower case. */
        public String key() {
            return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
        }
    }
}
