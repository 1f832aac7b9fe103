package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * Thesis §4.2.2 action 11: G09 (exact stop). The thesis toggled a program-wide flag nobody read;
 * gcnc takes G09 for its block only, as the Haas and Fanuc manuals do ("one-shot": the block's
 * move decelerates to rest and is checked in position before the next block starts): the checked
 * block says so ({@code CheckedBlock.stopAt}) and the planner ends its vector sequence there.
 * Emits nothing.
 */
public final class Sa11ExactStop implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        d.exactStop = true;
    }
}
