package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;
import gcnc.tables.ParameterLimit;

/**
 * Table 6 as the syntax actions apply it to a value as programmed (after the no-point rule).
 * Below the lower limit is error 8 ("too small"), above the upper one error 9 ("too large"); the
 * thesis used 15 for both and left 8/9 to wrong lexer states (reading §3.2). 15 is kept for
 * machine limits (travel, maximum rpm). Words without a Table 6 row pass.
 */
final class Limits {
    private Limits() {
    }

    static boolean within(Word w, double v, BlockDraft d, Diagnostics out) {
        ParameterLimit lim = d.functions.limit(w.letter());
        if (lim == null) {
            return true;
        }
        if (v < lim.lower()) {
            d.fail(out, Code.E008_PARAMETER_TOO_SMALL, w.span(), w.letter(), w.number(), plain(lim.lower()));
            return false;
        }
        if (v > lim.upper()) {
            d.fail(out, Code.E009_PARAMETER_TOO_LARGE, w.span(), w.letter(), w.number(), plain(lim.upper()));
            return false;
        }
        return true;
    }

    /** A limit as the table writes it (0.0001, not Double's 1.0E-4). */
    private static String plain(double v) {
        return NumberText.plain(v);
    }
}
