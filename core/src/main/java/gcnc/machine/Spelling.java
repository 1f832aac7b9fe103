package gcnc.machine;

import java.util.List;
import java.util.Optional;

/**
 * The known key a misspelt one was meant to be, for the message of an unknown key. A key is
 * typed by hand, so the likely mistakes are a letter or two wrong, missing, doubled or swapped
 * ({@code x.counts_per_m}), or the right name under a prefix of its own ({@code lathe.home},
 * {@code turret.count}).
 */
final class Spelling {
    /** How many edits still count as a misspelling rather than another word. */
    static final int MAX_EDITS = 2;

    private Spelling() {
    }

    /** A typo of a known key, else a known key with the same last part; empty when nothing is close. */
    static Optional<String> suggest(String key, List<String> known) {
        Optional<String> typo = typo(key, known);
        return typo.isPresent() ? typo : sameLastPart(key, known);
    }

    /** The nearest known key within {@link #MAX_EDITS} edits of {@code key} (the first on a tie). */
    static Optional<String> typo(String key, List<String> known) {
        return nearest(key, known, k -> distance(key, k) <= MAX_EDITS);
    }

    /** The nearest known key whose last dot-separated part is {@code key}'s ({@code lathe.home}: home). */
    static Optional<String> sameLastPart(String key, List<String> known) {
        return nearest(key, known, k -> lastPart(k).equals(lastPart(key)));
    }

    private static Optional<String> nearest(String key, List<String> known, java.util.function.Predicate<String> close) {
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String k : known) {
            int d = distance(key, k);
            if (close.test(k) && d < bestDistance) {
                best = k;
                bestDistance = d;
            }
        }
        return Optional.ofNullable(best);
    }

    private static String lastPart(String key) {
        return key.substring(key.lastIndexOf('.') + 1);
    }

    /**
     * Edits from {@code a} to {@code b}: characters inserted, deleted, replaced, or two neighbours
     * swapped (optimal string alignment distance), ignoring case.
     */
    static int distance(String a, String b) {
        String s = a.toLowerCase(java.util.Locale.ROOT);
        String t = b.toLowerCase(java.util.Locale.ROOT);
        int[][] d = new int[s.length() + 1][t.length() + 1];
        for (int i = 0; i <= s.length(); i++) {
            d[i][0] = i;
        }
        for (int j = 0; j <= t.length(); j++) {
            d[0][j] = j;
        }
        for (int i = 1; i <= s.length(); i++) {
            for (int j = 1; j <= t.length(); j++) {
                int cost = s.charAt(i - 1) == t.charAt(j - 1) ? 0 : 1;
                d[i][j] = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && s.charAt(i - 1) == t.charAt(j - 2) && s.charAt(i - 2) == t.charAt(j - 1)) {
                    d[i][j] = Math.min(d[i][j], d[i - 2][j - 2] + 1);
                }
            }
        }
        return d[s.length()][t.length()];
    }
}
