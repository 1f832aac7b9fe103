package gcnc.check;

import gcnc.check.cycle.Axes;
import gcnc.check.cycle.CycleCall;
import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
import gcnc.check.cycle.Roughing;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * G70: the stored contour's blocks followed again as ordinary blocks (their F and S apply; what
 * reading them ahead reported is not repeated), then a rapid return to the start point, first
 * along the axis that leaves the part.
 */
final class Finishing {
    private final CycleHost host;

    Finishing(CycleHost host) {
        this.host = host;
    }

    /**
     * The G70's checked blocks over {@code blocks}, the contour of a G71/G72 that cut along
     * {@code axes} with its start on the {@code depthSign} side.
     */
    List<CheckedBlock> expand(CycleCall call, int line, List<RawBlock> blocks, Axes axes, int depthSign) {
        ModalState start = host.state();
        Point a = start.position();
        CycleOrigin origin = new CycleOrigin(call.name(), 1, 1, line, call.label(Letter.P), call.label(Letter.Q), true);
        List<CheckedBlock> done = new ArrayList<>();
        // as the blocks would be checked where they stand: a block with an error is reported and the
        // checker goes on from the state it keeps (a G41/G42 block is followed without it)
        for (RawBlock b : blocks) {
            host.one(b, false, origin).ifPresent(done::add);
        }
        Point at = host.state().position();
        MoveWriter writer = new MoveWriter(CycleBlocks.frame(host, host.state()), line, call.g().span());
        CycleOrigin back = new CycleOrigin(call.name(), 1, 1, line, call.label(Letter.P), call.label(Letter.Q), false);
        for (Move m : Roughing.back(at, a, axes, depthSign, 1)) {
            Optional<CheckedBlock> r = host.one(writer.block(m, at), false, back);
            if (r.isEmpty()) {
                break;
            }
            done.add(r.get());
            at = host.state().position();
        }
        return done;
    }
}
