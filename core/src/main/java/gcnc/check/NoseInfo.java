package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Origin;
import gcnc.diag.Span;
import gcnc.machine.Nose;

/**
 * What the nose radius compensation ({@link NoseCompensation}) knows of a block besides the
 * block: the side after it, the nose in force, where it is (its place in its line and the file and
 * calls it was run from), and whether its moves are made with the compensation suspended. The
 * compensation holds a block until the next move shows its corner, so a finding about it is made
 * while a later block is checked, perhaps in another file: it is placed here, not where the
 * checker is.
 */
record NoseInfo(NoseSide side, Nose nose, int offset, Span at, Origin origin, NoseSuspend suspend) {
    NoseInfo(NoseSide side, Nose nose, int offset, Span at, Origin origin) {
        this(side, nose, offset, at, origin, NoseSuspend.NONE);
    }

    /** An error at this block. */
    Diagnostic error(Code code, Object... args) {
        return Diagnostic.error(code, at, args).in(origin);
    }
}
