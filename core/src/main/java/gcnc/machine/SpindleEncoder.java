package gcnc.machine;

/**
 * The encoder on the spindle that threading is geared to (docs/profiles.md, docs/threading.md):
 * how many counts it gives per spindle revolution (after quadrature), and the Galil channel whose
 * main encoder input reads it. A machine without one cannot cut a thread (E190).
 *
 * @param countsPerRev counts per spindle revolution, 4 or more
 * @param channel      Galil channel letter (A-H, X, Y, Z, W) whose main encoder is the spindle's
 */
public record SpindleEncoder(int countsPerRev, char channel) {
    /**
     * The largest gear ratio (slave counts per encoder count) the Galil controller's GR takes:
     * COMALL GR, "Min -127, Max 127, Resolution 1/65,536" (the DMC-40x0 user manual's ±127.9999 is
     * the older figure; gcnc takes the narrower). The checker, the backend and the replay use it.
     */
    public static final double MAX_RATIO = 127;
}
