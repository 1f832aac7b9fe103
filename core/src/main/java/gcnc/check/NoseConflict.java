package gcnc.check;

import gcnc.ir.RawBlock;
import gcnc.ir.Word;

/** What cannot be followed while tool nose radius compensation is in force (E178). */
final class NoseConflict {
    private NoseConflict() {
    }

    /** What a G function is to the compensation in force. */
    private enum Under {
        /** Followed under G41/G42 (a move, a modal or a setting). */
        FOLLOWED,
        /** G40: the block cancels the compensation, so nothing in it conflicts. */
        CANCELS,
        /** Needs G40 first (E178). */
        CONFLICTS,
        /** A G50 (Fanuc A, Haas) or G92 (B) that sets a position when it has X or Z, else only clamps. */
        CONFLICTS_WITH_AXES
    }

    /**
     * Every role, so that a new one does not compile until it is placed: the cycles other than G70,
     * threads (a spindle-synchronised pass is never offset), G28, G29, G53 and a position register
     * need G40 first.
     */
    private static Under under(gcnc.machine.GRole role) {
        return switch (role) {
            case NOSE_COMP_CANCEL -> Under.CANCELS;
            case TURNING_CYCLE, FACING_CYCLE, PATTERN_CYCLE, TURNING_SINGLE_CYCLE, FACING_SINGLE_CYCLE,
                 FACE_PECK_CYCLE, GROOVE_PECK_CYCLE, DRILL_CYCLE, SPOT_DRILL_CYCLE, PECK_DRILL_CYCLE,
                 THREAD, THREAD_SINGLE_CYCLE, THREAD_CYCLE, HOME, FROM_HOME, MACHINE_COORDINATES, REGISTER ->
                Under.CONFLICTS;
            case REGISTER_AND_CLAMP -> Under.CONFLICTS_WITH_AXES;
            case RAPID, LINEAR, ARC_CW, ARC_CCW, DWELL, EXACT_STOP, PLANE_XY, PLANE_ZX, PLANE_YZ, INCH, METRIC,
                 SKIP, NOSE_COMP_LEFT, NOSE_COMP_RIGHT, FINISHING_CYCLE, WORK_1, WORK_2, WORK_3, WORK_4, WORK_5,
                 WORK_6, CYCLE_CANCEL, ABSOLUTE, INCREMENTAL, FEED_PER_MINUTE, FEED_PER_REV, CSS, RPM,
                 UNSUPPORTED, MODE_ONLY -> Under.FOLLOWED;
        };
    }

    /**
     * E178: under G41/G42 gcnc follows G00-G03 moves only; a cycle other than G70, a thread, G28,
     * G29, G53, a G50/G92 position register or a tool change ({@code toolChanges}: not in the block
     * that turns the compensation on, where the T is the start-up's own) needs G40 first (unless
     * the block has it): the word of the block that does, or null.
     */
    static Word find(RawBlock b, FunctionIndex functions, boolean toolChanges) {
        Word conflict = null;
        for (Word w : b.words()) {
            if (toolChanges && w.letter() == gcnc.ir.Letter.T && conflict == null) {
                conflict = w;
            }
            if (w.letter() != gcnc.ir.Letter.G || w.number().isEmpty()) {
                continue;
            }
            gcnc.machine.GFunction f = functions.g(w.code());
            if (f == null) {
                continue;
            }
            switch (under(f.role())) {
                case CANCELS -> {
                    return null;
                }
                case CONFLICTS -> conflict = conflict == null ? w : conflict;
                case CONFLICTS_WITH_AXES -> {
                    if (b.words().stream().anyMatch(x -> x.letter() == gcnc.ir.Letter.X || x.letter() == gcnc.ir.Letter.Z)) {
                        conflict = conflict == null ? w : conflict;
                    }
                }
                case FOLLOWED -> {
                }
            }
        }
        return conflict;
    }

    /** The G41 or G42 of a block without G40, as the control names it; null when it has none. */
    static String turningOn(RawBlock b, FunctionIndex functions) {
        if (!functions.hasNoseCompensation()) {
            return null; // the thesis's language: no G41/G42 to look for
        }
        String on = null;
        for (Word w : b.words()) {
            gcnc.machine.GFunction f = w.letter() == gcnc.ir.Letter.G && !w.number().isEmpty() ? functions.g(w.code()) : null;
            if (f != null && f.role() == gcnc.machine.GRole.NOSE_COMP_CANCEL) {
                return null;
            }
            if (f != null && (f.role() == gcnc.machine.GRole.NOSE_COMP_LEFT || f.role() == gcnc.machine.GRole.NOSE_COMP_RIGHT)) {
                on = f.name();
            }
        }
        return on;
    }
}
