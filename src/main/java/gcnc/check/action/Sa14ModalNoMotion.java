package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;
import gcnc.tables.GFunction;

/**
 * Thesis §4.2.2 action 14: G40 (nose-radius compensation cancel; gcnc has no compensation, so it
 * only records the group) and G96 (constant surface speed: S of this and later blocks is m/min or
 * ft/min). Emits E016. Writes next.css, d.g96.
 */
public final class Sa14ModalNoMotion implements SyntaxAction {
    @Override
    public int number() {
        return 14;
    }

    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        int code = (int) NumberText.integer(w.number());
        GFunction f = d.functions.g(code);
        if (!d.claimG(f.group(), w, out)) {
            return;
        }
        if (code == 96) {
            d.next.css = true;
            d.g96 = true;
        }
    }
}
