package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.MCall;
import gcnc.ir.Word;
import gcnc.tables.MFunction;

/**
 * Thesis §4.2.2 action 12: an M function (every M but M30). One M per group per block (the text
 * asks for it, the code never checked: §12.19). The chuck may not open while the spindle runs
 * (error 40, thesis §4.5; only M03/M04 count as running, not "M05 never given"). The M goes to
 * {@code before} (moments 0, 1) or {@code after} (99) in source order (decision D2).
 * Emits E016, E040. Writes next.spindle, next.chuck, d.spindleBefore.
 */
public final class Sa12Miscellaneous implements SyntaxAction {
    @Override
    public int number() {
        return 12;
    }

    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        int code = (int) NumberText.integer(w.number());
        MFunction f = d.functions.m(code);
        if (!d.claimM(f.group(), w, out)) {
            return;
        }
        if (code == 10 && (running(d.prior.spindle()) || running(d.spindleBefore))
                || running(code) && d.next.chuck == 10 && d.prior.chuck() != 10) {
            d.fail(out, Code.E040_SPINDLE_RUNNING_CHUCK_OPEN, w.span());
            return;
        }
        if (f.group() == 2) {
            d.next.spindle = code;
            if (f.beforeMotion()) {
                d.spindleBefore = code;
            }
        } else if (code == 10 || code == 11) {
            d.next.chuck = code;
        }
        (f.beforeMotion() ? d.before : d.after).add(new MCall(code));
    }

    private static boolean running(int spindle) {
        return spindle == 3 || spindle == 4;
    }
}
