package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.RawBlock;

/**
 * The run's budget of blocks gone through again ({@link ProgramFlow#STEP_LIMIT}): counts them, and past it
 * reports the loop that last came round (E710; E149 when no loop runs) and lets each call finish its pass.
 */
final class StepBudget {
    private final long limit;
    private final Diagnostics diags;
    private final MacroJumps jumps;
    /** The programs being run: past the budget each finishes the pass it is in. */
    private final CallStack stack;
    /** Blocks of called programs, macro statements and main-program blocks run again, gone through so far. */
    private long steps;
    /** The budget was spent (E710 or E149): calls and jumps are no longer followed. */
    private boolean spent;

    StepBudget(long limit, Diagnostics diags, MacroJumps jumps, CallStack stack) {
        this.limit = limit;
        this.diags = diags;
        this.jumps = jumps;
        this.stack = stack;
    }

    /**
     * Counts a block against the budget: past it, the loop that last came round is E710 with its
     * passes (E149 when no loop runs: repeats of calls), and each call finishes the pass it is in,
     * and no more.
     */
    void step(RawBlock b) {
        if (spent || ++steps <= limit) {
            return;
        }
        spent = true;
        MacroJumps.Pass loop = jumps.last();
        if (loop != null) {
            diags.error(Code.E710_MACRO_BUDGET, loop.at(), loop.text(), loop.at().line(), loop.passes(), steps - 1);
        } else {
            diags.error(Code.E149_MACRO_ENDLESS_LOOP, b.last(), "the program", b.line(), steps - 1);
        }
        for (Frame running : stack) {
            running.repeats = 1; // each call finishes the pass it is in, and no more
        }
    }

    /** Whether the budget was spent: calls and jumps are then no longer followed. */
    boolean spent() {
        return spent;
    }

    /** Blocks gone through again so far. */
    long steps() {
        return steps;
    }
}
