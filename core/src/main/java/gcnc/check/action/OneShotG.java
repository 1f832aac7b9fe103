package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * The shape of thesis actions 5-9: a one-shot G that takes the block's parameters (thesis GWP).
 * Only one per block; a second reports the code of the one arriving (17 G04, 18 G28, 19 G29,
 * 20 G50/G92). These actions do not touch the modal G state.
 */
abstract class OneShotG implements SyntaxAction {
    private final int g;
    private final Code conflict;

    OneShotG(int g, Code conflict) {
        this.g = g;
        this.conflict = conflict;
    }

    @Override
    public final void apply(Word w, BlockDraft d, Diagnostics out) {
        if (d.oneShot != BlockDraft.NONE) {
            d.fail(out, conflict, w.span());
            return;
        }
        d.oneShot = g;
        d.oneShotWord = w;
    }
}
