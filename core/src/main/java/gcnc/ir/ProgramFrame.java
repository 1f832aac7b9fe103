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
 */
public record ProgramFrame(Point origin, double perX, double perZ, String number, String pass) {

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
        return new ProgramFrame(origin, perX, perZ, number, name);
    }
}
