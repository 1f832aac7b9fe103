package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * Thesis §4.2.2 action 15: M30 ends the program. It emits nothing (code and Table 5.2 agree);
 * any later block is error 53. Shares group 1 with M00-M02 (E016). Writes next.ended.
 */
public final class Sa15ProgramEnd implements SyntaxAction {
    @Override
    public int number() {
        return 15;
    }

    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        int group = d.functions.m(30).group();
        Word earlier = d.mInGroup(group);
        if (earlier != null) {
            d.fail(out, Code.E016_GROUP_CONFLICT, w.span(), earlier);
            return;
        }
        d.setM(group, w);
        d.next.ended = true;
    }
}
