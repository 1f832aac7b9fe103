package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;

/**
 * Table 10 of the thesis (the parse matrix) as a look-up: a word to its syntax action. Every word
 * is looked up afresh, so an error in one word cannot leave the matrix stuck (the thesis's
 * "stuck parser", reading §4 and §12.2). G and M numbers are read as integers, so G1 = G01 (D5),
 * and looked up in the control's tables: the action follows what a code does, not its number.
 */
public final class SyntaxActions {
    /** The actions by number: the thesis's 1-15, then gcnc's own 16-17; index 0 unused. */
    private final SyntaxAction[] byNumber = {null, new Sa01ModalG(), new Sa02Parameter(), new Sa03FeedOrName(),
        new Sa04SpeedOrTool(), new Sa05G04Dwell(), new Sa06G28Home(), new Sa07G29FromHome(), new Sa08G50Register(),
        new Sa09G92Register(), new Sa10SkipNoOp(), new Sa11ExactStop(), new Sa12Miscellaneous(),
        new Sa13DirectRpm(), new Sa14ModalNoMotion(), new Sa15ProgramEnd(), new Sa16MachineCoordinates(),
        new Sa17NotSupportedYet()};

    /** The action of number n (1..17). */
    public SyntaxAction action(int n) {
        return byNumber[n];
    }

    /** Table 10's action column for a G function (by what it does, whatever its number in the control). */
    static int forG(GRole role) {
        return switch (role) {
            case RAPID, LINEAR, ARC_CW, ARC_CCW, INCH, METRIC, WORK_1, WORK_2, WORK_3, WORK_4, WORK_5, WORK_6,
                 ABSOLUTE, INCREMENTAL, FEED_PER_MINUTE, FEED_PER_REV, CYCLE_RETURN_INITIAL, CYCLE_RETURN_R -> 1;
            case DWELL -> 5;
            case HOME -> 6;
            case FROM_HOME -> 7;
            case REGISTER_AND_CLAMP -> 8;
            case REGISTER -> 9;
            case SKIP -> 10;
            case EXACT_STOP -> 11;
            case RPM -> 13;
            case NOSE_COMP_CANCEL, NOSE_COMP_LEFT, NOSE_COMP_RIGHT, CSS, CYCLE_CANCEL, PLANE_XY, PLANE_ZX, PLANE_YZ,
                 EXACT_STOP_MODE, CUTTING_MODE, MODE_ONLY, LOOKAHEAD_LIMIT -> 14;
            case MACHINE_COORDINATES -> 16;
            case UNSUPPORTED -> 17;
            // a macro call reaches the checker only where gcnc.flow did not follow it, as an M98 does
            case MACRO_CALL -> 17;
            // expanded before the syntax actions (gcnc.check.cycle): a cycle word met here is in a
            // block the expansion hands on, where it cannot be followed
            case FINISHING_CYCLE, TURNING_CYCLE, FACING_CYCLE, PATTERN_CYCLE, TURNING_SINGLE_CYCLE, FACING_SINGLE_CYCLE,
                 FACE_PECK_CYCLE, GROOVE_PECK_CYCLE, DRILL_CYCLE, SPOT_DRILL_CYCLE, PECK_DRILL_CYCLE,
                 TAP_CYCLE, REVERSE_TAP_CYCLE, BORE_CYCLE, BORE_STOP_CYCLE, BORE_DWELL_CYCLE, THREAD, THREAD_SINGLE_CYCLE, THREAD_CYCLE, SET_OFFSETS, OTHER_HOME -> 17;
        };
    }

    /** The action for a word, or null after reporting why there is none (E001, E002, E004, E011, E262, E012). */
    public SyntaxAction lookUp(Word w, BlockDraft d, Diagnostics out) {
        if (!d.functions.reads(w.letter())) {
            d.fail(out, Code.E004_UNDEFINED_FUNCTION, w.span(), w.letter());
            return null;
        }
        switch (w.letter()) {
            case F, O:
                return byNumber[3];
            case S, T:
                return byNumber[4];
            case G: {
                if (w.number().isEmpty()) {
                    d.fail(out, Code.E001_G_NUMBER_EXPECTED, w.span());
                    return null;
                }
                GFunction f = d.functions.g(w.code());
                if (f == null) {
                    // G43/G44/G49: a mill's tool length compensation, written in mill-style safe-start lines
                    long c = w.code();
                    d.fail(out, c == 43 || c == 44 || c == 49 ? Code.E262_MILL_TOOL_LENGTH_G : Code.E011_UNDEFINED_G,
                            w.span(), w);
                    return null;
                }
                return byNumber[forG(f.role())];
            }
            case M: {
                if (w.number().isEmpty()) {
                    d.fail(out, Code.E002_M_NUMBER_EXPECTED, w.span());
                    return null;
                }
                MFunction f = d.functions.m(w.code());
                if (f == null) {
                    d.fail(out, Code.E012_UNDEFINED_M, w.span(), w);
                    return null;
                }
                // a call reaches the checker only without gcnc.flow in front of it: not followed, E110;
                // M99 reaches it only in the main program, which it ends (gcnc.flow warns: E139)
                if (f.role() == MRole.UNSUPPORTED || f.role().call()) {
                    return byNumber[17];
                }
                return byNumber[f.role() == MRole.END || f.role() == MRole.RETURN ? 15 : 12];
            }
            default:
                // N X Z U W I K R P, and the letters of cycles and threads (Q D A E ...)
                return byNumber[2];
        }
    }
}
