package gcnc.flow;

import gcnc.diag.Origin;
import gcnc.diag.Span;

/**
 * One program being run: what it is, where it is, how many more times it runs, its loops, and
 * where its findings go. The main program, a called program (M98, or G65 with locals of its own),
 * or the blocks of the program it is called from, from an N label on (Haas M97).
 */
final class Frame {
    final Blocks blocks;
    /** What runs, as messages name it: "O1000", "N100" (an M97 local call); null for the main program. */
    final String name;
    /** The file it is written in; null: the program's own. */
    final String file;
    /** Where it starts (its O word or N label), for E140. */
    final Span start;
    /** The index of its first block: 0, or the label's for M97. */
    final int first;
    final Origin origin;
    int next;
    int repeats;
    boolean returning;
    /** For loop ids 1-3: the index of its WHILE (-1: none), how many turns since it was entered. */
    final int[] whileAt = {-1, -1, -1, -1};
    final int[] turns = new int[4];
    /** The last jump was an END going back to its WHILE. */
    boolean cameBack;
    /** A macro call's program (G65): it has a level of local variables of its own, left when it returns. */
    boolean ownLocals;

    Frame(Blocks blocks, String name, String file, Span start, int first, Origin origin, int repeats) {
        this.blocks = blocks;
        this.name = name;
        this.file = file;
        this.start = start;
        this.first = first;
        this.origin = origin;
        this.repeats = repeats;
        this.next = first;
    }

    /** The main program. */
    static Frame main(Blocks blocks) {
        return new Frame(blocks, null, null, Span.of(1, 1), 0, Origin.PROGRAM, 1);
    }

    boolean isMain() {
        return name == null;
    }

    /** Runs again from its start (the next repeat). */
    void restart() {
        next = first;
        returning = false;
        java.util.Arrays.fill(whileAt, -1);
        cameBack = false;
    }
}
