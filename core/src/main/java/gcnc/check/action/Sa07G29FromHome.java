package gcnc.check.action;

import gcnc.diag.Code;

/**
 * Thesis §4.2.2 action 7: G29, return from the reference point through the G28 intermediate point. A one-shot G with parameters;
 * emits E019 when another one is already in the block. Writes d.oneShot.
 */
public final class Sa07G29FromHome extends OneShotG {
    public Sa07G29FromHome() {
        super(29, Code.E019_G29_WITH_OTHER);
    }
}
