package gcnc.flow;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Origin;
import gcnc.ir.RawBlock;
import java.util.BitSet;
import java.util.List;

/**
 * The blocks after the main program's end that a GOTO or an M97 can reach: the labels they name
 * (taken or not), and whether a block after the end is in a stretch from one of those labels to
 * the next end code (M30, M02, M99). Such a block is not "after the end" (E053); it is only
 * parsed, and a note says so (E138).
 */
final class ReachableAfterEnd {
    /** N numbers go up to 9999999 (the checker's E009 past it): a computed GOTO cannot grow the set past that. */
    private static final long MAX_LABEL = 10_000_000;

    private final FlowCodes codes;
    private final Diagnostics diags;
    /** The labels a GOTO (taken or not) or an M97 names: a stretch after M30 from one of them can be reached. */
    private final BitSet named = new BitSet();
    /** After the main program's end: in a stretch from a named label to the next end code (M30, M02, M99). */
    private boolean inReachable;

    ReachableAfterEnd(FlowCodes codes, Diagnostics diags) {
        this.codes = codes;
        this.diags = diags;
    }

    /** A label a GOTO or M97 names (a bit each: a loop of computed GOTOs holds no more than 1.25 MB). */
    void name(long label) {
        if (label >= 0 && label < MAX_LABEL) {
            named.set((int) label);
        }
    }

    /**
     * Whether a block after the main program's end can be reached from a GOTO or M97 that names its
     * label (or one before it in the same stretch, up to an end code), though this run did not go
     * there: such a block is not "after the end"; it is only parsed, and a note says so (E138).
     */
    boolean reachable(RawBlock b) {
        long label = MacroJumps.label(b);
        if (!inReachable && label >= 0 && label < MAX_LABEL && named.get((int) label)) {
            inReachable = true;
            diags.report(new Diagnostic(Code.E138_NEVER_CALLED, gcnc.diag.Severity.NOTE,
                    b.words().isEmpty() ? b.last() : b.words().get(0).span(), List.of("N" + label), Origin.PROGRAM));
        }
        if (!inReachable) {
            return false;
        }
        boolean ends = b.macro() != null ? codes.endsText(b.macro()) : (codes.scan(b.words()) & FlowCodes.END) != 0;
        if (ends) {
            inReachable = false;
        }
        return true;
    }
}
