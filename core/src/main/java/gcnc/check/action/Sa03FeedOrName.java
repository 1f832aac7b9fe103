package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;

/**
 * Thesis §4.2.2 action 3 ({@code AssUniqueParameters}): F (feed, modal, takes effect in its own
 * block) and O (program name: once, and only before the first block). The thesis had no duplicate
 * check for F; gcnc reports 7. An O written against the number before it ({@code Z-1O0}) is not
 * a program number but the letter O typed for a zero (120). Emits E006, E007, E008, E009, E013,
 * E014, E033, E034, E120.
 * Writes next.feed, next.named.
 */
public final class Sa03FeedOrName implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        if (w.letter() == Letter.O) {
            name(w, d, out);
            return;
        }
        if (d.has(Letter.F)) {
            d.fail(out, Code.E007_DUPLICATE_PARAMETER, w.span(), Letter.F);
            return;
        }
        if (w.number().isEmpty()) {
            d.fail(out, Code.E006_NUMBER_EXPECTED, w.span(), Letter.F);
            return;
        }
        double f = NumberText.decimal(w.number());
        if (Double.isNaN(f)) {
            d.fail(out, Code.E014_DECIMAL_EXPECTED, w.span(), Letter.F);
            return;
        }
        if (Limits.within(w, f, d, out)) {
            d.accept(w, f);
            d.next.feed = f;
        }
    }

    private static void name(Word w, BlockDraft d, Diagnostics out) {
        Word before = GluedWords.before(d.block, w);
        if (before != null && before.letter() != Letter.O) {
            // Z-1O5 lexes as Z-1 and a program number O5: the O is a zero typed as a letter, even in
            // the first block (a program number stands on its own, not against a number)
            d.fail(out, Code.E120_LETTER_O_IN_NUMBER, before.span(), before + "O" + w.number(),
                    before + "0" + w.number());
            return;
        }
        if (d.prior.named() || d.has(Letter.O)) {
            d.fail(out, Code.E033_PROGRAM_NAME_TWICE, w.span());
            return;
        }
        if (!d.first) {
            d.fail(out, Code.E034_PROGRAM_NAME_LATE, w.span());
            return;
        }
        if (w.number().isEmpty()) {
            d.fail(out, Code.E006_NUMBER_EXPECTED, w.span(), Letter.O);
            return;
        }
        long o = w.code();
        if (o == NumberText.NOT_INTEGER) {
            d.fail(out, Code.E013_INTEGER_EXPECTED, w.span(), Letter.O);
            return;
        }
        if (Limits.within(w, o, d, out)) {
            d.accept(w, o);
            d.next.named = true;
        }
    }
}
