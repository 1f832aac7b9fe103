package gcnc.check;

import gcnc.diag.Diagnostics;
import gcnc.ir.RawBlock;

/**
 * What a check may ask of the checker without changing it: a block followed from a given state,
 * checked but not committed ({@link Checker#peek}), and whether a block starts a cycle. A class
 * given this instead of the {@link Checker} can only look: whatever it finds, it returns.
 */
interface Lookahead {
    /** What {@code b} would do from {@code from}, its findings to {@code found}, or null after its errors. */
    Checker.Dry peek(RawBlock b, ModalState from, Diagnostics found);

    /** Whether the block starts or runs again a cycle (not a plain move). */
    boolean startsCycle(RawBlock b);
}
