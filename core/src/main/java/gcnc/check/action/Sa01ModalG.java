package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;

/**
 * Thesis §4.2.2 action 1: a modal G (motion, absolute/incremental, feed mode, units, work offset),
 * by what it does in the control (Fanuc B's G94 is the feed per minute of Fanuc A's G98). One G
 * per group per block: the thesis only checked group 1, gcnc checks all (reading §12.19).
 * Emits E016. Writes d.motionG, next.motion/incremental/feedPerRev/workOffset/returnToR.
 */
public final class Sa01ModalG implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        GFunction f = d.functions.g(w.code());
        if (!d.claimG(f.group(), w, out)) {
            return;
        }
        GRole r = f.role();
        if (r.motion()) {
            d.motionG = r.number();
            d.motionWord = w;
        }
        d.next.set(r); // units were applied to the whole block already (BlockDraft.units): the same value
    }
}
