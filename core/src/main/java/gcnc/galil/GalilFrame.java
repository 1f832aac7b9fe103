package gcnc.galil;

import gcnc.ir.Point;
import gcnc.machine.MachineProfile;

/**
 * The profile's axis mapping: which lathe axis is the vector plane's first channel, the signs,
 * and the channel letters. A Galil coordinate is sign x machine counts; the plane's channels are
 * listed in Galil channel order (A/X, B/Y, C/Z, D/W, E..H), and CR angles are measured in that
 * (first, second) plane, counter-clockwise positive.
 */
public final class GalilFrame {
    private final boolean xFirst;
    private final int xSign;
    private final int zSign;
    private final String plane;
    private final int spindleIndex;

    public GalilFrame(MachineProfile p) {
        int xi = channel(p.x().galil());
        int zi = channel(p.z().galil());
        if (xi == zi) {
            throw new IllegalArgumentException("lathe X and Z on the same Galil channel " + p.x().galil());
        }
        xFirst = xi < zi;
        xSign = p.x().sign();
        zSign = p.z().sign();
        plane = xFirst ? "" + p.x().galil() + p.z().galil() : "" + p.z().galil() + p.x().galil();
        spindleIndex = channel(p.spindleAxis());
    }

    /** 0 for A or X, 1 for B or Y, 2 for C or Z, 3 for D or W, 4.. for E..H ({@link gcnc.dmc.Channels#index}). */
    public static int channel(char letter) {
        int i = gcnc.dmc.Channels.index(letter);
        if (i < 0) {
            throw new IllegalArgumentException("not a Galil channel: " + letter);
        }
        return i;
    }

    /** The two vector channels in Galil order, e.g. {@code XY}. */
    public String plane() {
        return plane;
    }

    /** Position of the spindle channel in an OF command (0 = first field). */
    public int spindleIndex() {
        return spindleIndex;
    }

    /** First plane coordinate of a machine-frame displacement or point. */
    public double u(double x, double z) {
        return xFirst ? xSign * x : zSign * z;
    }

    /** Second plane coordinate. */
    public double v(double x, double z) {
        return xFirst ? zSign * z : xSign * x;
    }

    public double u(Point p) {
        return u(p.x(), p.z());
    }

    public double v(Point p) {
        return v(p.x(), p.z());
    }

    /**
     * +1 when the map from the lathe drawing (z right, x up) to the Galil plane keeps the sense of
     * rotation, -1 when it mirrors it: the determinant of the map's matrix. A counter-clockwise
     * arc in the drawing sweeps {@code handedness()} x its angle in Galil's convention.
     */
    public int handedness() {
        // (z, x) -> (u, v): z-first = diag(zSign, xSign); x-first = [[0, xSign], [zSign, 0]].
        return xFirst ? -xSign * zSign : xSign * zSign;
    }
}
