package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * Thesis §4.2.2 action 11: G09 (exact stop). The thesis toggled a program-wide flag nobody read;
 * gcnc accepts G09 for its block only, and a Galil move already ends at rest. Emits nothing.
 */
public final class Sa11ExactStop implements SyntaxAction {
    @Override
    public int number() {
        return 11;
    }

    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        // Each block's motion already stops exactly (the backend waits for the move).
    }
}
