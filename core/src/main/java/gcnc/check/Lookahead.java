package gcnc.check;

import gcnc.diag.Diagnostics;
import gcnc.ir.RawBlock;

/**
 * What a check may ask of the checker without changing it: a block followed from a given state,
 * checked but not committed ({@link Dry}), and whether a block starts a cycle. A class
 * given this instead of the checker itself can only look: whatever it finds, it returns.
 */
interface Lookahead {
    /** What {@code b} would do from {@code from}, its findings to {@code found}, or null after its errors. */
    Dry peek(RawBlock b, ModalState from, Diagnostics found);

    /** Whether the block starts or runs again a cycle (not a plain move). */
    boolean startsCycle(RawBlock b);

    /** The state a block refused for one word would leave were the word struck out ({@code fixed}), or null. */
    ModalState fixed(RawBlock fixed);

    /** Whether the C axis is engaged (after a C-axis option code): C is then an axis word, not a chamfer. */
    boolean cAxisOn();

    gcnc.machine.MachineProfile profile();

    /** The checker's coordinate frames (read here: only the checker writes a work offset, G10). */
    gcnc.check.geom.Coordinates coordinates();
}
