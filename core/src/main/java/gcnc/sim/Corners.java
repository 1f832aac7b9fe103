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
 * into the next one. Findings go to the line of the segment they are about. Every corner the machine
 * slows for, and every reversal, goes to the corner report ({@link SlowestCorners}) with what sets
 * its speed: the junction's angle, an arc's √(a·r), or the acceleration over a short segment.
 */
final class Corners {
    /** A segment this short (counts) is the rounding of an arc's end, not a corner: no junction check. */
    private static final double TINY = 4;
    /** Room for the even rounding of the written speeds, counts/s. */
    private static final double ROUNDING = 4;

    private final double acceleration;
    private final double deviation;
    private final double countsPerMm;
    private final MotionChecks.Reporter out;
    /** The slowest corners so far, for the report. */
    final SlowestCorners slowest = new SlowestCorners();
    /** The last segment of the sequence before, and whether the planner stopped there for a reversal. */
    private Segment previous;
    private String previousNumber;
    private boolean reversal;
    /** The share of the junction speed the planner takes (gcnc.plan.Contouring.MARGIN). */
    private static final double MARGIN = 0.9;

    Corners(MachineProfile profile, MotionChecks.Reporter out) {
        this.acceleration = Math.min(profile.acceleration(), profile.deceleration());
        this.countsPerMm = Math.min(profile.x().countsPerMm(), profile.z().countsPerMm());
        this.deviation = Blending.of(profile).deviationMm() * countsPerMm;
        this.out = out;
    }

    /** The sequence that ran last ended for {@code why} (null: not known, a DMC read back). */
    void stopped(gcnc.plan.Stop why) {
        reversal = why == gcnc.plan.Stop.REVERSAL;
    }

    /**
     * Checks a sequence's corners and notes the slow ones. {@code numbers}: the N word of each
     * segment's block by the segment's index (null where none is known), or null; asked during the call only.
     */
    void check(List<Segment> segs, double speed, gcnc.dmc.Source start, java.util.function.IntFunction<String> numbers) {
        if (segs.isEmpty()) {
            return;
        }
        if (reversal && previous != null) {
            // the planner stopped where the path turns back: a corner taken at 0
            Segment first = segs.get(0);
            note(previous, first, previousNumber, 0, Math.max(speedOf(previous, speed), speedOf(first, speed)),
                    Corner.Why.REVERSAL, Double.NaN, Double.NaN);
        }
        reversal = false;
        previous = segs.get(segs.size() - 1);
        previousNumber = numbers == null ? null : numbers.apply(segs.size() - 1);
        boolean blended = false;
        for (Segment s : segs) {
            blended = blended || !Double.isNaN(s.speed()) || !Double.isNaN(s.end());
        }
        if (segs.size() < 2 || !blended) {
            return; // one segment, or a sequence without speeds of its own (a geared pass, an arc and its closing move)
        }
        double entry = 0;
        // each segment's length and the junction's cosine worked out once (a hypot each), not per use
        double length = segs.get(0).length();
        for (int k = 0; k < segs.size(); k++) {
            Segment s = segs.get(k);
            gcnc.dmc.Source at = MotionChecks.place(s, start);
            double v = Double.isNaN(s.speed()) ? speed : s.speed();
            boolean last = k == segs.size() - 1;
            double exit = last ? 0 : Double.isNaN(s.end()) ? v : s.end();
            double nextLength = last ? 0 : segs.get(k + 1).length();
            // a segment of a count or two (an arc's closing move) is a rounding, not a corner of the path
            if (!last && length > TINY && nextLength > TINY) {
                Segment next = segs.get(k + 1);
                double junction = Blending.junctionSpeed(cosine(s, next), acceleration, deviation);
                double limit = Math.min(Math.min(v, speedOf(next, speed)), junction);
                if (exit > limit + ROUNDING) {
                    out.report(Code.E332_SIM_CORNER_TOO_FAST, at, perMinute(exit), perMinute(limit));
                }
                double nextExit = k + 1 == segs.size() - 1 ? 0 : Double.isNaN(next.end()) ? speedOf(next, speed) : next.end();
                classify(s, next, length, nextLength, junction, numbers, k, v,
                        speedOf(next, speed), entry, exit, nextExit);
            }
            double change = Math.abs(entry * entry - exit * exit);
            double peak = Math.max(entry, exit) + ROUNDING;
            if (change > 2 * acceleration * length + 2 * peak * ROUNDING) {
                out.report(Code.E333_SIM_SPEED_CHANGE_TOO_SHORT, at, perMinute(entry), perMinute(exit),
                        MotionChecks.mm(length / countsPerMm));
            }
            entry = exit;
            length = nextLength;
        }
    }

