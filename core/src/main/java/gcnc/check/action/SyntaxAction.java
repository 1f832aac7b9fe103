package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * One of the 15 syntax actions of thesis §4.2.2 (Table 10's action column; reading §4.1).
 * An action reads one word into the block draft, or reports the block's first error through
 * {@link BlockDraft#fail}. Its thesis number is the one in its class's name (Sa07...) and its
 * index in {@link SyntaxActions}, which alone pairs numbers and actions.
 */
public interface SyntaxAction {
    void apply(Word w, BlockDraft d, Diagnostics out);
}
