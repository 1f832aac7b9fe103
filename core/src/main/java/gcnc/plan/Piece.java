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
 * start). A straight move longer than the controller takes in one segment is split into
 * {@code parts} equal pieces ({@link SegmentLimit}), this one number {@code part} (0 for the first);
 * a move that fits is part 0 of 1.
 */
public record Piece(CheckedBlock block, int motion, double speed, double exit, double length, boolean spindle,
                    List<Switch> switches, int part, int parts) {
    public Piece {
        switches = List.copyOf(switches);
    }

    /** A whole motion (one part). */
    public Piece(CheckedBlock block, int motion, double speed, double exit, double length, boolean spindle,
                 List<Switch> switches) {
        this(block, motion, speed, exit, length, spindle, switches, 0, 1);
    }

    public Motion path() {
        return block.motions().get(motion);
    }

    /** Whether anything is set as the tool reaches the piece's start (an {@code AV} trip point). */
    public boolean onTheWay() {
        return spindle || !switches.isEmpty();
    }
}
