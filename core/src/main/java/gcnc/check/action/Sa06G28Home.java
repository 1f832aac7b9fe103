package gcnc.check.action;

import gcnc.diag.Code;

/**
 * Thesis §4.2.2 action 6: G28, return to the reference point through an intermediate point. A one-shot G with parameters;
 * emits E018 when another one is already in the block. Writes d.oneShot.
 */
public final class Sa06G28Home extends OneShotG {
    public Sa06G28Home() {
        super(28, Code.E018_G28_WITH_OTHER);
    }
}
