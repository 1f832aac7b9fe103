package gcnc.plan;

import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import java.util.List;

/**
 * M functions whose outputs switch while the axes move (the profile's {@code plan.on_the_fly}):
 * the block they are written in, the calls, and whether they are the block's end ({@code after},
 * moment 99) or its start. The emitter switches them where the path reaches the piece that carries
 * them ({@code AV <distance>}, then {@code SB}/{@code CB}); when the sequence ends first, they are
 * switched at rest, as its {@link Step.Before} or {@link Step.After}.
 */
public record Switch(CheckedBlock block, List<MCall> calls, boolean after) {
    public Switch {
        calls = List.copyOf(calls);
    }

    /** The step that switches them at rest. */
    Step atRest() {
        return after ? new Step.After(block) : new Step.Before(block);
    }
}
