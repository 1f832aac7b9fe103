package gcnc.sim;

/**
 * The workpiece as a radius-versus-Z profile on a fixed grid (constant memory, fine for turning):
 * cell i covers z in [z0 + i*step, z0 + (i+1)*step) and holds the radius of material left at its
 * centre. The tool tip lowers a cell when it passes its centre below the current radius; a rapid
 * that passes a centre more than {@code slack} below the radius there is inside uncut material.
 */
final class StockProfile {
    static final int CELLS = 4096;
    private static final int BLOCK = 64;

    private final double z0;
    private final double step;
    private final double[] radius = new double[CELLS];
    private final double initialRadius;
    /** Largest radius in each run of BLOCK cells: a move above it skips the whole run. */
    private final double[] blockMax = new double[CELLS / BLOCK];
    /** Blocks whose cells all hold blockMax (radius[] is stale there): a level pass updates them in one step. */
    private final boolean[] uniform = new boolean[CELLS / BLOCK];

    StockProfile(double backZ, double faceZ, double radius) {
        this.z0 = backZ;
        this.step = (faceZ - backZ) / CELLS;
        this.initialRadius = radius;
        java.util.Arrays.fill(this.radius, radius);
        java.util.Arrays.fill(this.blockMax, radius);
        java.util.Arrays.fill(this.uniform, true);
    }

    double back() {
        return z0;
    }

    double face() {
        return z0 + step * CELLS;
    }

    /** Could a move whose tip stays in this box (z range, smallest radius) touch material? */
    boolean mayTouch(double zLo, double zHi, double rMin, double slack) {
        if (zHi < z0 || zLo > face()) {
            return false;
        }
        int lo = Math.max(0, (int) ((zLo - z0) / step) / BLOCK);
        int hi = Math.min(blockMax.length - 1, (int) ((zHi - z0) / step) / BLOCK);
        for (int b = lo; b <= hi; b++) {
            if (rMin < blockMax[b] - slack) {
                return true;
            }
        }
        return false;
    }

    double initialRadius() {
        return initialRadius;
    }

    int cells() {
        return CELLS;
    }

    double cellZ(int i) {
        return z0 + (i + 0.5) * step;
    }

    double radiusAt(int i) {
        return uniform[i / BLOCK] ? blockMax[i / BLOCK] : radius[i];
    }

    /**
     * Walks the tip's straight move (a -> b, radii from the centreline) over the cell centres it
     * crosses: lowers the profile to the tip, and returns the index of the first cell where the tip
     * was more than slack inside material that was still there, or -1.
     */
    int cut(double az, double ar, double bz, double br, double slack) {
        double lo = Math.min(az, bz);
        double hi = Math.max(az, bz);
        int first = (int) Math.ceil((lo - z0) / step - 0.5);
        int last = (int) Math.floor((hi - z0) / step - 0.5);
        int hit = -1;
        if (hi - lo < step) {
            // A (nearly) radial move: the cell holding its z, if it is inside the stock.
            int i = (int) Math.floor(((lo + hi) / 2 - z0) / step);
            if (i >= 0 && i < CELLS && (lo + hi) / 2 > z0 + slack && (lo + hi) / 2 < face() - slack) {
                double r = Math.min(ar, br);
                if (r < radiusAt(i) - slack) {
                    hit = i;
                    materialise(i / BLOCK);
                    radius[i] = Math.max(0, r);
                    blockMax[i / BLOCK] = maxOf(i / BLOCK);
                }
            }
            return hit;
        }
        first = Math.max(first, 0);
        last = Math.min(last, CELLS - 1);
        double slope = (br - ar) / (bz - az);
        for (int b = first / BLOCK; b <= last / BLOCK && b < blockMax.length; b++) {
            int from = Math.max(first, b * BLOCK);
            int to = Math.min(last, b * BLOCK + BLOCK - 1);
            double r0 = ar + (cellZ(from) - az) * slope;
            double r1 = ar + (cellZ(to) - az) * slope;
            if (Math.min(r0, r1) >= blockMax[b] - slack) {
                continue;
            }
            if (uniform[b] && slope == 0 && from == b * BLOCK && to == from + BLOCK - 1) {
                // A level pass over a whole level block (most turning passes): one value, not 64.
                if (hit < 0) {
                    hit = from;
                }
                blockMax[b] = Math.max(0, r0);
                continue;
            }
            materialise(b);
            int lowered = 0;
            for (int i = from; i <= to; i++) {
                double r = ar + (cellZ(i) - az) * slope;
                if (r < radius[i] - slack) {
                    if (hit < 0) {
                        hit = i;
                    }
                    radius[i] = Math.max(0, r);
                    lowered++;
                }
            }
            if (slope == 0 && lowered == BLOCK) {
                uniform[b] = true;
                blockMax[b] = Math.max(0, r0);
            } else if (lowered > 0) {
                blockMax[b] = maxOf(b);
            }
        }
        return hit;
    }

    /** Writes a level block's one value into its cells before they are changed one by one. */
    private void materialise(int b) {
        if (uniform[b]) {
            java.util.Arrays.fill(radius, b * BLOCK, b * BLOCK + BLOCK, blockMax[b]);
            uniform[b] = false;
        }
    }

    private double maxOf(int b) {
        double max = 0;
        for (int i = b * BLOCK; i < b * BLOCK + BLOCK; i++) {
            max = Math.max(max, radius[i]);
        }
        return max;
    }
}
