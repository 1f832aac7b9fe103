package gcnc.send;

import java.io.IOException;

/**
 * A program stop as the host follows it (docs/run.md, "Program stops"): thread 0 stands in the
 * compiled program's {@code #PSTOP} routine, the axes at rest. The stop is announced once
 * ({@link Event.ProgramStop}: the line and its comment), then the host waits for the operator's
 * continue (Enter; the studio's Start), which it passes on as {@code gstop=0}, or sees the machine's
 * cycle start button end the wait itself. The operator's stop and hold stay the caller's: the wait
 * returns when {@link Operator#stopped()}.
 */
final class ProgramStopWait {
    /** Whether the controller still waits in the stop routine (asked between the operator's waits). */
    @FunctionalInterface
    interface Waiting {
        boolean stillWaiting() throws IOException;
    }

    private ProgramStopWait() {
    }

    /**
     * The stop whose call is compiled line {@code call}: announced, then waited out. Enters pressed
     * before it began do not count.
     */
    static void await(MachineLink c, Progress progress, Operator op, int call, int pollMs, Waiting waiting)
            throws IOException, InterruptedException {
        int line = progress.program().sourceLine(call);
        BlockTable.Block b = progress.blocks().at(line);
        op.forgetEnters();
        progress.events().accept(new Event.ProgramStop(line, b == null ? null : b.number(),
                progress.blocks().comment(line)));
        while (!op.stopped()) {
            if (op.enterWithin(pollMs)) {
                c.require(gcnc.dmc.ProgramStop.FLAG + "=0");
                progress.events().accept(new Event.ProgramStopContinued(line, "operator"));
                return;
            }
            if (!waiting.stillWaiting()) {
                progress.events().accept(new Event.ProgramStopContinued(line, "cycle-start"));
                return;
            }
        }
    }
}
