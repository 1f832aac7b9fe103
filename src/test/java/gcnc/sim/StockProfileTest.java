package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The stock profile keeps level blocks as one value (a speed-up); it must cut exactly like the
 * plain rule: every cell centre the move crosses is lowered to the tip when the tip is more than
 * the slack below it, and the first such cell is the hit.
 */
class StockProfileTest {
    private static final double BACK = 1000;
    private static final double FACE = 5096; // one count per cell
    private static final double RADIUS = 500;
    private static final double SLACK = 0.5;

    @Test
    void levelPassLowersEveryCellItCrossesAndReportsTheFirst() {
        StockProfile stock = new StockProfile(BACK, FACE, RADIUS);
        assertEquals(4000 - 1000, stock.cut(5200, 400, 4000, 400, SLACK)); // right to left: first cell in z order
        assertEquals(400, stock.radiusAt(3500));
        assertEquals(RADIUS, stock.radiusAt(2999));
        assertEquals(-1, stock.cut(5200, 400, 4000, 400, SLACK), "the same pass again cuts air");
        assertEquals(-1, stock.cut(5200, 399.7, 4000, 399.7, SLACK), "within the slack: nothing cut");
    }

    @Test
    void randomMovesCutLikeThePlainRule() {
        Random rnd = new Random(7);
        for (int run = 0; run < 200; run++) {
            StockProfile stock = new StockProfile(BACK, FACE, RADIUS);
            double[] plain = new double[StockProfile.CELLS];
            java.util.Arrays.fill(plain, RADIUS);
            for (int move = 0; move < 60; move++) {
                double az = BACK - 100 + rnd.nextInt(4400);
                double ar = rnd.nextInt(600);
                int kind = rnd.nextInt(3);
                double bz = kind == 0 ? az + rnd.nextDouble() * 0.5 : BACK - 100 + rnd.nextInt(4400);
                double br = kind == 1 ? ar : rnd.nextInt(600);
                int expected = plainCut(plain, az, ar, bz, br);
                assertEquals(expected, stock.cut(az, ar, bz, br, SLACK), "run " + run + " move " + move);
                for (int i = 0; i < StockProfile.CELLS; i++) {
                    assertEquals(plain[i], stock.radiusAt(i), "cell " + i);
                }
            }
        }
    }

    /** The rule written out cell by cell, with no blocks. */
    private static int plainCut(double[] r, double az, double ar, double bz, double br) {
        double lo = Math.min(az, bz);
        double hi = Math.max(az, bz);
        if (hi - lo < 1) {
            double mid = (lo + hi) / 2;
            int i = (int) Math.floor(mid - BACK);
            double tip = Math.min(ar, br);
            if (i >= 0 && i < r.length && mid > BACK + SLACK && mid < FACE - SLACK && tip < r[i] - SLACK) {
                r[i] = Math.max(0, tip);
                return i;
            }
            return -1;
        }
        int hit = -1;
        for (int i = 0; i < r.length; i++) {
            double z = BACK + i + 0.5;
            if (z >= lo && z <= hi) {
                double tip = ar + (z - az) * ((br - ar) / (bz - az));
                if (tip < r[i] - SLACK) {
                    hit = hit < 0 ? i : hit;
                    r[i] = Math.max(0, tip);
                }
            }
        }
        return hit;
    }
}
