package gcnc.parse;

/**
 * The number texts of a program's words, one String per distinct text recently read rather than
 * one per word: a program repeats its numbers (G01, Z2., F120., R1.), and a word's text was two
 * objects per word (the String and its bytes), the largest allocation of a check after the words
 * themselves. A text is kept in one of a fixed number of slots by its hash; a newer text with the
 * same slot takes it. Strings are values, so a shared one is the same as a copy to every reader.
 * N and O numbers, which a program does not repeat, are not kept (they would only push the others
 * out).
 */
final class NumberTexts {
    private static final int SLOTS = 1024; // a power of two
    private final String[] slots = new String[SLOTS];

    /** The text of {@code buf[from, to)}. */
    String text(char[] buf, int from, int to) {
        int h = 0;
        for (int i = from; i < to; i++) {
            h = 31 * h + buf[i];
        }
        int slot = (h ^ h >>> 16) & (SLOTS - 1);
        String kept = slots[slot];
        if (kept != null && same(kept, buf, from, to)) {
            return kept;
        }
        String s = new String(buf, from, to - from);
        slots[slot] = s;
        return s;
    }

    private static boolean same(String s, char[] buf, int from, int to) {
        if (s.length() != to - from) {
            return false;
        }
        for (int i = from; i < to; i++) {
            if (s.charAt(i - from) != buf[i]) {
                return false;
            }
        }
        return true;
    }
}
