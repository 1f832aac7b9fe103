package gcnc.check;

import gcnc.check.geom.Coordinates;
import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import java.util.List;
import java.util.Optional;

/**
 * What a cycle's expansion (G70-G76, G81-G89, G90/G94, G32/G92, G30) may have the checker do: hand
 * it a block it wrote, to be checked and committed like any other ({@link #one}, {@link #thread}),
 * follow one without committing ({@link #dry}), and read the state and the findings. The cycles
 * plan each next move from the state the last one left, so the blocks go through one at a time;
 * only the checker commits a block's state.
 */
interface CycleHost {
    /** The modal state after the last accepted block. */
    ModalState state();

    /** Where the program's findings go. */
    Diagnostics out();

    MachineProfile profile();

    /** The checker's coordinate frames (read here: only the checker writes a work offset, G10). */
    Coordinates coordinates();

    FunctionIndex functions();

    /**
     * One block through every check, committing its state: a block of the program, or one that a
     * cycle made or follows again ({@code origin} not null: its findings get a note saying which
     * pass, and its frame names the pass for the simulator's findings).
     */
    Optional<CheckedBlock> one(RawBlock b, boolean isFirst, CycleOrigin origin);

    /**
     * A thread pass written as a G01 block (its F the lead per revolution), checked like any cut
     * and built as a spindle-synchronised {@link gcnc.ir.Motion.Thread}; {@code thread} names the
     * function ("G32", "G76") for its findings; {@code pullOut}, when not null, ends it with Haas
     * M23's chamfer instead of at the block's end point.
     */
    Optional<CheckedBlock> thread(RawBlock b, boolean isFirst, CycleOrigin origin, String thread, PullOut pullOut);

    /** As above, the pass starting {@code startAngle} degrees past the spindle's whole revolution (Q of G92, Haas G76). */
    Optional<CheckedBlock> thread(RawBlock b, boolean isFirst, CycleOrigin origin, String thread, PullOut pullOut,
                                  double startAngle);

    /**
     * A contour block followed from {@code from} without changing the program's state: its words
     * and geometry checked (not the prerequisites: the cycle's own moves are checked for those),
     * findings to {@code found}; null after its errors.
     */
    Dry dry(RawBlock b, ModalState from, Diagnostics found);

    /** A counted block in the program's flow (a G70 following its contour again). */
    List<CheckedBlock> flow(RawBlock b, boolean isFirst);

    /** A cycle's contour with its chamfers and corners made, followed from {@code from} ({@link CornerInsertion#inContour}). */
    List<RawBlock> cornersInContour(List<RawBlock> blocks, ModalState from);

    /** Where Threading marks its G32 passes for the continuous threads. */
    ThreadChain threadChain();

    /** Reports findings of a block checked outside the flow (a contour read ahead), remembering them. */
    void reportAside(Diagnostics found);
}
