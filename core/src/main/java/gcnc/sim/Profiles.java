package gcnc.sim;

/** Speed profiles of one segment: how long the controller takes over it with VA and VD. */
final class Profiles {
    private Profiles() {
    }

    /**
     * The time over {@code length} entered at {@code in}, run at {@code v} and left at {@code out}
     * (counts, counts/s), accelerating at {@code acc} and decelerating at {@code dec}: a trapezoid,
     * or a triangle whose peak is what the length allows. An entry or exit the length cannot reconcile
     * (faster than the machine can change speed there) is run at their mean: the corner check (E332)
     * reports it.
     */
    static double time(double length, double in, double v, double out, double acc, double dec) {
        if (length <= 0) {
            return 0;
        }
        v = Math.max(v, 1e-9);
        double up = v > in ? (v * v - in * in) / (2 * acc) : 0;
        double down = v > out ? (v * v - out * out) / (2 * dec) : 0;
        if (up + down <= length) {
            return (v > in ? (v - in) / acc : 0) + (length - up - down) / v + (v > out ? (v - out) / dec : 0);
        }
        double peak2 = (2 * acc * dec * length + dec * in * in + acc * out * out) / (acc + dec);
        double peak = Math.sqrt(Math.max(peak2, 0));
        if (peak < Math.max(in, out)) {
            return 2 * length / Math.max(in + out, 1e-9);
        }
        return (peak - in) / acc + (peak - out) / dec;
    }

    /** Trapezoidal speed profile from rest to rest; a triangle when the move is too short to reach v. */
    static double time(double length, double v, double acc, double dec) {
        if (length <= 0 || v <= 0) {
            return 0;
        }
        double ramps = v * v / (2 * acc) + v * v / (2 * dec);
        if (length >= ramps) {
            return length / v + v / (2 * acc) + v / (2 * dec);
        }
        double peak = Math.sqrt(2 * length * acc * dec / (acc + dec));
        return peak / acc + peak / dec;
    }
}
