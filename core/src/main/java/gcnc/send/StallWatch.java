package gcnc.send;

/**
 * A vector sequence that has begun and does not move (the profiler stopped taking segments): no
 * reply tells it, so the axes do. Fed the axes at every poll while the machine should be moving;
 * a hold, an override of 0, a dwell or a thread pass's wait for the spindle is no motion and
 * restarts the watch. Both forms watch their sequences through one of these.
 */
final class StallWatch {
    private final double seconds;
    private double[] still;
    private long since;

    /** @param seconds how long the axes may stand within a count before the run is stalled */
    StallWatch(double seconds) {
        this.seconds = seconds;
    }

    /** Whether the axes, now at {@code at}, have stood still too long while {@code moving}. */
    boolean stalled(double[] at, boolean moving) {
        if (!moving || still == null || Math.hypot(at[0] - still[0], at[1] - still[1]) > 1) {
            still = at;
            since = System.nanoTime();
            return false;
        }
        return (System.nanoTime() - since) / 1e9 > seconds;
    }

    /** The fault of a stall during {@code line}. */
    RunFault fault(int line) {
        return new RunFault(gcnc.diag.Code.E825_NOT_READY, line, true, "the axes stood still for " + Math.round(seconds)
                + " s during line " + line + " while its motion had not ended (the controller stopped feeding the sequence)");
    }
}
