package gcnc.flow;

import gcnc.diag.Origin;

/** One program being run: where it is, how many more times it runs, its loops, and where its findings go. */
final class Frame {
    final Blocks blocks;
    /** Null for the main program. */
    final Program program;
    final Origin origin;
    int next;
    int repeats;
    boolean returning;
    /** For loop ids 1-3: the index of its WHILE (-1: none), how many turns since it was entered. */
    final int[] whileAt = {-1, -1, -1, -1};
    final int[] turns = new int[4];
    /** The last jump was an END going back to its WHILE. */
    boolean cameBack;

    Frame(Blocks blocks, Program program, Origin origin, int repeats) {
        this.blocks = blocks;
        this.program = program;
        this.origin = origin;
        this.repeats = repeats;
    }

    /** Runs the program again from its start (the next repeat). */
    void restart() {
        next = 0;
        returning = false;
        java.util.Arrays.fill(whileAt, -1);
        cameBack = false;
    }
}
