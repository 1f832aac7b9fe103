package gcnc.sim;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.PriorityQueue;

/**
 * The slowest corners of a run, at most {@link #KEPT}: the simulator hands it every corner the machine
 * slows for (and every reversal), it keeps the slowest; ties go to the earlier corner.
 */
final class SlowestCorners {
    /** The most corners a report holds (what {@code --corners N} may ask for). */
    static final int KEPT = 100;

    private record Entry(Corner corner, long order) {
    }

    /** The fastest kept corner on top, so that a slower one replaces it. */
    private final PriorityQueue<Entry> kept = new PriorityQueue<>(
            Comparator.comparingDouble((Entry e) -> e.corner().speedMmMin()).thenComparingLong(Entry::order).reversed());
    private long order;

    /** Whether a corner taken at {@code mmPerMin} would be kept: not when as many are kept, none faster (ties: the earlier). */
    boolean keeps(double mmPerMin) {
        return kept.size() < KEPT || mmPerMin < kept.peek().corner().speedMmMin();
    }

    void add(Corner c) {
        kept.add(new Entry(c, order++));
        if (kept.size() > KEPT) {
            kept.poll();
        }
    }

    /** The kept corners, slowest first. */
    List<Corner> slowest() {
        List<Entry> all = new ArrayList<>(kept);
        all.sort(Comparator.comparingDouble((Entry e) -> e.corner().speedMmMin()).thenComparingLong(Entry::order));
        List<Corner> out = new ArrayList<>(all.size());
        for (Entry e : all) {
            out.add(e.corner());
        }
        return out;
    }
}
