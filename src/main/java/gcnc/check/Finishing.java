package gcnc.check;

import gcnc.check.cycle.Axes;
import gcnc.check.cycle.CycleCall;
import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
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
    private final Checker host;

    Finishing(Checker host) {
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
        for (RawBlock b : blocks) {
            Optional<CheckedBlock> r = host.one(b, false, origin);
            if (r.isEmpty()) {
                return done;
            }
            done.add(r.get());
        }
        Point at = host.state().position();
        Axes ax = axes;
        boolean endsOutside = (ax.depth(at) - ax.depth(a)) * depthSign >= 0;
        Point corner = endsOutside ? ax.point(ax.depth(at), ax.cut(a)) : ax.point(ax.depth(a), ax.cut(at));
        MoveWriter writer = new MoveWriter(CycleExpansion.frame(host, host.state()), line, call.g().span());
        CycleOrigin back = new CycleOrigin(call.name(), 1, 1, line, call.label(Letter.P), call.label(Letter.Q), false);
        for (Point to : new Point[] {corner, a}) {
            if (to.distanceTo(at) <= 1e-9) {
                continue;
            }
            Optional<CheckedBlock> r = host.one(writer.block(Move.line(true, to, 1), at), false, back);
            if (r.isEmpty()) {
                break;
            }
            done.add(r.get());
            at = host.state().position();
        }
        return done;
    }
}
