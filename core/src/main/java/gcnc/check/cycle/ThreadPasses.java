package gcnc.check.cycle;

import java.util.ArrayList;
import java.util.List;

/**
 * The depths of a G76's passes (docs/threading.md), pure: radius depths below the thread's top,
 * each the cumulative depth of one pass. Constant area (Fanuc G76, Haas P1): pass n is at
 * {@code first x sqrt(n)}, so each removes about the same area of the 60-degree vee; each pass at
 * least {@code minimum} deeper than the one before (Fanuc Q of the first block). Constant depth
 * (Haas P3): pass n is at {@code first x n}. Roughing stops at {@code height - allowance} exactly;
 * then {@code finishes} passes at {@code height} (the first removes the allowance, the others are
 * spring passes at the same depth). With no finishing passes the last roughing pass is at the height.
 */
public final class ThreadPasses {
    /** How the depth grows: Fanuc's constant area (Haas P1) or Haas P3's constant depth. */
    public enum Infeed { CONSTANT_AREA, CONSTANT_DEPTH }

    private ThreadPasses() {
    }

    /**
     * The depths, or null when there would be more than {@code limit} (the caller reports E167).
     * Requires height > 0, first > 0, minimum >= 0, 0 <= allowance < height, finishes >= 0.
     */
    public static double[] depths(double height, double first, double minimum, double allowance, int finishes,
                                  Infeed infeed, int limit) {
        if (!(height > 0) || !(first > 0) || minimum < 0 || allowance < 0 || allowance >= height || finishes < 0) {
            throw new IllegalArgumentException("thread passes: height " + height + " first " + first);
        }
        double rough = finishes == 0 ? height : height - allowance;
        List<Double> out = new ArrayList<>();
        double at = 0;
        for (int n = 1; at < rough; n++) {
            double next = infeed == Infeed.CONSTANT_AREA ? first * Math.sqrt(n) : first * n;
            next = Math.max(next, at + minimum);
            // a last step of less than a millionth of the height is merged into the one before
            if (next >= rough || rough - next <= height * 1e-6) {
                next = rough;
            }
            out.add(next);
            at = next;
            if (out.size() + finishes > limit) {
                return null;
            }
        }
        for (int i = 0; i < finishes; i++) {
            out.add(height);
        }
        double[] d = new double[out.size()];
        for (int i = 0; i < d.length; i++) {
            d[i] = out.get(i);
        }
        return d;
    }

    /** How many passes the depths would be, without building them (for E167's message). */
    public static int count(double height, double first, double minimum, double allowance, int finishes,
                            Infeed infeed) {
        double rough = finishes == 0 ? height : height - allowance;
        double n = infeed == Infeed.CONSTANT_AREA ? Math.ceil(Math.pow(rough / first, 2)) : Math.ceil(rough / first);
        if (minimum > 0) {
            n = Math.min(n, Math.ceil(rough / minimum));
        }
        return (int) Math.min(Integer.MAX_VALUE - finishes, Math.max(1, n)) + finishes;
    }
}
