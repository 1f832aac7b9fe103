package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;

/**
 * Thesis end-of-block operation 5: only one function of the block may take its parameters, so a
 * one-shot G with parameters (G04, G28, G29, G50, G92) and a motion G cannot share a block.
 * (Two one-shots are already 17-20 in actions 5-9.) gcnc accepts a G00 beside G28, G29 or G53,
 * as real safe-start and homing lines have it ({@code G28 G00 U0 W0}): their move is a rapid
 * anyway, and the G00 stays the modal motion. Emits E035, at the second of the two G words (as
 * E016 is at the G that finds its group taken).
 */
public final class Eb05SingleParameterFunction implements BlockCheck {
    @Override
    public void run(BlockDraft d, Diagnostics out) {
        boolean rapidAlong = d.motionG == 0 && (d.oneShot == 28 || d.oneShot == 29 || d.oneShot == 53);
        if (d.oneShot != BlockDraft.NONE && d.motionG != BlockDraft.NONE && !rapidAlong) {
            Span second = d.motionWord.span().compareTo(d.oneShotWord.span()) > 0 ? d.motionWord.span()
                    : d.oneShotWord.span();
            d.fail(out, Code.E035_TWO_G_WITH_PARAMETERS, second, d.motionWord, d.oneShotWord);
        }
    }
}
