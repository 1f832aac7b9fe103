package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;
import gcnc.tables.GFunction;

/**
 * Thesis §4.2.2 action 1: a modal G (groups 1 motion, 3 G90/G91, 5 and 10 feed mode, 6 units,
 * 12 work offset). One G per group per block: the thesis only checked group 1, gcnc checks all
 * (reading §12.19). Emits E016. Writes d.motionG, next.motion/incremental/feedPerRev/workOffset.
 */
public final class Sa01ModalG implements SyntaxAction {
    @Override
    public int number() {
        return 1;
    }

    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        int code = (int) NumberText.integer(w.number());
        GFunction f = d.functions.g(code);
        if (!d.claimG(f.group(), w, out)) {
            return;
        }
        switch (f.group()) {
            case 1 -> {
                d.motionG = code;
                d.next.motion = code;
            }
            case 3 -> d.next.incremental = code == 91;
            case 5, 10 -> d.next.feedPerRev = code == 95 || code == 99;
            case 12 -> d.next.workOffset = code;
            default -> {
                // group 6 (units) was applied to the whole block before any word (BlockDraft.units)
            }
        }
    }
}
