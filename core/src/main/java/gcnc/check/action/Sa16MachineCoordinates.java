package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * gcnc's action 16 (not in the thesis): G53, a rapid move to machine coordinates, for this block
 * only (Fanuc, Haas). A one-shot G that takes the block's X and Z; another one-shot in the block
 * is E035. A G00 may share the block (it sets the modal motion). Writes d.oneShot.
 */
public final class Sa16MachineCoordinates implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        if (d.oneShot != BlockDraft.NONE) {
            d.fail(out, Code.E035_TWO_G_WITH_PARAMETERS, w.span(), d.oneShotWord, w);
            return;
        }
        d.oneShot = 53;
        d.oneShotWord = w;
    }
}
