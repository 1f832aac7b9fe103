package gcnc.sim;

import gcnc.diag.Code;
import gcnc.dmc.Source;
import java.util.List;

/**
 * What the replayed program makes the machine do, as the {@link ReplayController} hands it on:
 * vector sequences when BGS starts them, dwells, tool changes, output changes, and the findings
 * about the commands; the {@link Simulator} turns them into machine state and checks. A finding,
 * and what may make one (a sequence, a tool change), comes with the {@link Source} of the DMC line
 * that caused it: its file and calls travel with its line.
 */
interface ReplayListener {
    void sequence(List<Segment> segments, double speed, Source at);

    void dwell(double seconds, int line);

    void tool(int n, Source at);

    void output(int bit, boolean on, int line);

    void spindleVolts(double volts, int line);

    void report(Code code, Source at, Object... args);

    /**
     * A command set on the way: after {@code AV trip}, while the last sequence runs. {@code around}:
     * the sources of the segments the path is on at that point (one, or two where it is at their
     * joint), for the check that it is where the program has it (docs/galil.md); {@code what}: the
     * command's own.
     */
    default void onTheWay(Source what, List<Source> around, long trip, String text) {
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
