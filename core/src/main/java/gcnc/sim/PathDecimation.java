package gcnc.sim;

import java.util.Arrays;

/**
 * What {@link PathRecorder} does to a tool path that would not fit its budget: a polyline's points
 * that lie within a tolerance of the segment between the points kept either side of them go
 * (Douglas-Peucker, with an explicit stack: a polyline of a million points does not recurse a
 * million deep), and a polyline that, snapped to a grid of that tolerance, is one already kept
 * adds nothing that can be seen and is known by a 64-bit hash of its snapped points.
 */
final class PathDecimation {
    private PathDecimation() {
    }

    /**
     * The points of (z, r) to keep within {@code tol}: the two ends always, an inner point only
     * where it lies more than {@code tol} from the segment between its kept neighbours. Returns
     * {z, r}, the input arrays themselves when every point stays.
     */
    static double[][] decimate(double[] z, double[] r, double tol) {
        int n = z.length;
        if (n <= 2 || !(tol > 0)) {
            return new double[][] {z, r};
        }
        boolean[] keep = new boolean[n];
        keep[0] = true;
        keep[n - 1] = true;
        int[] stack = new int[64];
        int top = 0;
        stack[top++] = 0;
        stack[top++] = n - 1;
        int kept = 2;
        while (top > 0) {
            int j = stack[--top];
            int i = stack[--top];
            int far = -1;
            double most = tol;
            for (int k = i + 1; k < j; k++) {
                double d = distance(z[k], r[k], z[i], r[i], z[j], r[j]);
                if (d > most) {
                    most = d;
                    far = k;
                }
            }
            if (far < 0) {
                continue;
            }
            keep[far] = true;
            kept++;
            if (top + 4 > stack.length) {
                stack = Arrays.copyOf(stack, 2 * stack.length);
            }
            stack[top++] = i;
            stack[top++] = far;
            stack[top++] = far;
            stack[top++] = j;
        }
        if (kept == n) {
            return new double[][] {z, r};
        }
        double[] oz = new double[kept];
        double[] or = new double[kept];
        for (int k = 0, m = 0; k < n; k++) {
            if (keep[k]) {
                oz[m] = z[k];
                or[m++] = r[k];
            }
        }
        return new double[][] {oz, or};
    }

    /** Distance from (pz, pr) to the segment from (az, ar) to (bz, br). */
    static double distance(double pz, double pr, double az, double ar, double bz, double br) {
        double dz = bz - az;
        double dr = br - ar;
        double len2 = dz * dz + dr * dr;
        double t = len2 == 0 ? 0 : Math.max(0, Math.min(1, ((pz - az) * dz + (pr - ar) * dr) / len2));
        return Math.hypot(pz - (az + t * dz), pr - (ar + t * dr));
    }

    /** A 64-bit hash of the polyline snapped to a grid of {@code tol}, with its kind and tool. */
    static long snappedHash(boolean rapid, int tool, double[] z, double[] r, double tol) {
        long h = rapid ? 0x51afd7ed558ccdL : 0x4cf5ad432745937fL;
        h = mix(h ^ tool);
        for (int i = 0; i < z.length; i++) {
            h = mix(h ^ Math.round(z[i] / tol));
            h = mix(h ^ Math.round(r[i] / tol));
        }
        return h;
    }

    /** The 64-bit finaliser of MurmurHash3. */
    private static long mix(long k) {
        k ^= k >>> 33;
        k *= 0xff51afd7ed558ccdL;
        k ^= k >>> 33;
        k *= 0xc4ceb9fe1a85ec53L;
        k ^= k >>> 33;
        return k;
    }

    /** A set of longs, open addressing, for the hashes of the polylines kept. */
    static final class LongSet {
        private long[] slots = new long[1024];
        private boolean zero;
        private int size;

        /** Adds v; false if it was there already. */
        boolean add(long v) {
            if (v == 0) {
                boolean fresh = !zero;
                zero = true;
                return fresh;
            }
            if (2 * (size + 1) > slots.length) {
                grow();
            }
            int mask = slots.length - 1;
            for (int i = (int) v & mask; ; i = (i + 1) & mask) {
                if (slots[i] == v) {
                    return false;
                }
                if (slots[i] == 0) {
                    slots[i] = v;
                    size++;
                    return true;
                }
            }
        }

        private void grow() {
            long[] old = slots;
            slots = new long[2 * old.length];
            int mask = slots.length - 1;
            for (long v : old) {
                if (v != 0) {
                    int i = (int) v & mask;
                    while (slots[i] != 0) {
                        i = (i + 1) & mask;
                    }
                    slots[i] = v;
                }
            }
        }
    }
}
