package gcnc.flow;

import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;

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

    /** Whether a word calls or returns. */
    boolean flow(Word w) {
        MRole r = role(w);
        return r == MRole.CALL || r == MRole.RETURN;
    }

    /** Whether a word ends the main program: an end code, or M99 (the control loops; E139). */
    boolean ends(Word w) {
        MRole r = role(w);
        return r == MRole.END || r == MRole.RETURN;
    }
}
