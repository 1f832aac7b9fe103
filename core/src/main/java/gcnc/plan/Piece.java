package gcnc.plan;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;

/**
 * One motion of a planned sequence: the block it belongs to, its index among the block's motions,
 * the speeds the planner gave it, counts/s ({@code speed} to run at, {@code exit} to reach at its
 * end: the corner into the next piece, 0 for the sequence's last piece, which stops), its length
 * (counts, along the path) and whether its block's new spindle speed (G96 at this diameter) is set
 * as the tool reaches its start, without stopping.
 */
public record Piece(CheckedBlock block, int motion, double speed, double exit, double length, boolean spindle) {
    public Motion path() {
        return block.motions().get(motion);
    }
}
