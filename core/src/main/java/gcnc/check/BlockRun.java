package gcnc.check;

import gcnc.check.action.SyntaxAction;
import gcnc.check.action.SyntaxActions;
import gcnc.check.block.BlockCheck;
import gcnc.check.block.BlockChecks;
import gcnc.check.geom.Coordinates;
import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.MachineProfile;
import gcnc.tables.Tables;
import java.util.List;

/**
 * One block through the thesis's syntax actions, then the end-of-block operations in their fixed
 * order, then motion building, from a given state. It only checks: the {@link BlockDraft} it fills
 * holds the next state, which the checker takes (or not) in one step.
 */
final class BlockRun {
    private final SyntaxActions actions = new SyntaxActions();
    private final MachineProfile profile;
    private final FunctionIndex functions;
    private final MotionBuilder motions;
    /** The draft of the block being checked, started afresh for each ({@link BlockDraft}). */
    private final BlockDraft draft;

    BlockRun(Tables tables, FunctionIndex functions, MachineProfile profile, Coordinates coordinates) {
        this.profile = profile;
        this.functions = functions;
        this.motions = new MotionBuilder(profile, coordinates);
        this.draft = new BlockDraft(tables, functions, profile, coordinates);
    }

    /** The draft started for {@code b} from {@code from} (the one draft, emptied). */
    BlockDraft start(RawBlock b, ModalState from, boolean isFirst) {
        return draft.start(b, from, isFirst);
    }

    /** The block's words, checks and motion; null after an error ({@code prerequisites} false: those rules skipped). */
    CheckedBlock run(BlockDraft d, Diagnostics out, boolean prerequisites) {
        return words(d, out, prerequisites) ? motions.build(d, out) : null;
    }

    /** The block's motion, its words already run; null after an error. */
    CheckedBlock motion(BlockDraft d, Diagnostics out) {
        return motions.build(d, out);
    }

    /** The syntax actions and the end-of-block checks; false after an error. */
    boolean words(BlockDraft d, Diagnostics out, boolean prerequisites) {
        Word unsupported = d.unsupported;
        if (unsupported != null) {
            actions.action(17).apply(unsupported, d, out);
            return false;
        }
        List<Word> words = d.block.words();
        for (int i = 0; i < words.size() && !d.failed(); i++) {
            Word w = words.get(i);
            SyntaxAction a = actions.lookUp(w, d, out);
            if (a != null) {
                a.apply(w, d, out);
            }
        }
        for (int i = 0; i < BlockChecks.ORDER.size() && !d.failed(); i++) {
            BlockCheck c = BlockChecks.ORDER.get(i);
            if (prerequisites || !c.prerequisite()) {
                c.run(d, out);
            }
        }
        return !d.failed();
    }

    /**
     * A block refused for one word that is not part of its move (the thesis's R on a G01): when
     * the block without it ({@code fixed}) is sound from {@code state}, the state it would leave, as
     * if the programmer had fixed what was reported; null when {@code fixed} has errors of its own.
     */
    ModalState fixed(RawBlock fixed, ModalState state) {
        BlockDraft d = draft.start(fixed, state, false);
        Diagnostics none = new Diagnostics();
        if (!words(d, none, false) || motions.build(d, none) == null) {
            return null;
        }
        // as a block whose move failed (recover): its motion G and its end point, nothing else of it
        return Salvage.moved(fixed, state, d, functions, profile);
    }
}
