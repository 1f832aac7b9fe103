package gcnc.sim;

import gcnc.machine.MachineProfile;

/**
 * The vector plane and its mapping to the lathe: Galil coordinate = sign x machine counts, the
 * plane's first channel is the lower Galil channel (A before B; X=A, Y=B, Z=C, W=D). An arc's
 * sweep keeps its sign in the machine drawing (z right, x up) when the mapping keeps handedness.
 */
final class Plane {
    final boolean firstIsZ;
    final int signX;
    final int signZ;
    final String letters;

    Plane(MachineProfile p) {
        signX = p.x().sign();
        signZ = p.z().sign();
        int cx = channel(p.x().galil());
        int cz = channel(p.z().galil());
        firstIsZ = cz < cx;
        letters = firstIsZ ? "" + p.z().galil() + p.x().galil() : "" + p.x().galil() + p.z().galil();
    }

    /** A=0 .. H=7, with X/Y/Z/W as A/B/C/D. */
    static int channel(char c) {
        return switch (c) {
            case 'X' -> 0;
            case 'Y' -> 1;
            case 'Z' -> 2;
            case 'W' -> 3;
            default -> c - 'A';
        };
    }

    /** Do the letters of a VM/SH argument name the same two channels (any order, any alias)? */
    boolean sameChannels(String arg) {
        if (arg.length() != 2) {
            return false;
        }
        int a = channel(arg.charAt(0));
        int b = channel(arg.charAt(1));
        int p = channel(letters.charAt(0));
        int q = channel(letters.charAt(1));
        return a >= 0 && a < 8 && b >= 0 && b < 8 && (a == p && b == q || a == q && b == p);
    }

    double machineX(double g1, double g2) {
        return signX * (firstIsZ ? g2 : g1);
    }

    double machineZ(double g1, double g2) {
        return signZ * (firstIsZ ? g1 : g2);
    }

    double galil1(double x, double z) {
        return firstIsZ ? signZ * z : signX * x;
    }

    double galil2(double x, double z) {
        return firstIsZ ? signX * x : signZ * z;
    }

    /** +1 when a counter-clockwise Galil arc is counter-clockwise in the machine drawing. */
    int handedness() {
        return firstIsZ ? signX * signZ : -signX * signZ;
    }

    /**
     * The arc a Galil {@code CR r,start,sweep} draws from the Galil-plane position (p1, p2), as the
     * controller derives it: the centre from the start angle, the end from start + sweep. One
     * place for the replay ({@code ReplayController}) and for check's prediction of it
     * ({@code ArcVerdict}), so that the two cannot differ. {@code end} receives the end in the
     * Galil plane (first, second channel).
     */
    Segment cr(double p1, double p2, double r, double startDeg, double sweepDeg, gcnc.dmc.Instruction instruction, double[] end) {
        double[] g = gcnc.dmc.Command.CircularArc.geometry(p1, p2, r, startDeg, sweepDeg);
        double c1 = g[0];
        double c2 = g[1];
        end[0] = g[2];
        end[1] = g[3];
        double fx = machineX(p1, p2);
        double fz = machineZ(p1, p2);
        double cx = machineX(c1, c2);
        double cz = machineZ(c1, c2);
        double from = Math.toDegrees(Math.atan2(fx - cx, fz - cz));
        return new Segment(fx, fz, machineX(end[0], end[1]), machineZ(end[0], end[1]), true, cx, cz, r, from,
                sweepDeg * handedness(), instruction);
    }
}
