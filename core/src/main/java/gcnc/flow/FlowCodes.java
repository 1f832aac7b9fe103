package gcnc.flow;

import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import java.util.List;

/**
 * What the control's M codes mean for the program's flow, looked up by number in an array: the
 * flow stage asks it of every M word of every block, so a program without calls pays one array
 * read per M word.
 */
final class FlowCodes {
    private static final int SIZE = 1000;
    private final MRole[] roles = new MRole[SIZE];

    FlowCodes(Control control) {
        for (MFunction f : control.allM()) {
            if (f.code() >= 0 && f.code() < SIZE) {
                roles[f.code()] = f.role();
            }
        }
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
            }
        }
        return bits;
    }

    /** Whether a word calls or returns. */
    boolean flow(Word w) {
        MRole r = role(w);
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
