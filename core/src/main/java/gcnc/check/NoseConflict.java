package gcnc.check;

import gcnc.ir.RawBlock;
import gcnc.ir.Word;

/** What cannot be followed while tool nose radius compensation is in force (E178). */
final class NoseConflict {
    private NoseConflict() {
    }

    /**
     * E178: under G41/G42 gcnc follows G00-G03 moves only; a cycle other than G70, G28, G29, G53, a
     * G50/G92 position register or a tool change needs G40 first (unless the block has it): the
     * word of the block that does, or null.
     */
    static Word find(RawBlock b, FunctionIndex functions) {
        Word conflict = null;
        for (Word w : b.words()) {
            if (w.letter() == gcnc.ir.Letter.T && conflict == null) {
                conflict = w;
            }
            if (w.letter() != gcnc.ir.Letter.G || w.number().isEmpty()) {
                continue;
            }
            gcnc.machine.GFunction f = functions.g(w.code());
            if (f == null) {
                continue;
            }
            switch (f.role()) {
                case NOSE_COMP_CANCEL -> {
                    return null;
                }
                case TURNING_CYCLE, FACING_CYCLE, PATTERN_CYCLE, TURNING_SINGLE_CYCLE, FACING_SINGLE_CYCLE, HOME,
                     FROM_HOME, MACHINE_COORDINATES, REGISTER -> conflict = conflict == null ? w : conflict;
                case REGISTER_AND_CLAMP -> {
                    if (b.words().stream().anyMatch(x -> x.letter() == gcnc.ir.Letter.X || x.letter() == gcnc.ir.Letter.Z)) {
                        conflict = conflict == null ? w : conflict;
                    }
                }
                default -> {
                }
            }
        }
        return conflict;
    }
}
