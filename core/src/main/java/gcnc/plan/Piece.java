package gcnc.plan;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import java.util.List;

/**
 * One motion of a planned sequence: the block it belongs to, its index among the block's motions,
 * the speeds the planner gave it, counts/s ({@code speed} to run at, {@code exit} to reach at its
 * end: the corner into the next piece, 0 for the sequence's last piece, which stops), its length
 * (counts, along the path), whether its block's new spindle speed (G96 at this diameter) is set
 * as the tool reaches its start, without stopping, and the outputs switched there ({@code switches},
 * in program order: the end of the block before, blocks without motion between, then this block's
 * start).
 */
public record Piece(CheckedBlock block, int motion, double speed, double exit, double length, boolean spindle,
                    List<Switch> switches) {
    public Piece {
        switches = List.copyOf(switches);
    }

    public Motion path() {
        return block.motions().get(motion);
    }

    /** Whether anything is set as the tool reaches the piece's start (an {@code AV} trip point). */
    public boolean onTheWay() {
        return spindle || !switches.isEmpty();
    }
}
