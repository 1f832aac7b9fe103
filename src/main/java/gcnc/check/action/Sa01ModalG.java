package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;

/**
 * Thesis §4.2.2 action 1: a modal G (motion, absolute/incremental, feed mode, units, work offset),
 * by what it does in the control (Fanuc B's G94 is the feed per minute of Fanuc A's G98). One G
 * per group per block: the thesis only checked group 1, gcnc checks all (reading §12.19).
 * Emits E016. Writes d.motionG, next.motion/incremental/feedPerRev/workOffset.
 */
public final class Sa01ModalG implements SyntaxAction {
    @Override
    public int number() {
        return 1;
    }

    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        GFunction f = d.functions.g(NumberText.integer(w.number()));
        if (!d.claimG(f.group(), w, out)) {
            return;
        }
        GRole r = f.role();
        switch (r) {
            case RAPID, LINEAR, ARC_CW, ARC_CCW -> {
                d.motionG = r.number();
                d.motionWord = w;
                d.next.motion = r.number();
            }
            case ABSOLUTE, INCREMENTAL -> d.next.incremental = r == GRole.INCREMENTAL;
            case FEED_PER_MINUTE, FEED_PER_REV -> d.next.feedPerRev = r == GRole.FEED_PER_REV;
            case WORK_1, WORK_2, WORK_3, WORK_4, WORK_5, WORK_6 -> d.next.workOffset = r.number();
            default -> {
                // units (G20/G21) were applied to the whole block before any word (BlockDraft.units)
            }
        }
    }
}
