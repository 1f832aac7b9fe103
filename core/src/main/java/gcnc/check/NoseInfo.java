package gcnc.check;

import gcnc.diag.Span;
import gcnc.machine.Nose;

/**
 * What the nose radius compensation ({@link NoseCompensation}) knows of a block besides the
 * block: the side after it, the nose in force, where it is, and whether its moves are made with
 * the compensation suspended.
 */
record NoseInfo(NoseSide side, Nose nose, int offset, Span at, NoseSuspend suspend) {
    NoseInfo(NoseSide side, Nose nose, int offset, Span at) {
        this(side, nose, offset, at, NoseSuspend.NONE);
    }
}
