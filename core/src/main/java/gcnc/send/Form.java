package gcnc.send;

import java.io.IOException;

/**
 * How a checked program reaches the controller once pre-flight passed.
 * {@link ProgramForm} downloads it whole (or block by block in step mode) and follows it; the
 * stream form (a resident program plus a segment stream fed into the vector buffer with flow
 * control, galil-controller.md §6.3-6.4) implements this too once the compiler plans blended
 * groups: it gets the same controller, progress and operator, and reports through them the same way.
 */
public interface Form {
    /** Its name in the events ({@code "program"}, {@code "stream"}). */
    String name();

    /**
     * Runs {@code piece} to its end; a stop (fault or operator) is a {@link RunFault} after the
     * machine was stopped; a failed link is a {@link LinkFault} (the caller stops what it still can).
     */
    void run(Piece piece, Controller controller, Progress progress, Operator operator, boolean step, boolean dryRun)
            throws RunFault, IOException, InterruptedException;
}