    /**
     * Notes a corner the machine slows for, with what sets its speed: the junction (its angle at
     * the planner's share of the junction-deviation speed), an arc's √(a·r) when the arc is the
     * slower move, else the acceleration over the segment before or after it (whichever pass
     * brought it down). A corner at the faster move's speed is not slowed; one at a lower feed of
     * the next move is the program's, not the machine's.
     */
    private void classify(Segment s, Segment next, double length, double nextLength, double fullJunction,
                          java.util.function.IntFunction<String> numbers, int k, double v, double vn, double entry,
                          double exit, double nextExit) {
        double feed = Math.max(v, vn);
        if (exit >= feed - ROUNDING) {
            return;
        }
        double cap = Math.min(v, vn);
        double junction = MARGIN * fullJunction;
        double own = Math.min(junction, cap);
        if (exit >= own - ROUNDING - 0.02 * own) {
            if (junction <= cap) {
                note(s, next, numbers, k, exit, feed, Corner.Why.JUNCTION, deviation / countsPerMm, Double.NaN);
                return;
            }
            Segment slower = v <= vn ? s : next;
            double o = Math.min(v, vn);
            if (slower.arc() && Math.abs(o - Math.sqrt(acceleration * slower.radius())) <= ROUNDING + 0.01 * o) {
                note(s, next, numbers, k, exit, feed, Corner.Why.ARC, Double.NaN, slower.radius() / countsPerMm);
            }
            return;
        }
        double forward = Math.sqrt(entry * entry + 2 * acceleration * length);
        double backward = Math.sqrt(nextExit * nextExit + 2 * acceleration * nextLength);
        double shortOne = Math.abs(forward - exit) <= Math.abs(backward - exit) ? length : nextLength;
        note(s, next, numbers, k, exit, feed, Corner.Why.ACCELERATION, Double.NaN, shortOne / countsPerMm);
    }

    /**
     * A corner at the end of {@code s} into {@code next}, for the report (radius or length in mm as
     * {@code why} has one); nothing is made for a corner faster than the slowest kept ones.
     */
    private void note(Segment s, Segment next, java.util.function.IntFunction<String> numbers, int k, double speed,
                      double feed, Corner.Why why, double deviationMm, double mm) {
        if (slowest.keeps(speed / countsPerMm * 60)) { // (the N word looked up only for a corner kept)
            note(s, next, numbers == null ? null : numbers.apply(k), speed, feed, why, deviationMm, mm);
        }
    }

    private void note(Segment s, Segment next, String number, double speed, double feed, Corner.Why why,
                      double deviationMm, double mm) {
        double mmPerMin = speed / countsPerMm * 60;
        if (!slowest.keeps(mmPerMin)) {
            return;
        }
        double angle = angle(s, next);
        gcnc.dmc.Source src = s.source();
        String file = src == null ? null : src.file();
        int line = src == null ? 0 : src.line();
        slowest.add(new Corner(file, line, number, mmPerMin, feed / countsPerMm * 60, why, angle,
                why == Corner.Why.JUNCTION ? deviationMm : Double.NaN, why == Corner.Why.ARC ? mm : Double.NaN,
                why == Corner.Why.ACCELERATION ? mm : Double.NaN));
    }

    /** How far the path turns from {@code a} into {@code b}, degrees. */
    static double angle(Segment a, Segment b) {
        double dot = Math.max(-1, Math.min(1, dx(a, false) * dx(b, true) + dz(a, false) * dz(b, true)));
        return Math.toDegrees(Math.acos(dot));
    }

    private static double speedOf(Segment s, double speed) {
        return Double.isNaN(s.speed()) ? speed : s.speed();
    }

    /**
     * The junction's cosine as Grbl takes it (-1 straight on, +1 straight back), from which
     * {@link Blending#junctionSpeed} gives the fastest the corner from {@code a} into {@code b} may be
     * taken: {@link #dx} and {@link #dz}'s numbers, each segment's length or angle worked out once.
     */
    private static double cosine(Segment a, Segment b) {
        double la = length(a);
        double lb = length(b);
        return -(dx(a, false, la) * dx(b, true, lb) + dz(a, false, la) * dz(b, true, lb));
    }

    /**
     * The unit direction of travel at a segment's start or end, machine counts: its x ({@link #dx})
     * and z ({@link #dz}) parts, computed apart so that a corner check per junction makes no arrays.
     * A point at angle a of an arc is (cx + r sin a, cz + r cos a); its derivative along the sweep's sign.
     */
    static double dx(Segment s, boolean start) {
        return dx(s, start, length(s));
    }

    /** The z part of {@link #dx}'s direction. */
    static double dz(Segment s, boolean start) {
        return dz(s, start, length(s));
    }

    /** A straight segment's length, counts (what its direction is divided by); 0 for an arc, whose direction needs none. */
    private static double length(Segment s) {
        return s.arc() ? 0 : Math.hypot(s.toX() - s.fromX(), s.toZ() - s.fromZ());
    }

    private static double dx(Segment s, boolean start, double len) {
        if (!s.arc()) {
            return len == 0 ? 0 : (s.toX() - s.fromX()) / len;
        }
        return Math.signum(s.sweepDeg()) * Math.cos(Math.toRadians(s.startDeg() + (start ? 0 : s.sweepDeg())));
    }

    private static double dz(Segment s, boolean start, double len) {
        if (!s.arc()) {
            return len == 0 ? 0 : (s.toZ() - s.fromZ()) / len;
        }
        return -Math.signum(s.sweepDeg()) * Math.sin(Math.toRadians(s.startDeg() + (start ? 0 : s.sweepDeg())));
    }

    /** counts/s as mm/min, one decimal. */
    private String perMinute(double countsPerSecond) {
        return String.format(java.util.Locale.ROOT, "%.1f", countsPerSecond / countsPerMm * 60);
    }
}
