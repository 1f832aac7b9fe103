package gcnc.machine;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.machine.GalilModel.Limit;
import gcnc.machine.GalilModel.Range;
import java.util.Optional;

/**
 * Checks a number gcnc is about to hand the controller against what its model takes
 * (tables/galil_models.csv; docs/galil.md, "The controller's limits"). Pure: each check answers
 * with the {@link Violation}, if any, and the caller (the backend, which knows the block) reports
 * it where it belongs ({@link #report}). A value the controller would refuse is an error; a value
 * it would silently round is written already rounded, with a warning that says so ({@link Rounded}):
 * never a number on the machine that differs from the one on the screen without a word.
 *
 * <p>Speeds, accelerations and times are at the model's TM 1000 (the values the reference gives);
 * gcnc does not change TM.
 */
public final class ControllerLimits {
    private final GalilModel model;
    /**
     * The model's range of each limit by its ordinal, looked up once: a compile checks several
     * numbers per block (each a look-up in the model's maps otherwise).
     */
    private final Range[] ranges;

    public ControllerLimits(GalilModel model) {
        this.model = model;
        Limit[] all = Limit.values();
        this.ranges = new Range[all.length];
        for (Limit l : all) {
            ranges[l.ordinal()] = model.range(l);
        }
    }

    public GalilModel model() {
        return model;
    }

    /**
     * A value beyond one of the model's limits.
     *
     * @param limit   which limit
     * @param value   the value as gcnc would have written it
     * @param allowed what the model takes (its maximum excluded when {@link Limit#below})
     * @param model   the model, with its row in tables/galil_models.csv
     */
    public record Violation(Limit limit, double value, Range allowed, GalilModel model) {
        /** The located error: the limit's code, with the value, the range and the model. */
        public Diagnostic diagnostic(Span span) {
            return Diagnostic.error(limit.code(), span, written(value), allowed.min(), allowed.max(), model.name());
        }

        /** One line in English for logs and test failures: "VS 16000000 not in 2..15000000 (DMC-4040, galil_models.csv:12)". */
        public String render() {
            return limit.command() + " " + written(value) + " not in " + allowed.min() + (limit.below() ? "..<" : "..")
                    + allowed.max() + " (" + model.name() + ", galil_models.csv:" + model.row() + ")";
        }
    }

    /**
     * A value brought to the controller's resolution: what was asked, what gcnc writes, the step.
     * {@link #changed} says whether the two differ; when they do, {@link #report} warns.
     */
    public record Rounded(Limit limit, long asked, long taken, long step, GalilModel model, Code warning) {
        public boolean changed() {
            return asked != taken;
        }

        /** The warning, when the value changed. */
        public Optional<Diagnostic> diagnostic(Span span) {
            return changed() ? Optional.of(Diagnostic.warning(warning, span, asked, taken, step, model.name()))
                    : Optional.empty();
        }
    }

    /** VS, counts/s. */
    public Optional<Violation> vectorSpeed(long countsPerSecond) {
        return check(Limit.VECTOR_SPEED, countsPerSecond);
    }

    /** A segment speed {@code <o} or {@code >p} of VP or CR (a corner speed), counts/s. */
    public Optional<Violation> cornerSpeed(long countsPerSecond) {
        return check(Limit.SEGMENT_SPEED, countsPerSecond);
    }

    /** VA or VD, counts/s^2 (before rounding to the step: {@link #roundAcceleration}). */
    public Optional<Violation> acceleration(long countsPerSecondSquared) {
        return check(Limit.ACCELERATION, countsPerSecondSquared);
    }

    /**
     * One VP segment moving {@code du} and {@code dv} counts on the plane's two axes: its length
     * (the reference limits "the length of each vector segment", which also bounds each axis).
     */
    public Optional<Violation> segment(long du, long dv) {
        return check(Limit.SEGMENT_LENGTH, Math.hypot(du, dv));
    }

