package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.RawBlock;
import gcnc.machine.Control;

/**
 * The block delete switch ('/') as a checker follows the program, and from the first '/' block on the
 * checker that follows it in the other position, so that both variants of the program are checked.
 */
final class DeleteSwitch {
    /** The control has no switch: a '/' is a syntax error (E010). */
    private final boolean none;
    /** The switch as this checker follows the program: true = '/' blocks are skipped. */
    private final boolean skips;
    /** This is the other position's own switch: it makes no checker of its own. */
    private final boolean isOther;
    /** The checker in the other position, from the first '/' block on; null before (and in the other itself). */
    private Checker other;

    /** The switch as the control sets it. */
    DeleteSwitch(Control control) {
        this(control.blockDelete() == Control.BlockDelete.NONE, control.blockDelete() == Control.BlockDelete.ON, false);
    }

    private DeleteSwitch(boolean none, boolean skips, boolean isOther) {
        this.none = none;
        this.skips = skips;
        this.isOther = isOther;
    }

    /** The switch of the checker for the other position. */
    DeleteSwitch otherPosition() {
        return new DeleteSwitch(none, !skips, true);
    }

    /** A '/' block on a control without the switch: E010 at the '/', reported; the block is not checked. */
    boolean refused(RawBlock b, Span first, Diagnostics out) {
        if (b.blockDelete() == 0 || !none) {
            return false;
        }
        int at = b.deleteColumn() > 0 ? b.deleteColumn() : Math.max(1, first.column() - 1);
        out.error(Code.E010_SYNTAX, Span.of(b.line(), at), "'/'");
        return true;
    }

    /** Hands {@code b} to the other position's checker too, forked from {@code checker} at the first '/' block. */
    void follow(RawBlock b, Checker checker) {
        if (b.blockDelete() > 0 && other == null && !isOther) {
            other = checker.fork();
        }
        if (other != null) {
            other.check(b);
        }
    }

    /** {@code b} as this position runs it: null when it is skipped. */
    RawBlock running(RawBlock b) {
        if (b.blockDelete() == 0 || !skips) {
            return b;
        }
        // with the switch on a '/' block is skipped; a '/' in the middle runs the words before it
        return b.deleteColumn() > 0 ? b.beforeDelete() : null;
    }

    /** Ends the other position's checker and adds what only it found ({@link FindingReport#merge}). */
    void finish(int lastLine, FindingReport findings) {
        if (other != null) {
            other.finish(lastLine);
            findings.merge(other.out(), !skips);
        }
    }
}
