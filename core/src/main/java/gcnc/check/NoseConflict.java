package gcnc.check;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import java.util.List;

/**
 * What a block's functions do to the tool nose radius compensation in force
 * (docs/nose-compensation.md, "Under G41/G42"): followed as offset moves, run with the
 * compensation suspended (a warning saying how the control runs them), or an alarm (E178).
 */
final class NoseConflict {
    private NoseConflict() {
    }

    /** What a G function is to the compensation in force. */
    private enum Under {
        /** Followed under G41/G42 (a move, a modal, a setting, G70). */
        FOLLOWED,
        /** G40: the block cancels the compensation, so nothing in it conflicts. */
        CANCELS,
        /** The control alarms (Fanuc PS0035 for G31): E178. */
        ALARM,
        /** Fanuc's temporary cancel: the offset is cancelled for the block's move and restored after (E620). */
        FOR_THE_BLOCK,
        /** A G50 (Fanuc A, Haas) or G92 (B) position register: as {@link #FOR_THE_BLOCK} when it has X or Z, else a clamp. */
        FOR_THE_BLOCK_WITH_AXES,
        /** G71, G72, G73: the control roughs the offset contour, gcnc the programmed one (E622). */
        ROUGHING,
        /** G90, G94: the control offsets each path of the cycle, gcnc follows the programmed paths (E623). */
        SINGLE_CYCLE,
        /** Threads, peck and drilling cycles: the control does not offset them (E624). */
        NOT_OFFSET
    }

    /** Every role, so that a new one does not compile until it is placed. */
    private static Under under(GRole role) {
        return switch (role) {
            case NOSE_COMP_CANCEL -> Under.CANCELS;
            case SKIP -> Under.ALARM;
            case HOME, FROM_HOME, OTHER_HOME, MACHINE_COORDINATES, REGISTER -> Under.FOR_THE_BLOCK;
            case REGISTER_AND_CLAMP -> Under.FOR_THE_BLOCK_WITH_AXES;
            case TURNING_CYCLE, FACING_CYCLE, PATTERN_CYCLE -> Under.ROUGHING;
            case TURNING_SINGLE_CYCLE, FACING_SINGLE_CYCLE -> Under.SINGLE_CYCLE;
            case FACE_PECK_CYCLE, GROOVE_PECK_CYCLE, DRILL_CYCLE, SPOT_DRILL_CYCLE, PECK_DRILL_CYCLE, TAP_CYCLE,
                 REVERSE_TAP_CYCLE, BORE_CYCLE, BORE_STOP_CYCLE, BORE_DWELL_CYCLE, THREAD,
                 THREAD_SINGLE_CYCLE, THREAD_CYCLE -> Under.NOT_OFFSET;
            case RAPID, LINEAR, ARC_CW, ARC_CCW, DWELL, EXACT_STOP, PLANE_XY, PLANE_ZX, PLANE_YZ, INCH, METRIC,
                 NOSE_COMP_LEFT, NOSE_COMP_RIGHT, FINISHING_CYCLE, WORK_1, WORK_2, WORK_3, WORK_4, WORK_5,
                 WORK_6, SET_OFFSETS, CYCLE_CANCEL, CYCLE_RETURN_INITIAL, CYCLE_RETURN_R, ABSOLUTE, INCREMENTAL, FEED_PER_MINUTE, FEED_PER_REV, CSS, RPM,
                 EXACT_STOP_MODE, CUTTING_MODE, UNSUPPORTED, MODE_ONLY, MACRO_CALL, LOOKAHEAD_LIMIT -> Under.FOLLOWED;
        };
    }

    /** What the block's G words do under the compensation, the first that is not followed (and its word). */
    private record Found(Under under, Word word) {
    }

    private static Found find(RawBlock b, FunctionIndex functions) {
        Found found = null;
        boolean axes = b.words().stream().anyMatch(x -> x.letter() == Letter.X || x.letter() == Letter.Z);
        for (Word w : b.words()) {
            GFunction f = w.letter() == Letter.G && !w.number().isEmpty() ? functions.g(w.code()) : null;
            if (f == null) {
                continue;
            }
            Under u = under(f.role());
            if (u == Under.CANCELS) {
                return null;
            }
            if (u == Under.FOR_THE_BLOCK_WITH_AXES) {
                u = axes ? Under.FOR_THE_BLOCK : Under.FOLLOWED;
            }
            if (u != Under.FOLLOWED && (found == null || u == Under.ALARM)) {
                found = new Found(u, w);
            }
        }
        return found;
    }

