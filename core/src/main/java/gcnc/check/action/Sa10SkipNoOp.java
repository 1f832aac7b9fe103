package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * Thesis §4.2.2 action 10: G31 (skip). The thesis accepts it and does nothing; so does gcnc:
 * the block's axis words belong to the modal motion (documented in docs/thesis.md). Emits nothing.
 */
public final class Sa10SkipNoOp implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        // G31 has no effect, as in the thesis.
    }
}
