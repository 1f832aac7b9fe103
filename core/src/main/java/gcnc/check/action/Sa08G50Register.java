package gcnc.check.action;

import gcnc.diag.Code;

/**
 * Thesis §4.2.2 action 8: G50, position register (X Z) and spindle clamp (S). A one-shot G with parameters;
 * emits E020 when another one is already in the block. Writes d.oneShot.
 */
public final class Sa08G50Register extends OneShotG {
    public Sa08G50Register() {
        super(50, Code.E020_G50_G92_WITH_OTHER);
    }
}
