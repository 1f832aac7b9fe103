package gcnc.dmc;

import gcnc.diag.Origin;

/**
 * Where an instruction comes from: the G-code file and calls ({@link Origin#PROGRAM}: the main
 * program), the G-code line (0: the program's header and footer, from no block), the index of the
 * block's motion it carries out (-1: none, e.g. a spindle or output command), and which block of
 * the run it is, counted from 0 in the order the blocks were run (-1: not known, a file read back).
 * A line run twice (a loop, a cycle's passes, a subprogram called again) is two blocks.
 */
public record Source(Origin origin, int line, int motion, long block) {
    /** The header and footer: from no block. */
    public static final Source NONE = new Source(Origin.PROGRAM, 0, -1, -1);

    public Source {
        java.util.Objects.requireNonNull(origin);
    }

    /** A source whose block is not counted. */
    public Source(Origin origin, int line, int motion) {
        this(origin, line, motion, -1);
    }

    /** A line of the main program, no motion (a replay of a DMC file by itself knows no more). */
    public static Source line(int line) {
        return new Source(Origin.PROGRAM, line, -1);
    }

    /** The file the line is in: null for the program's own file. */
    public String file() {
        return origin.file();
    }
}
