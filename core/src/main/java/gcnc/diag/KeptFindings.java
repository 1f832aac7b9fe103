package gcnc.diag;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;

/**
 * The findings {@link Diagnostics} keeps, in the order they were made, each with how many times it
 * was found (E680) and, for a warning folded from other places, how many and on which lines
 * (E115); and their sorted list, those notes in place. What to keep and what to fold is
 * Diagnostics' call; this holds what it kept.
 */
final class KeptFindings {
    /** The most lines E115 lists for a folded warning; past it "...". */
    static final int LATER_LINES = 10;

    private final List<Diagnostic> all = new ArrayList<>();
    /** How many times each kept finding was found (1: once); parallel to {@link #all}. */
    private int[] counts = new int[16];
    /** For a kept warning repeated elsewhere: how many later places, and their lines (the first few). */
    private final Map<Integer, Later> later = new HashMap<>();

    /** The later places of a folded warning, as E115 lists them. */
    private static final class Later {
        int count;
        final StringBuilder lines = new StringBuilder();
    }

    /** Keeps a finding, found once so far; its index. */
    int keep(Diagnostic d) {
        if (all.size() == counts.length) {
            counts = Arrays.copyOf(counts, counts.length * 2);
        }
        counts[all.size()] = 1;
        all.add(d);
        return all.size() - 1;
    }

    /** The finding at {@code at} was found {@code more} times more. */
    void count(int at, int more) {
        counts[at] += more;
    }

    /** The warning at {@code at} was found again on another line (E115). */
    void laterAt(int at, int line) {
        Later l = later.computeIfAbsent(at, k -> new Later());
        l.count++;
        if (l.count <= LATER_LINES) {
            l.lines.append(l.lines.length() == 0 ? "" : ", ").append(line);
        } else if (l.count == LATER_LINES + 1) {
            l.lines.append(", ...");
        }
    }

    Diagnostic get(int k) {
        return all.get(k);
    }

    void set(int k, Diagnostic d) {
        all.set(k, d);
    }

    int size() {
        return all.size();
    }

    boolean isEmpty() {
        return all.isEmpty();
    }

    /**
     * Takes back the warnings and notes {@code which} selects (errors are never taken back), the
     * counts and the folded repeats following the findings that stay; where each finding went
     * (its new index, -1: taken back), by its old index.
     */
    int[] withdraw(Predicate<Diagnostic> which) {
        int[] moved = new int[all.size()];
        List<Diagnostic> kept = new ArrayList<>(all.size());
        int[] keptCounts = new int[counts.length];
        Map<Integer, Later> keptLater = new HashMap<>();
        for (int k = 0; k < all.size(); k++) {
            Diagnostic d = all.get(k);
            if (d.severity() != Severity.ERROR && which.test(d)) {
                moved[k] = -1;
                continue;
            }
            moved[k] = kept.size();
            keptCounts[kept.size()] = counts[k];
            Later l = later.get(k);
            if (l != null) {
                keptLater.put(kept.size(), l);
            }
            kept.add(d);
        }
        all.clear();
        all.addAll(kept);
        counts = keptCounts;
        later.clear();
        later.putAll(keptLater);
        return moved;
    }

    /** Forgets every finding. */
    void clear() {
        all.clear();
        later.clear();
    }

    /**
     * Every finding kept, sorted by file and position (stable: same position keeps reporting order),
     * each found more than once followed by its count (E680).
     */
    List<Diagnostic> sorted() {
        List<Diagnostic> copy = new ArrayList<>(all.size());
        Diagnostic count = null; // the E680 of the last finding, after the notes that go with it
        for (int k = 0; k < all.size(); k++) {
            Diagnostic d = all.get(k);
            if (count != null && (d.severity() != Severity.NOTE || !d.span().equals(count.span()))) {
                copy.add(count);
                count = null;
            }
            copy.add(d);
            Later l = later.get(k);
            if (l != null) {
                copy.add(new Diagnostic(Code.E115_SAME_CAUSE, Severity.NOTE, d.span(),
                        List.of(Integer.toString(l.count), l.lines.toString()), d.origin().withoutCalls()));
            }
            if (counts[k] > 1) {
                count = new Diagnostic(Code.E680_FOLDED, Severity.NOTE, d.span(),
                        List.of(Integer.toString(counts[k])), d.origin().withoutCalls());
            }
        }
        if (count != null) {
            copy.add(count);
        }
        Collections.sort(copy);
        return Collections.unmodifiableList(copy);
    }
}
