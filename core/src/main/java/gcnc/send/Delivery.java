package gcnc.send;

import java.io.IOException;

/**
 * How a checked program reaches the controller once pre-flight passed.
 * {@link ProgramForm} downloads it whole (or block by block in step mode) and follows it;
 * {@link StreamForm} downloads the resident program and feeds the rest through the command line
 * (docs/galil.md, "Two forms"). Both get the same controller, progress and operator, and report
 * through them the same way.
 */
public interface Delivery {
    /** Its name in the events ({@code "program"}, {@code "stream"}). */
    String name();

    /**
     * Runs {@code piece} to its end; a stop (fault or operator) is a {@link RunFault} after the
     * machine was stopped; a failed link is a {@link LinkFault} (the caller stops what it still can).
     */
    void run(Download piece, MachineLink controller, Progress progress, Operator operator, boolean step, boolean dryRun)
            throws RunFault, IOException, InterruptedException;

    /** The program lines {@code piece} takes on the controller at once: checked against its memory in pre-flight. */
    int linesNeeded(Download piece, DmcProgram program, boolean step);
}
