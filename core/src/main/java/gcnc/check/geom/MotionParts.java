package gcnc.check.geom;

import gcnc.ir.Motion;

/**
 * A motion as the one kind a check asks about (a line, an arc, a thread pass), or null when it is
 * another: a type test, not a dispatch. A question every kind of motion must answer is a
 * {@link Motion.Visitor} (so that a new kind does not compile until it is answered); "is this
 * an arc?" is answered for every kind by the test itself.
 */
public final class MotionParts {
    private MotionParts() {
    }

    /** The motion as a straight line (a rapid or a feed), or null. */
    public static Motion.Linear line(Motion m) {
        return m instanceof Motion.Linear l ? l : null;
    }

    /** The motion as an arc, or null. */
    public static Motion.Arc arc(Motion m) {
        return m instanceof Motion.Arc a ? a : null;
    }

    /** The motion as a thread pass, or null. */
    public static Motion.Thread thread(Motion m) {
        return m instanceof Motion.Thread t ? t : null;
    }

    /** The motion as a move along the path (a line, an arc, a thread pass), or null for a dwell. */
    public static Motion.PathMotion path(Motion m) {
        return m instanceof Motion.PathMotion p ? p : null;
    }
}
