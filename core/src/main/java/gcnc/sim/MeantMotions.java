package gcnc.sim;

import gcnc.ir.ProgramFrame;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Objects;
import java.util.function.IntFunction;

/**
 * The motions of the program a started sequence carries out: its segments cut into runs, one run
 * for each DMC source in a row, each matched to the motion the checker meant there. Kept and reused
 * from one sequence to the next (a sequence is a handful of segments); for {@link Simulator}.
 */
final class MeantMotions {
    /** The motions the last sequence carried out, in order; the segments of motion k are runFrom[k] to runTo[k]. */
    private final List<ExpectedMotions.Expected> meant = new ArrayList<>();
    private int[] runFrom = new int[8];
    private int[] runTo = new int[8];
    private int segments;

    /**
     * Cuts {@code sequence} into its runs and matches each to a motion meant ({@code expected}; null:
     * a bare replay, nothing meant). Returns how many runs no motion of the program asked for (E311 each).
     */
    int match(List<Segment> sequence, ExpectedMotions expected) {
        meant.clear();
        segments = sequence.size();
        if (expected == null) {
            return 0;
        }
        int unasked = 0;
        for (int i = 0; i < sequence.size(); ) {
            gcnc.dmc.Source from = sequence.get(i).source();
            int j = i + 1;
            while (j < sequence.size() && Objects.equals(sequence.get(j).source(), from)) {
                j++;
            }
            ExpectedMotions.Expected e = expected.match(from, sequence.get(i), sequence.get(j - 1));
            if (e == null) {
                unasked++;
            } else {
                int k = meant.size();
                if (k == runFrom.length) {
                    runFrom = Arrays.copyOf(runFrom, 2 * k);
                    runTo = Arrays.copyOf(runTo, 2 * k);
                }
                meant.add(e);
                runFrom[k] = i;
                runTo[k] = j;
            }
            i = j;
        }
        return unasked;
    }

    boolean isEmpty() {
        return meant.isEmpty();
    }

    int size() {
        return meant.size();
    }

    ExpectedMotions.Expected get(int k) {
        return meant.get(k);
    }

    /** The segments of motion k: the whole sequence where it is the only one and has them all (no sublist made). */
    List<Segment> run(int k, List<Segment> sequence) {
        return meant.size() == 1 && runFrom[0] == 0 && runTo[0] == sequence.size() ? sequence
                : sequence.subList(runFrom[k], runTo[k]);
    }

    /** Each segment's program frame: its own motion's block's (a sequence of several blocks). */
    ProgramFrame[] frames() {
        ProgramFrame[] frames = new ProgramFrame[segments];
        for (int k = 0; k < meant.size(); k++) {
            Arrays.fill(frames, runFrom[k], runTo[k], meant.get(k).block().frame());
        }
        return frames;
    }

    /**
     * The N word of the last sequence's segment k (null where its block has none, or no motion
     * asked for it), for the corner report, which asks only for the corners it keeps.
     */
    final IntFunction<String> numbers = k -> {
        for (int r = 0; r < meant.size(); r++) {
            if (k >= runFrom[r] && k < runTo[r]) {
                ProgramFrame f = meant.get(r).block().frame();
                return f == null ? null : f.number();
            }
        }
        return null;
    };
}
