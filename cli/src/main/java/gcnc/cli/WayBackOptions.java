package gcnc.cli;

import gcnc.machine.MachineProfile;
import gcnc.send.Operator;
import gcnc.send.WayBackRun;
import gcnc.sim.SimOptions;
import java.io.PrintWriter;
import picocli.CommandLine.Option;

/**
 * {@code gcnc run}'s way back (docs/run.md, "Resume"): {@code --way-back FEED} makes the moves E827
 * advises before a resume, at that feed, after the operator types the word; and how the word is taken.
 */
final class WayBackOptions {
    @Option(names = "--way-back", paramLabel = "FEED",
            description = "With --resume-at, when the axes are off the resume's path: first make the way back E827 advises"
                    + " (X away from the part, Z, X in), each leg at FEED program units per minute, checked by the"
                    + " simulator on the stock as cut; asks for the word '" + WayBackRun.WORD + "' first.")
    Double feed;

    @Option(names = "--confirm-from-stdin", description = "Take the way back's typed word from standard input even when"
            + " it is not a terminal (a script that has made sure the machine is clear).")
    boolean confirmFromStdin;

    /** How long the run waits for the word. */
    static final long WAIT_MS = 60_000;

    /** What the run needs for the way back, or null when none was asked for. */
    WayBackRun.Ask ask(Operator operator, PrintWriter prompt, MachineProfile onBlank, SimOptions sim) {
        if (feed == null) {
            return null;
        }
        return new WayBackRun.Ask(feed, () -> confirmed(operator, prompt), onBlank, sim);
    }

    /** Null when the operator typed the word; else why the way back does not move. */
    private String confirmed(Operator operator, PrintWriter prompt) {
        if (System.console() == null && !confirmFromStdin) {
            return "standard input is not a terminal: give --confirm-from-stdin to take the word from it";
        }
        prompt.print("The way back moves the axes in three legs at F"
                + java.math.BigDecimal.valueOf(feed).stripTrailingZeros().toPlainString() + ". Type '" + WayBackRun.WORD
                + "' to go on: ");
        prompt.flush();
        try {
            String w = operator.word(WAIT_MS);
            if (w == null) {
                return "nothing was typed in " + WAIT_MS / 1000 + " s";
            }
            return w.equals(WayBackRun.WORD) ? null : w.equals(Operator.END) ? "standard input ended" : "'" + w + "' was typed";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        }
    }
}
