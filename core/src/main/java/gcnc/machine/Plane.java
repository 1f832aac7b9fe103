package gcnc.machine;

/**
 * The vector plane and its mapping to the lathe: Galil coordinate = sign x machine counts, the
 * plane's first channel is the lower Galil channel (A before B, as {@code VM} lists them; X=A,
 * Y=B, Z=C, W=D). One type for the simulator's replay and the sender's positions, so that the two
 * cannot map a point differently. An arc's sweep keeps its sign in the machine drawing (z right,
 * x up) when the mapping keeps handedness ({@link #handedness}).
 *
 * @param letters the profile's two channel letters in channel order, as it wrote them (e.g. {@code XY})
 * @param xFirst  lathe X is the first channel (else lathe Z is)
 * @param xSign   the sign of lathe X on its channel
 * @param zSign   the sign of lathe Z on its channel
 */
public record Plane(String letters, boolean xFirst, int xSign, int zSign) {
    /** The letters Galil names the channels by in a DMC program: X Y Z W, then E..H. */
    private static final String LETTERS = "XYZWEFGH";

    /** The profile's plane; its axes on two different channels (the profile's reader refuses the rest). */
    public static Plane of(MachineProfile p) {
        char x = p.x().galil();
        char z = p.z().galil();
        if (channel(x) < 0 || channel(z) < 0 || channel(x) == channel(z)) {
            throw new IllegalArgumentException("lathe X and Z must be two Galil channels, not " + x + " and " + z);
        }
        boolean xFirst = channel(z) > channel(x);
        return new Plane(xFirst ? "" + x + z : "" + z + x, xFirst, p.x().sign(), p.z().sign());
    }

    /**
     * The channel index of a Galil axis letter: X Y Z W = A B C D = 0 1 2 3, E..H = 4..7. Upper
     * case only, as the profile and the DMC name channels; -1 for any other character.
     */
    public static int channel(char c) {
        return switch (c) {
            case 'X' -> 0;
            case 'Y' -> 1;
            case 'Z' -> 2;
            case 'W' -> 3;
            default -> c >= 'A' && c <= 'H' ? c - 'A' : -1;
        };
    }

    /** The letter a DMC program names channel {@code index} (0..7) by: X Y Z W E F G H. */
    public static char letter(int index) {
        return LETTERS.charAt(index);
    }

    /** Whether two letters name the same channel ({@code A} and {@code X}). */
    public static boolean sameChannel(char a, char b) {
        return channel(a) >= 0 && channel(a) == channel(b);
    }

    /** Channel index (A/X = 0 ... H = 7) of the plane's first channel. */
    public int first() {
        return channel(letters.charAt(0));
    }

    /** Channel index of the plane's second channel. */
    public int second() {
        return channel(letters.charAt(1));
    }

    /** Do the letters of a VM/SH argument name the same two channels (any order, any alias)? */
    public boolean sameChannels(String arg) {
        if (arg.length() != 2) {
            return false;
        }
        int a = channel(arg.charAt(0));
        int b = channel(arg.charAt(1));
        int p = first();
        int q = second();
        return a >= 0 && a < 8 && b >= 0 && b < 8 && (a == p && b == q || a == q && b == p);
    }

    /** Machine X counts (a radius) of the Galil plane point (g1, g2). */
    public double machineX(double g1, double g2) {
        return xSign * (xFirst ? g1 : g2);
    }

    /** Machine Z counts of the Galil plane point (g1, g2). */
    public double machineZ(double g1, double g2) {
        return zSign * (xFirst ? g2 : g1);
    }

    /** Machine counts (lathe X as a radius, Z) of a point in Galil plane coordinates. */
    public double[] machine(double[] galil) {
        return new double[] {machineX(galil[0], galil[1]), machineZ(galil[0], galil[1])};
    }

    /** The first Galil plane coordinate of machine counts. */
    public double galil1(double x, double z) {
        return xFirst ? xSign * x : zSign * z;
    }

    /** The second Galil plane coordinate of machine counts. */
    public double galil2(double x, double z) {
        return xFirst ? zSign * z : xSign * x;
    }

    /** The first Galil plane coordinate of a point in machine counts. */
    public double galil1(gcnc.ir.Point p) {
        return galil1(p.x(), p.z());
    }

    /** The second Galil plane coordinate of a point in machine counts. */
    public double galil2(gcnc.ir.Point p) {
        return galil2(p.x(), p.z());
    }

    /** Galil plane coordinates of machine counts. */
    public double[] galil(double x, double z) {
        return new double[] {galil1(x, z), galil2(x, z)};
    }

    /** +1 when a counter-clockwise Galil arc is counter-clockwise in the machine drawing. */
    public int handedness() {
        return xFirst ? -xSign * zSign : xSign * zSign;
    }
}
