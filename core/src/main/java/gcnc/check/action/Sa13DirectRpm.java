package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * Thesis §4.2.2 action 13: G97, direct rpm (cancels G96). The thesis made it a one-shot that
 * demanded S; gcnc treats it as the modal group-17 code it is (Fanuc): S in the same or a later
 * block is an rpm. Emits E016 (G96 and G97 together). Writes next.css.
 */
public final class Sa13DirectRpm implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        if (!d.claimG(d.functions.g(w.code()).group(), w, out)) {
            return;
        }
        d.next.css = false;
    }
}