    /**
     * Judges a block under G41/G42 ({@code inForce}) or one that turns it on, {@code compensation}
     * naming it ("G42"): a warning for what the control runs in its own way (E620-E624), and false
     * after E178 where the control alarms (G31). A T word is the start-up's own in the block that
     * turns the compensation on; under it, the new offset applies from the next move (E621).
     */
    static boolean judge(RawBlock b, FunctionIndex functions, boolean inForce, String compensation,
                         Diagnostics out) {
        Found found = find(b, functions);
        if (found != null && found.under() == Under.ALARM) {
            out.error(Code.E178_NOSE_FUNCTION_IN_FORCE, found.word().span(), found.word(), compensation);
            return false;
        }
        if (found != null && !(found.under() == Under.ROUGHING && b.words().stream().noneMatch(w -> w.letter() == Letter.P))) {
            // (a Fanuc first block, G71 U R, only sets the depth and retract: its second block warns)
            warn(found.under(), found.word().toString(), compensation, found.word(), out);
        } else if (inForce && !cancels(b, functions)) {
            for (Word w : b.words()) {
                if (w.letter() == Letter.T) {
                    out.report(Diagnostic.warning(Code.E621_NOSE_TOOL_CHANGE, w.span(), w, compensation));
                    break;
                }
            }
        }
        return true;
    }

    /**
     * A modal cycle run again under G41/G42 ({@code name} as the program wrote it, "G92"): its
     * warning when the block turns the compensation on ({@code inForce} false); with it in force
     * before, the cycle's own block warned already.
     */
    static void again(RawBlock b, String name, FunctionIndex functions, boolean inForce, String compensation,
                      Diagnostics out) {
        GFunction f = named(name, functions);
        if (f != null && !inForce) {
            warn(under(f.role()), gcnc.diag.Phrase.CYCLE_AGAIN.with(name).toString(), compensation,
                    b.words().get(0), out);
        }
    }

    private static void warn(Under u, String what, String compensation, Word at, Diagnostics out) {
        Code c = switch (u) {
            case FOR_THE_BLOCK -> Code.E620_NOSE_CANCELLED_FOR_THE_BLOCK;
            case ROUGHING -> Code.E622_NOSE_ROUGHING_CYCLE;
            case SINGLE_CYCLE -> Code.E623_NOSE_SINGLE_CYCLE;
            default -> Code.E624_NOSE_NOT_OFFSET;
        };
        // E622 is a note: the program is right and the control roughs as it should; the finding says
        // what gcnc's model does differently (it roughs the programmed contour), not what to change
        out.report(c == Code.E622_NOSE_ROUGHING_CYCLE
                ? new Diagnostic(c, gcnc.diag.Severity.NOTE, at.span(), List.of(what, compensation))
                : Diagnostic.warning(c, at.span(), what, compensation));
    }

    private static boolean cancels(RawBlock b, FunctionIndex functions) {
        for (Word w : b.words()) {
            GFunction f = w.letter() == Letter.G && !w.number().isEmpty() ? functions.g(w.code()) : null;
            if (f != null && f.role() == GRole.NOSE_COMP_CANCEL) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether the checked block made of {@code b} runs with the compensation suspended: a block a
     * cycle other than G70 made ({@code cycle} the cycle's name, null for a block of the program),
     * a thread pass ({@code thread}), or (with the compensation in force before it, {@code before})
     * a temporary cancel: G28, G29, G30, G53, a position register with X or Z, a T word, or a
     * change of side (G42 under G41: the warning E174).
     */
    static NoseSuspend suspend(RawBlock b, FunctionIndex functions, NoseSide before, String cycle,
                                            boolean thread) {
        boolean inForce = before != NoseSide.OFF;
        if (thread) {
            return NoseSuspend.CYCLE;
        }
        if (cycle != null) {
            GFunction f = named(cycle, functions);
            return f != null && f.role() == GRole.FINISHING_CYCLE ? NoseSuspend.NONE
                    : NoseSuspend.CYCLE;
        }
        if (!inForce || cancels(b, functions)) {
            return NoseSuspend.NONE;
        }
        Found found = find(b, functions);
        String on = turningOn(b, functions);
        if (found != null && found.under() == Under.FOR_THE_BLOCK
                || b.words().stream().anyMatch(w -> w.letter() == Letter.T)
                || on != null && !on.equals(before.g())) {
            return NoseSuspend.FOR_THE_BLOCK;
        }
        return NoseSuspend.NONE;
    }

    /** The function of a G code as a finding names it ("G71"), or null. */
    private static GFunction named(String name, FunctionIndex functions) {
        return name.matches("G[0-9]{1,3}") ? functions.g(Long.parseLong(name.substring(1))) : null;
    }

    /** The G41 or G42 of a block without G40, as the control names it; null when it has none. */
    static String turningOn(RawBlock b, FunctionIndex functions) {
        if (!functions.hasNoseCompensation()) {
            return null; // the thesis's language: no G41/G42 to look for
        }
        String on = null;
        for (Word w : b.words()) {
            GFunction f = w.letter() == Letter.G && !w.number().isEmpty() ? functions.g(w.code()) : null;
            if (f != null && f.role() == GRole.NOSE_COMP_CANCEL) {
                return null;
            }
            if (f != null && (f.role() == GRole.NOSE_COMP_LEFT || f.role() == GRole.NOSE_COMP_RIGHT)) {
                on = f.name();
            }
        }
        return on;
    }
}
