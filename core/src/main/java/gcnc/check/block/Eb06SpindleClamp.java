package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;

/**
 * Thesis end-of-block operation 6: G50 S sets the maximum spindle speed for later S words and
 * for G96. It emits nothing. Emits no code. Writes next.rpmClamp.
 */
public final class Eb06SpindleClamp implements BlockCheck {
    @Override
    public void run(BlockDraft d, Diagnostics out) {
        if (d.function == 50 && d.has(Letter.S)) {
            d.next.rpmClamp = d.value(Letter.S);
        }
    }
}
