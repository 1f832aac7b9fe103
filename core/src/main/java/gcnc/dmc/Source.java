package gcnc.dmc;

import gcnc.diag.Origin;

/**
 * Where an instruction comes from: the G-code file and calls ({@link Origin#PROGRAM}: the main
 * program), the G-code line (0: the program's header and footer, from no block), and the index of
 * the block's motion it carries out (-1: none, e.g. a spindle or output command).
 */
public record Source(Origin origin, int line, int motion) {
    /** The header and footer: from no block. */
    public static final Source NONE = new Source(Origin.PROGRAM, 0, -1);

    public Source {
        java.util.Objects.requireNonNull(origin);
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
