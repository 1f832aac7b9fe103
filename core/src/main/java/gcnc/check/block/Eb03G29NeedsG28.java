package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;

/**
 * Thesis end-of-block operation 3: G29 needs a G28 earlier in the program (not necessarily the
 * previous block). The thesis's fall-through made every G29 fail (§12.7). Emits E042, at the G29.
 */
public final class Eb03G29NeedsG28 implements BlockCheck {
    @Override
    public void run(BlockDraft d, Diagnostics out) {
        if (d.function == 29 && d.prior.g28() == null) {
            d.fail(out, Code.E042_G29_WITHOUT_G28, d.oneShotWord.span());
        }
    }
}
