package gcnc.flow;

import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.GRole;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import gcnc.machine.Units;
import java.util.List;

/**
 * What the control's codes mean for the program's flow: its M codes, looked up by number in an
 * array (the flow stage asks it of every M word of every block, so a program without calls pays
 * one array read per M word), its macro call (G65) and its G20/G21, by which a macro call's
 * arguments written without a decimal point are read.
 */
final class FlowCodes {
    private static final int SIZE = 1000;
    private final MRole[] roles = new MRole[SIZE];
    /** The G numbers of the macro call, inch and metric input; -1: the control has none. */
    private final long macroCall;
    private final long inch;
    private final long metric;

    FlowCodes(Control control) {
        for (MFunction f : control.allM()) {
            if (f.code() >= 0 && f.code() < SIZE) {
                roles[f.code()] = f.role();
            }
        }
        macroCall = gNumber(control, GRole.MACRO_CALL);
        inch = gNumber(control, GRole.INCH);
        metric = gNumber(control, GRole.METRIC);
    }

    private static long gNumber(Control control, GRole role) {
        return control.gFor(role).map(g -> (long) g.code()).orElse(-1L);
    }

    /** Whether a word is the control's macro call (G65). */
    boolean macroCall(Word w) {
        return w.letter() == Letter.G && macroCall >= 0 && FlowWords.digits(w.number()) == macroCall;
    }

    /** The input units a G word selects (G20, G21), or null for any other word. */
    Units units(Word w) {
        if (w.letter() != Letter.G) {
            return null;
        }
        long g = FlowWords.digits(w.number());
        return g < 0 ? null : g == inch ? Units.INCH : g == metric ? Units.MM : null;
    }

    /** The role of a flow word in the program's flow: a macro call calls, as M98 does ({@link MRole#CALL}). */
    MRole flowRole(Word w) {
        return macroCall(w) ? MRole.CALL : role(w);
    }

    /** The role of an M word's code, or null (not an M word, not a code of the control). */
    MRole role(Word w) {
        if (w.letter() != Letter.M) {
            return null;
        }
        long code = FlowWords.digits(w.number());
        return code >= 0 && code < SIZE ? roles[(int) code] : null;
    }

    /** {@link #scan} bits: the block has a call or return; it has an end code or M99. */
    static final int FLOW = 1;
    static final int END = 2;

    /** One look at a block's words: {@link #FLOW} and {@link #END} bits. */
    int scan(List<Word> words) {
        int bits = 0;
        for (int i = 0, n = words.size(); i < n; i++) {
            Word w = words.get(i);
            if (w.letter() == Letter.M) {
                MRole r = role(w);
                if (r == MRole.CALL || r == MRole.LOCAL_CALL || r == MRole.RETURN) {
                    bits |= FLOW;
                }
                if (r == MRole.END || r == MRole.RETURN) {
                    bits |= END;
                }
            } else if (macroCall(w)) {
                bits |= FLOW;
            }
        }
        return bits;
    }

    /** Whether a word calls or returns. */
    boolean flow(Word w) {
        MRole r = flowRole(w);
        return r == MRole.CALL || r == MRole.LOCAL_CALL || r == MRole.RETURN;
    }

    /**
     * Whether a macro statement line holds an M word that ends the main program ({@code X[#1] M30}):
     * an M right after a digit, space, ']' or the start, followed by digits, outside comments.
     */
    boolean endsText(String text) {
        boolean comment = false;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            if (comment || c == '(') {
                comment = c != ')';
                continue;
            }
            boolean m = (c == 'M' || c == 'm') && (i == 0 || !Character.isLetter(text.charAt(i - 1)));
            int j = i + 1;
            while (m && j < text.length() && Character.isDigit(text.charAt(j))) {
                j++;
            }
            if (m && j > i + 1) {
                long code = FlowWords.digits(text.substring(i + 1, j));
                MRole r = code >= 0 && code < SIZE ? roles[(int) code] : null;
                if (r == MRole.END || r == MRole.RETURN) {
                    return true;
                }
            }
        }
        return false;
    }
}
