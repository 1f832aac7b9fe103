package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * One of the 15 syntax actions of thesis §4.2.2 (Table 10's action column; reading §4.1).
 * An action reads one word into the block draft, or reports the block's first error through
 * {@link BlockDraft#fail}.
 */
public interface SyntaxAction {
    /** The thesis's action number, 1..15. */
    int number();

    void apply(Word w, BlockDraft d, Diagnostics out);
}
