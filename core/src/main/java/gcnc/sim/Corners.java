package gcnc.sim;

import gcnc.diag.Code;
import gcnc.machine.Blending;
import gcnc.machine.MachineProfile;
import java.util.List;

/**
 * The speeds of a blended sequence as the controller will run them, checked from the segments the
 * simulator replayed (not from the planner's numbers): each corner taken no faster than the
 * junction-deviation speed of the machine's acceleration and {@code corner.deviation} (E332), and
 * each segment long enough for the machine to change from its entry speed to its exit speed (E333).
 * A segment without its own speeds runs at the sequence's VS; without {@code >p} it keeps its speed
 * into the next one. Findings go to the line of the segment they are about.
 */
final class Corners {
    /** A segment this short (counts) is the rounding of an arc's end, not a corner: no junction check. */
    private static final double TINY = 4;
    /** Room for the even rounding of the written speeds, counts/s. */
    private static final double ROUNDING = 4;

    interface Report {
        void report(Code code, int line, Object... args);
    }

    private final double acceleration;
    private final double deviation;
    private final double countsPerMm;
    private final Report out;

    Corners(MachineProfile profile, Report out) {
        this.acceleration = Math.min(profile.acceleration(), profile.deceleration());
        this.countsPerMm = Math.min(profile.x().countsPerMm(), profile.z().countsPerMm());
        this.deviation = Blending.of(profile).deviationMm() * countsPerMm;
        this.out = out;
    }

    void check(List<Segment> segs, double speed, int line) {
        boolean blended = false;
        for (Segment s : segs) {
            blended = blended || !Double.isNaN(s.speed()) || !Double.isNaN(s.end());
        }
        if (segs.size() < 2 || !blended) {
            return; // one segment, or a sequence without speeds of its own (a geared pass, an arc and its closing move)
        }
        double entry = 0;
        for (int k = 0; k < segs.size(); k++) {
            Segment s = segs.get(k);
            int at = s.source() != null && s.source().line() > 0 ? s.source().line() : line;
            double v = Double.isNaN(s.speed()) ? speed : s.speed();
            boolean last = k == segs.size() - 1;
            double exit = last ? 0 : Double.isNaN(s.end()) ? v : s.end();
            // a segment of a count or two (an arc's closing move) is a rounding, not a corner of the path
            if (!last && s.length() > TINY && segs.get(k + 1).length() > TINY) {
                double limit = junction(s, segs.get(k + 1), Math.min(v, speedOf(segs.get(k + 1), speed)));
                if (exit > limit + ROUNDING) {
                    out.report(Code.E332_SIM_CORNER_TOO_FAST, at, perMinute(exit), perMinute(limit));
                }
            }
            double change = Math.abs(entry * entry - exit * exit);
            double peak = Math.max(entry, exit) + ROUNDING;
            if (change > 2 * acceleration * s.length() + 2 * peak * ROUNDING) {
                out.report(Code.E333_SIM_SPEED_CHANGE_TOO_SHORT, at, perMinute(entry), perMinute(exit),
                        MotionChecks.mm(s.length() / countsPerMm));
            }
            entry = exit;
        }
    }

    private static double speedOf(Segment s, double speed) {
        return Double.isNaN(s.speed()) ? speed : s.speed();
    }

    /** The fastest the corner from {@code a} into {@code b} may be taken, at most {@code cap}. */
    double junction(Segment a, Segment b, double cap) {
        double[] out = direction(a, false);
        double[] in = direction(b, true);
        double cos = -(out[0] * in[0] + out[1] * in[1]);
        if (cos < -0.999999) {
            return cap;
        }
        if (cos > 0.999999) {
            return 0;
        }
        double sinHalf = Math.sqrt(0.5 * (1 - cos));
        return Math.min(cap, Math.sqrt(acceleration * deviation * sinHalf / (1 - sinHalf)));
    }

    /** The unit direction of travel at a segment's start or end, machine counts (x, z). */
    static double[] direction(Segment s, boolean start) {
        if (!s.arc()) {
            double dx = s.toX() - s.fromX();
            double dz = s.toZ() - s.fromZ();
            double len = Math.hypot(dx, dz);
            return len == 0 ? new double[] {0, 0} : new double[] {dx / len, dz / len};
        }
        // a point at angle a is (cx + r sin a, cz + r cos a); its derivative along the sweep's sign
        double a = Math.toRadians(s.startDeg() + (start ? 0 : s.sweepDeg()));
        double sign = Math.signum(s.sweepDeg());
        return new double[] {sign * Math.cos(a), -sign * Math.sin(a)};
    }

    /** counts/s as mm/min, one decimal. */
    private String perMinute(double countsPerSecond) {
        return String.format(java.util.Locale.ROOT, "%.1f", countsPerSecond / countsPerMm * 60);
    }
}
