package gcnc.check;

import gcnc.check.action.SyntaxAction;
import gcnc.check.action.SyntaxActions;
import gcnc.check.block.BlockCheck;
import gcnc.check.block.BlockChecks;
import gcnc.check.geom.Coordinates;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.MachineProfile;
import gcnc.tables.Tables;
import java.util.List;
import java.util.Optional;

/**
 * The checking stage: each block's words go through the thesis's syntax actions, then the
 * end-of-block operations in their fixed order, then motion building. The first error of a block
 * is reported and the block is dropped; the modal state changes only for a block without errors,
 * or one whose only errors are broken prerequisites ({@link #recover}).
 */
public final class Checker {
    /** After this many errors the checker reports 45 ("not enough memory") once and stops. */
    public static final int ERROR_CAP = 10_000;

    private final Tables tables;
    private final MachineProfile profile;
    private final Diagnostics out;
    private final FunctionIndex functions;
    private final SyntaxActions actions = new SyntaxActions();
    private final Coordinates coordinates;
    private final MotionBuilder motions;
    private final int errorCap;
    private ModalState state;
    private long blocks;
    private boolean stopped;

    public Checker(Tables tables, MachineProfile profile, Diagnostics out) {
        this(tables, profile, out, ERROR_CAP);
    }

    Checker(Tables tables, MachineProfile profile, Diagnostics out, int errorCap) {
        this.tables = tables;
        this.profile = profile;
        this.out = out;
        this.functions = new FunctionIndex(tables);
        this.coordinates = new Coordinates(profile);
        this.motions = new MotionBuilder(profile, coordinates);
        this.errorCap = errorCap;
        this.state = ModalState.initial(profile.home());
    }

    /** The modal state after the last accepted block. */
    public ModalState state() {
        return state;
    }

    public Optional<CheckedBlock> check(RawBlock b) {
        if (stopped) {
            return Optional.empty();
        }
        Span first = b.words().isEmpty() ? b.last() : b.words().get(0).span();
        if (out.errorCount() >= errorCap) {
            out.error(Code.E045_OUT_OF_MEMORY, first, out.errorCount());
            stopped = true;
            return Optional.empty();
        }
        boolean isFirst = blocks++ == 0;
        if (state.ended()) {
            out.error(Code.E053_M30_NOT_LAST, first);
            return Optional.empty();
        }
        if (b.malformed()) {
            return Optional.empty();
        }
        BlockDraft d = new BlockDraft(b, state, tables, functions, profile, coordinates, isFirst);
        CheckedBlock result = run(d, out, true);
        if (result == null) {
            recover(b, isFirst);
            return Optional.empty();
        }
        state = d.next.build();
        return Optional.of(result);
    }

    /**
     * After an error: if the block is clean but for prerequisite rules (an F, M11, M03 or G50 S
     * missing before a cut, an S above the clamp), take the state it would have left, as if the
     * programmer had fixed what was reported. Otherwise its F, G01, S or M03 would be lost and
     * every later block would report an echo of this one instead of its own errors. The re-run
     * reports nothing; a block with any other error leaves the state alone (atomic commit).
     */
    private void recover(RawBlock b, boolean isFirst) {
        BlockDraft d = new BlockDraft(b, state, tables, functions, profile, coordinates, isFirst);
        if (run(d, new Diagnostics(), false) != null) {
            state = d.next.build();
        }
    }

    private CheckedBlock run(BlockDraft d, Diagnostics out, boolean prerequisites) {
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
        return d.failed() ? null : motions.build(d, out);
    }

    /** End of the program: it must have ended with M30 (52). */
    public void finish(int lastLine) {
        if (!stopped && !state.ended()) {
            out.error(Code.E052_NO_M30, Span.of(Math.max(1, lastLine), 1));
        }
    }
}
