package gcnc.send;

import gcnc.diag.Code;
import java.io.IOException;

/**
 * A sequence fed while it runs whose vector buffer ran dry before its {@code VE} (E890), as both forms
 * report it: the controller "will stop motion instantly at the last vector. There will be no controlled
 * deceleration" (M13X8-74), so the sequence is not complete and is never taken for a normal end. The
 * stream form sees it when the host has not sent VE yet, the program form when thread 0 has not reached
 * it (docs/run.md, "Feeding the buffer").
 */
final class Starvation {
    private Starvation() {
    }

    /**
     * Stops the machine and says where the buffer ran dry: the last segment executed, named by {@code _CSS}
     * read after the end (the segment counter from zero while the sequence runs: after it, the manuals do not
     * say, so the count is taken as the segments run and clamped to those given), and its block.
     *
     * @param segments the compiled lines of the sequence's segments, in the controller's order
     */
    static RunFault fault(int[] segments, MachineLink c, Progress progress, Operator op) throws IOException {
        double[] at = c.position();
        int css = c.segment(); // the last segment executed
        int k = Math.max(1, Math.min(segments.length, css));
        progress.at(segments[k - 1], at, op);
        int code = c.stopCode();
        c.stopAll();
        // the manuals give no stop code for an underrun; 101 ("stopped at commanded vector") goes unsaid
        return new RunFault(Code.E890_BUFFER_STARVED, progress.executingLine(), true, k, progress.executingLine(),
                code == 101 ? "" : " (stop code " + code + ": " + MachineLink.stopReason(code) + ")");
    }
}
