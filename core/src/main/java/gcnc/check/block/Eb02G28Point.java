package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.diag.Diagnostics;
import gcnc.ir.Point;

/**
 * Thesis end-of-block operation 2: G28 remembers its intermediate point (for G29). The point is
 * the block's X/Z (G90/G91) or U/W, in machine counts; it must be inside the travel (E015).
 * The thesis's G28 fell through into G29 and forgot it (§12.7). Emits E015. Writes next.g28.
 */
public final class Eb02G28Point implements BlockCheck {
    @Override
    public void run(BlockDraft d, Diagnostics out) {
        if (d.function != 28) {
            return;
        }
        Point via = d.coordinates.target(d, d.prior.position());
        if (d.coordinates.beyondTravel(d, via, d.coordinates.origin(d.next), out)) {
            return;
        }
        d.next.g28 = via;
    }
}
