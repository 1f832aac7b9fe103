package gcnc.check.action;

import gcnc.diag.Code;

/**
 * Thesis §4.2.2 action 9: G92, position register (X Z). A one-shot G with parameters;
 * emits E020 when another one is already in the block. Writes d.oneShot.
 */
public final class Sa09G92Register extends OneShotG {
    public Sa09G92Register() {
        super(92, Code.E020_G50_G92_WITH_OTHER);
    }
}