    /** A CR radius, counts. */
    public Optional<Violation> arcRadius(long counts) {
        return check(Limit.ARC_RADIUS, counts);
    }

    /** A CR arc: its radius, then its radius times the degrees it turns (either sign). */
    public Optional<Violation> arc(long radius, double sweepDegrees) {
        Optional<Violation> r = arcRadius(radius);
        return r.isPresent() ? r : check(Limit.ARC_LENGTH, radius * Math.abs(sweepDegrees));
    }

    /** WT, milliseconds (before rounding to the step: {@link #roundDwell}). */
    public Optional<Violation> dwell(long ms) {
        return check(Limit.DWELL, ms);
    }

    /** The most characters on one program line: what a packed line is filled to. */
    public int lineWidth() {
        return (int) model.range(Limit.LINE_LENGTH).max();
    }

    /**
     * VA or VD as the controller takes it: a multiple of its step (1,024), rounded down as the
     * controller does itself (the reference's "VA 20000" reads back 19456), and down also because
     * the profile's acceleration is what the machine can do: gcnc never writes more. A value below
     * the smallest step is left for {@link #acceleration} to refuse.
     */
    public Rounded roundAcceleration(long countsPerSecondSquared) {
        Range r = ranges[Limit.ACCELERATION.ordinal()];
        long taken = countsPerSecondSquared < r.step() ? countsPerSecondSquared
                : Math.floorDiv(countsPerSecondSquared, r.step()) * r.step();
        return new Rounded(Limit.ACCELERATION, countsPerSecondSquared, taken, r.step(), model, Code.E235_ACCELERATION_ROUNDED);
    }

    /**
     * A speed (VS, {@code <o}, {@code >p}) as the controller takes it: a multiple of 2, rounded down
     * so that no feed is faster than programmed (which way the controller itself rounds an odd
     * speed is not documented). A value below the step is left for the range check.
     */
    public Rounded roundSpeed(long countsPerSecond) {
        Range r = ranges[Limit.VECTOR_SPEED.ordinal()];
        long taken = countsPerSecond < r.step() ? countsPerSecond : Math.floorDiv(countsPerSecond, r.step()) * r.step();
        return new Rounded(Limit.VECTOR_SPEED, countsPerSecond, taken, r.step(), model, Code.E236_SPEED_ROUNDED);
    }

    /**
     * WT as the controller takes it: a multiple of 2 ms, rounded up so that a dwell is never
     * shorter than programmed (a dwell is a minimum: the chip breaks, the spindle reaches speed).
     */
    public Rounded roundDwell(long ms) {
        Range r = ranges[Limit.DWELL.ordinal()];
        long taken = Math.floorDiv(ms + r.step() - 1, r.step()) * r.step();
        return new Rounded(Limit.DWELL, ms, taken, r.step(), model, Code.E237_DWELL_ROUNDED);
    }

    /** Reports a violation, if any, as an error at {@code span}. */
    public static void report(Optional<Violation> v, Span span, Diagnostics out) {
        v.ifPresent(violation -> out.report(violation.diagnostic(span)));
    }

    /** Reports a rounded value that changed as a warning at {@code span}. */
    public static void report(Rounded r, Span span, Diagnostics out) {
        r.diagnostic(span).ifPresent(out::report);
    }

    /**
     * A value against one limit: what the named checks above come to, and the check itself for the
     * counts a program is held to as a whole (its lines, labels, label names, variables, arrays, a
     * sequence's length and segments), which need no conversion.
     */
    public Optional<Violation> check(Limit limit, double value) {
        Range r = ranges[limit.ordinal()];
        return r.holds(value, limit.below()) ? Optional.empty() : Optional.of(new Violation(limit, value, r, model));
    }

    /** A value as a message shows it: whole numbers without a point, others to 3 decimals. */
    static String written(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v)
                : String.valueOf(Math.rint(v * 1000) / 1000);
    }
}
