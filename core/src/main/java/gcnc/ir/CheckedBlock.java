package gcnc.ir;

import gcnc.diag.Origin;
import java.util.List;
import java.util.OptionalDouble;
import java.util.OptionalInt;

/**
 * A block that passed every check, in the order its effects reach the machine (thesis §4.5,
 * decision D2): spindle speed, tool change, the M functions applied at the start, the motions,
 * then the M functions applied at the end.
 *
 * @param line        source line, for source maps and findings
 * @param spindleRpm  the spindle speed to set before the block's motion, if it changes here
 *                    (S word, or G96 constant surface speed at this block's diameter; G50-clamped)
 * @param tool        tool number of a T word in this block
 * @param before      M functions of moments 0 and 1, in source order
 * @param motions     motions in order (empty for a block without motion)
 * @param after       M functions of moment 99, in source order
 * @param end         position after the block, machine counts
 * @param frame       the block's program coordinates in the machine, for findings; null when unknown
 * @param origin      the file and the subprogram calls the block was run from ({@link Origin#PROGRAM}:
 *                    the main program), so that the simulator's findings are placed as the checker's
 * @param stopAt      where the block's motion must end at rest (G09, G61), else {@link StopAt#BLEND}
 */
public record CheckedBlock(int line, OptionalDouble spindleRpm, OptionalInt tool, List<MCall> before,
                           List<Motion> motions, List<MCall> after, Point end, ProgramFrame frame, Origin origin,
                           StopAt stopAt) {
    public CheckedBlock {
        before = List.copyOf(before);
        motions = List.copyOf(motions);
        after = List.copyOf(after);
        java.util.Objects.requireNonNull(origin);
        java.util.Objects.requireNonNull(stopAt);
    }

    /** A block that asks for no exact stop. */
    public CheckedBlock(int line, OptionalDouble spindleRpm, OptionalInt tool, List<MCall> before,
                        List<Motion> motions, List<MCall> after, Point end, ProgramFrame frame, Origin origin) {
        this(line, spindleRpm, tool, before, motions, after, end, frame, origin, StopAt.BLEND);
    }

    /** The same block with other motions ending at {@code end} (a cycle's or the compensation's), its stop kept. */
    public CheckedBlock withMotions(List<Motion> other, Point end) {
        return new CheckedBlock(line, spindleRpm, tool, before, other, after, end, frame, origin, stopAt);
    }

    /** The same block with another program frame (a cycle pass's name), its stop kept. */
    public CheckedBlock inFrame(ProgramFrame other) {
        return new CheckedBlock(line, spindleRpm, tool, before, motions, after, end, other, origin, stopAt);
    }

    /** A block of the main program. */
    public CheckedBlock(int line, OptionalDouble spindleRpm, OptionalInt tool, List<MCall> before,
                        List<Motion> motions, List<MCall> after, Point end, ProgramFrame frame) {
        this(line, spindleRpm, tool, before, motions, after, end, frame, Origin.PROGRAM);
    }

    /** The same block, run from {@code o} (its frame names the file it is written in). */
    public CheckedBlock from(Origin o) {
        return new CheckedBlock(line, spindleRpm, tool, before, motions, after, end,
                frame == null ? null : frame.inFile(o.file()), o, stopAt);
    }

    /** A block whose program frame is not known (built by hand, as the backend's tests do). */
    public CheckedBlock(int line, OptionalDouble spindleRpm, OptionalInt tool, List<MCall> before,
                        List<Motion> motions, List<MCall> after, Point end) {
        this(line, spindleRpm, tool, before, motions, after, end, null);
    }
}
