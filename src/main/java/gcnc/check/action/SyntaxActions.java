package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;

/**
 * Table 10 of the thesis (the parse matrix) as a look-up: a word to its syntax action. Every word
 * is looked up afresh, so an error in one word cannot leave the matrix stuck (the thesis's
 * "stuck parser", reading §4 and §12.2). G and M numbers are read as integers, so G1 = G01 (D5).
 */
public final class SyntaxActions {
    /** The actions by thesis number; index 0 unused. */
    private final SyntaxAction[] byNumber = {null, new Sa01ModalG(), new Sa02Parameter(), new Sa03FeedOrName(),
        new Sa04SpeedOrTool(), new Sa05G04Dwell(), new Sa06G28Home(), new Sa07G29FromHome(), new Sa08G50Register(),
        new Sa09G92Register(), new Sa10SkipNoOp(), new Sa11ExactStop(), new Sa12Miscellaneous(),
        new Sa13DirectRpm(), new Sa14ModalNoMotion(), new Sa15ProgramEnd()};

    /** The action of thesis number n (1..15). */
    public SyntaxAction action(int n) {
        return byNumber[n];
    }

    /** Table 10's action column for a G code, or 0 when gcnc has no action for it. */
    static int forG(int g) {
        return switch (g) {
            case 0, 1, 2, 3, 20, 21, 54, 55, 56, 57, 58, 59, 90, 91, 94, 95, 98, 99 -> 1;
            case 4 -> 5;
            case 28 -> 6;
            case 29 -> 7;
            case 50 -> 8;
            case 92 -> 9;
            case 31 -> 10;
            case 9 -> 11;
            case 97 -> 13;
            case 40, 96 -> 14;
            default -> 0;
        };
    }

    /** The action for a word, or null after reporting why there is none (E001, E002, E011, E012). */
    public SyntaxAction lookUp(Word w, BlockDraft d, Diagnostics out) {
        switch (w.letter()) {
            case N, X, Z, U, W, I, K, R, P:
                return byNumber[2];
            case F, O:
                return byNumber[3];
            case S, T:
                return byNumber[4];
            case G: {
                long g = NumberText.integer(w.number());
                if (w.number().isEmpty()) {
                    d.fail(out, Code.E001_G_NUMBER_EXPECTED, w.span());
                    return null;
                }
                int n = d.functions.g(g) == null ? 0 : forG((int) g);
                if (n == 0) {
                    d.fail(out, Code.E011_UNDEFINED_G, w.span(), w);
                    return null;
                }
                return byNumber[n];
            }
            case M: {
                long m = NumberText.integer(w.number());
                if (w.number().isEmpty()) {
                    d.fail(out, Code.E002_M_NUMBER_EXPECTED, w.span());
                    return null;
                }
                if (d.functions.m(m) == null) {
                    d.fail(out, Code.E012_UNDEFINED_M, w.span(), w);
                    return null;
                }
                return byNumber[m == 30 ? 15 : 12];
            }
            default:
                throw new IllegalStateException("letter without an action: " + w.letter());
        }
    }
}
