package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * Thesis §4.2.2 action 15: M30 ends the program (and M02 on the controls whose table says
 * {@code end}: Fanuc, Haas), and so does M99 where the main program has it (the control would run
 * the program again from its top; gcnc.flow warns, E139). It emits nothing (code and Table 5.2 agree); any later block is
 * error 53. Shares group 1 with M00-M02 (E016). Writes next.ended.
 */
public final class Sa15ProgramEnd implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        int group = d.functions.m(w.code()).group();
        if (!d.claimM(group, w, out)) {
            return;
        }
        d.next.ended = true;
    }
}
