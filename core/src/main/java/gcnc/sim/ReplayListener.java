package gcnc.sim;

import gcnc.diag.Code;
import java.util.List;

/**
 * What the replayed program makes the machine do, as the {@link ReplayController} hands it on:
 * vector sequences when BGS starts them, dwells, tool changes, output changes, and the findings
 * about the commands; the {@link Simulator} turns them into machine state and checks.
 */
interface ReplayListener {
    void sequence(List<Segment> segments, double speed, int line);

    void dwell(double seconds, int line);

    void tool(int n, int line);

    void output(int bit, boolean on, int line);

    void spindleVolts(double volts, int line);

    void report(Code code, int line, Object... args);

    /**
     * A command set on the way: after {@code AV trip}, while the last sequence runs. {@code around}:
     * the sources of the segments the path is on at that point (one, or two where it is at their
     * joint), for the check that it is where the program has it (docs/galil.md).
     */
    default void onTheWay(gcnc.dmc.Source what, List<gcnc.dmc.Source> around, long trip, String text, int line) {
    }

    /**
     * A program stop ({@code JS #PSTOP}: M00, M01 with the switch on): the machine waits for the
     * operator, at rest; the cycle time counts none of it.
     */
    default void programStop(int line) {
    }

    /** The sequence that ran ends here (AMS), for the reason the planner recorded (the corner report). */
    default void stopped(gcnc.plan.Stop why, int line) {
    }
}
