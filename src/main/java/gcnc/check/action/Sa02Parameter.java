package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.Units;

/**
 * Thesis §4.2.2 action 2 ({@code ChkActiveParameter}, reading §4.1, §5): N, X, Z, U, W, I, K, R, P.
 * A word once per block; its number present and well formed; Table 6's range; N increasing.
 * A coordinate written without a decimal point is scaled by the profile's no-point rule in the
 * block's units. Emits E006, E007, E008, E009, E013, E014, E043. Writes the word and next.lastN.
 */
public final class Sa02Parameter implements SyntaxAction {
    @Override
    public int number() {
        return 2;
    }

    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        Letter l = w.letter();
        if (!d.fresh(w, out)) {
            return;
        }
        double v;
        if (l == Letter.N || l == Letter.P) {
            long n = NumberText.integer(w.number());
            if (n == NumberText.NOT_INTEGER) {
                d.fail(out, Code.E013_INTEGER_EXPECTED, w.span(), l);
                return;
            }
            v = n;
        } else {
            v = NumberText.decimal(w.number());
            if (Double.isNaN(v)) {
                d.fail(out, Code.E014_DECIMAL_EXPECTED, w.span(), l);
                return;
            }
            if (!NumberText.hasPoint(w.number())) {
                v *= d.units == Units.INCH ? d.profile.noPointInch() : d.profile.noPointMm();
            }
        }
        if (!Limits.within(w, v, d, out)) {
            return;
        }
        if (l == Letter.N) {
            if (v <= d.prior.lastN()) {
                d.fail(out, Code.E043_LINE_NUMBER_ORDER, w.span(), (long) v, d.prior.lastN());
                return;
            }
            d.next.lastN = (long) v;
        }
        d.accept(w, v);
    }
}
