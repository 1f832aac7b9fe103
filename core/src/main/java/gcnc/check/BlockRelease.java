package gcnc.check;

import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

/**
 * How the checked blocks leave the checker: through the nose radius compensation (G41/G42, which
 * may hold some back until the next move) and the continuous threads (consecutive G32 blocks
 * joined into one, docs/threading.md), each thread's run-in checked once joined.
 */
final class BlockRelease {
    private final MachineProfile profile;
    private final FunctionIndex functions;
    private final Diagnostics out;
    /** G41/G42: the compensated path, and what it needs to know of each block the flow made. */
    private final NoseCompensation nose;
    private final Map<CheckedBlock, NoseInfo> noseInfo = new IdentityHashMap<>();
    /** Consecutive G32 blocks: one continuous thread (docs/threading.md). */
    private final ThreadChain threadChain;

    BlockRelease(MachineProfile profile, FunctionIndex functions, Diagnostics out) {
        this(profile, functions, out, new NoseCompensation(profile, out));
    }

    private BlockRelease(MachineProfile profile, FunctionIndex functions, Diagnostics out, NoseCompensation nose) {
        this.profile = profile;
        this.functions = functions;
        this.out = out;
        this.nose = nose;
        this.threadChain = new ThreadChain(out);
    }

    /** The same compensation, findings to {@code out}, for the other position of the block delete switch. */
    BlockRelease copy(FunctionIndex functions, Diagnostics out) {
        return new BlockRelease(profile, functions, out, nose.copy(out));
    }

    /** Where Threading marks its G32 passes for the continuous threads. */
    ThreadChain threadChain() {
        return threadChain;
    }

    /**
     * Notes what the compensation needs to know of a block made with G41/G42 in force before or
     * after it ({@code prior}, {@code state}); a block without this record has G40 in force before
     * and after it (most blocks: nothing allocated).
     */
    void made(CheckedBlock made, RawBlock b, ModalState prior, ModalState state, CycleOrigin origin, boolean thread) {
        if (state.nose() != NoseSide.OFF || prior.nose() != NoseSide.OFF) {
            noseInfo.put(made, new NoseInfo(state.nose(), profile.nose(state.toolOffset()),
                    state.toolOffset(), b.words().isEmpty() ? b.last() : b.words().get(0).span(), made.origin(),
                    NoseConflict.suspend(b, functions, prior.nose(), origin == null ? null : origin.cycle(), thread)));
        }
    }

    /** The blocks {@code b} made, as they go out, with {@code state} the state after them. */
    List<CheckedBlock> release(RawBlock b, List<CheckedBlock> checked, ModalState state) {
        List<CheckedBlock> made = compensated(b, checked, state);
        if (threadChain.idle()) {
            ThreadRunIn.check(made, profile, out);
            return made; // no G32 held or made: nothing to join
        }
        List<CheckedBlock> emit = new ArrayList<>(made.size() + 1);
        threadChain.accept(made, emit);
        if (state.ended()) {
            threadChain.end(emit);
        }
        ThreadRunIn.check(emit, profile, out); // a continuous G32 thread as one pass, once joined
        return emit;
    }

    /** The blocks through the nose radius compensation (G41/G42), which may hold some back. */
    private List<CheckedBlock> compensated(RawBlock b, List<CheckedBlock> made, ModalState state) {
        if (noseInfo.isEmpty() && !nose.active()) {
            return made; // no G41/G42 before or in these blocks: nothing to offset, nothing held
        }
        List<CheckedBlock> emit = new ArrayList<>(made.size() + 1);
        for (CheckedBlock c : made) {
            NoseInfo info = noseInfo.get(c);
            nose.accept(c, info != null ? info : new NoseInfo(NoseSide.OFF,
                    profile.nose(state.toolOffset()), state.toolOffset(), Span.of(c.line(), 1), c.origin()), emit);
        }
        noseInfo.clear();
        if (state.ended()) {
            nose.end(b.words().isEmpty() ? b.last() : b.words().get(0).span(), emit);
        }
        return emit;
    }

    /** End of the program: the compensation still in force ends there (nothing can be sent after the end). */
    void finish(int lastLine) {
        if (nose.active()) {
            nose.end(Span.of(Math.max(1, lastLine), 1), new ArrayList<>());
        }
    }
}
