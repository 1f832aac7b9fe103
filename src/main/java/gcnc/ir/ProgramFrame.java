package gcnc.ir;

/**
 * Where a block's program coordinates are in the machine, so that a finding can be given the way
 * the program is written (X as a diameter, Z from work zero, in the block's units) besides the
 * machine frame.
 *
 * @param origin    the block's work zero, machine counts (work offset + tool offset + G50/G92 shift)
 * @param perX      counts per programmed unit of X (half a unit's counts where X is a diameter)
 * @param perZ      counts per programmed unit of Z
 * @param sequence  the block's N word as written ("N110"), or "" when it has none
 */
public record ProgramFrame(Point origin, double perX, double perZ, String sequence) {
}
