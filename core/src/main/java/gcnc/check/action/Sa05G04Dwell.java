package gcnc.check.action;

import gcnc.diag.Code;

/**
 * Thesis §4.2.2 action 5: G04, dwell (X/U seconds or P milliseconds). A one-shot G with parameters;
 * emits E017 when another one is already in the block. Writes d.oneShot.
 */
public final class Sa05G04Dwell extends OneShotG {
    public Sa05G04Dwell() {
        super(4, Code.E017_G04_WITH_OTHER);
    }
}
