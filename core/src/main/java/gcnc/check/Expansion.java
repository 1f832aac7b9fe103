package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.ir.Word;

/**
 * The warning for a cycle block that expands into far more motion than its text suggests. A Haas
 * {@code G75 ... I01} reads I01 as 0.0001 in (a value without its decimal point is in the smallest
 * unit), so an 11-line program makes thousands of pecks: tens of thousands of DMC lines and a
 * replay that takes minutes. The control would run it (no alarm), so it is a warning, not an
 * error; it is given from the pecks the cycle's plan counts, before a single move is expanded.
 * Past {@link Grooving#MAX_PECKS} the cycle is E167 instead.
 */
final class Expansion {
    /**
     * More pecks than this from one block is suspicious: a 1 in deep groove at 0.001 in per peck,
     * ten times over; real programs peck a few dozen to a few hundred times per cycle.
     */
    static final long MANY_PECKS = 1000;

    private Expansion() {
    }

    /** E330 at {@code word} when {@code pecks} is over {@link #MANY_PECKS}. */
    static void warnIfMany(CycleHost host, String label, Word word, long pecks) {
        if (pecks > MANY_PECKS) {
            host.out().report(Diagnostic.warning(Code.E330_CYCLE_MANY_PECKS, word.span(), label, word, pecks,
                    MANY_PECKS));
        }
    }
}
