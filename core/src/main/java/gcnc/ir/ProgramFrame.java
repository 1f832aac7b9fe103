package gcnc.ir;

/**
 * Where a block's program coordinates are in the machine, so that a finding can be given the way
 * the program is written (X as a diameter, Z from work zero, in the block's units) besides the
 * machine frame.
 *
 * @param origin  the block's work zero, machine counts (work offset + tool offset + G50/G92 shift)
 * @param perX    counts per programmed unit of X (half a unit's counts where X is a diameter)
 * @param perZ    counts per programmed unit of Z
 * @param number  the number of the block's N word as written ("110"), or null when it has none
 * @param pass    what made the block when a cycle did ("G71 pass 4 of 9"), else null
 * @param file    the file the block is written in when it is not the program's own (a called
 *                program beside it, {@code O1000.nc}), else null; so that a drawn move can be
 *                linked to its line in its file
 */
public record ProgramFrame(Point origin, double perX, double perZ, String number, String pass, String file) {
    /** A frame of a block of the program's own file. */
    public ProgramFrame(Point origin, double perX, double perZ, String number, String pass) {
        this(origin, perX, perZ, number, pass, null);
    }

    /** The same frame for a block written in {@code other} (null: the program's own file). */
    public ProgramFrame inFile(String other) {
        return java.util.Objects.equals(other, file) ? this : new ProgramFrame(origin, perX, perZ, number, pass, other);
    }

    /**
     * How a finding names the block: "N110", "N110 G71 pass 4 of 9", "G71 pass 4 of 9", or "" when
     * there is nothing to say. Made here, when a finding asks, not for every block.
     */
    public String sequence() {
        String n = number == null ? "" : "N" + number;
        return pass == null ? n : n.isEmpty() ? pass : n + " " + pass;
    }

    /** The same frame for a block a cycle made. */
    public ProgramFrame inPass(String name) {
        return new ProgramFrame(origin, perX, perZ, number, name, file);
    }
}
