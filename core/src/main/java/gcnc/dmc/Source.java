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

    /*
     * equals and hashCode written out, the same as a record's: the generated ones are linked on
     * first use by spinning method-handle classes (19 of them, 20-40 ms of a cold compile, in the
     * simulator's first sequence), and this is the record a compile compares first and most.
     */
    @Override
    public boolean equals(Object o) {
        return o instanceof Source s && line == s.line && motion == s.motion && block == s.block
                && (origin == s.origin || origin.equals(s.origin)); // most share one Origin
    }

    @Override
    public int hashCode() {
        return ((origin.hashCode() * 31 + Integer.hashCode(line)) * 31 + Integer.hashCode(motion)) * 31
                + Long.hashCode(block);
    }
}
