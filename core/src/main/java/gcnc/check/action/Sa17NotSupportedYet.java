package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.MFunction;

/**
 * gcnc's action 17 (not in the thesis): a function the control has and gcnc cannot follow yet
 * (canned cycles, threading, nose-radius compensation, subprograms; the control's table says
 * {@code unsupported}). E110 names it at its word, before any other word of the block is read,
 * so it is never misread as something else (Haas G92 is a thread, not a coordinate shift).
 */
public final class Sa17NotSupportedYet implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        long code = w.code();
        String name;
        if (w.letter() == Letter.G) {
            GFunction f = d.functions.g(code);
            name = f == null ? "" : f.english();
        } else {
            MFunction f = d.functions.m(code);
            name = f == null ? "" : f.english();
        }
        d.fail(out, Code.E110_NOT_SUPPORTED_YET, w.span(), w, lowerFirst(name));
    }

    /** "Stock removal in turning" reads "G71 stock removal in turning" after the code; "OD" stays. */
    private static String lowerFirst(String s) {
        if (s.length() > 1 && Character.isUpperCase(s.charAt(0)) && Character.isLowerCase(s.charAt(1))) {
            return Character.toLowerCase(s.charAt(0)) + s.substring(1);
        }
        return s;
    }
}
