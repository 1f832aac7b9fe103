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
}
