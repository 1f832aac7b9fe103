package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;

/**
 * Thesis §4.2.2 action 4 ({@code ChkActiveParameter} for S and T, reading §5). S: once, an
 * integer within Table 6 (its meaning is settled at the end of the block: G50 clamp, G96 surface
 * speed or rpm). T{@code tt}{@code oo}: tool = all digits but the last two, offset = the last two;
 * one or two digits ({@code T1}, {@code T01}) select that tool with the offset of the same number
 * (the thesis crashed on them, §12.14). Offset 0 cancels the tool offset. Tool 0 ({@code T0},
 * {@code T00}, {@code T0001}) indexes no tool: the control runs it, the turret stays and only the
 * offset changes (a cut with offset 00 after it is warning E646, {@code gcnc.check.Advisories}).
 * Emits E006, E007, E008, E009, E013, E046, E047. Writes next.tool, next.toolOffset.
 */
public final class Sa04SpeedOrTool implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        Letter l = w.letter();
        if (!d.fresh(w, out)) {
            return;
        }
        long n = w.code();
        if (n == NumberText.NOT_INTEGER) {
            d.fail(out, Code.E013_INTEGER_EXPECTED, w.span(), l);
            return;
        }
        if (l == Letter.S) {
            if (Limits.within(w, n, d, out)) {
                d.accept(w, n);
            }
            return;
        }
        String text = w.number();
        int digits = text.length();
        long tool = digits <= 2 ? n : n / 100;
        long offset = digits <= 2 ? n : n % 100;
        // the messages quote the digits as written: a long T saturates when read, its text does not
        if (tool < 0 || tool > d.profile.tools()) {
            d.fail(out, Code.E046_UNDEFINED_TOOL, w.span(), digits <= 2 ? text : text.substring(0, digits - 2));
            return;
        }
        if (offset != 0 && d.profile.toolOffset((int) offset).isEmpty()) {
            d.fail(out, Code.E047_TOOL_OFFSET_RANGE, w.span(), digits <= 2 ? text : text.substring(digits - 2));
            return;
        }
        d.accept(w, tool);
        if (tool != 0) {
            d.next.tool = (int) tool; // tool 0 (T0, T00, T0001): the turret stays where it is
        }
        d.next.toolOffset = (int) offset;
    }
}
