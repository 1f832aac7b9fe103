package gcnc.check.geom;

import gcnc.ir.Motion;

/**
 * A motion as the one kind a check asks about (a line, an arc, a thread pass), or null when it is
 * another: the sealed {@link Motion} dispatched through {@link Motion.Visitor}, once for the
 * checker's packages, instead of instanceof tests and casts.
 */
public final class MotionParts {
    private MotionParts() {
    }

    /** The motion as a straight line (a rapid or a feed), or null. */
    public static Motion.Linear line(Motion m) {
        return m.accept(LINE);
    }

    /** The motion as an arc, or null. */
    public static Motion.Arc arc(Motion m) {
        return m.accept(ARC);
    }

    /** The motion as a thread pass, or null. */
    public static Motion.Thread thread(Motion m) {
        return m.accept(THREAD);
    }

    /** The motion as a move along the path (a line, an arc, a thread pass), or null for a dwell. */
    public static Motion.PathMotion path(Motion m) {
        return m.accept(PATH);
    }

    /** Null for every kind of motion: each visitor below answers for its own kind. */
    private abstract static class Only<R> implements Motion.Visitor<R> {
        @Override
        public R linear(Motion.Linear l) {
            return null;
        }

        @Override
        public R arc(Motion.Arc a) {
            return null;
        }

        @Override
        public R dwell(Motion.Dwell d) {
            return null;
        }

        @Override
        public R thread(Motion.Thread t) {
            return null;
        }
    }

    private static final Motion.Visitor<Motion.Linear> LINE = new Only<>() {
        @Override
        public Motion.Linear linear(Motion.Linear l) {
            return l;
        }
    };

    private static final Motion.Visitor<Motion.Arc> ARC = new Only<>() {
        @Override
        public Motion.Arc arc(Motion.Arc a) {
            return a;
        }
    };

    private static final Motion.Visitor<Motion.Thread> THREAD = new Only<>() {
        @Override
        public Motion.Thread thread(Motion.Thread t) {
            return t;
        }
    };

    private static final Motion.Visitor<Motion.PathMotion> PATH = new Only<>() {
        @Override
        public Motion.PathMotion linear(Motion.Linear l) {
            return l;
        }

        @Override
        public Motion.PathMotion arc(Motion.Arc a) {
            return a;
        }

        @Override
        public Motion.PathMotion thread(Motion.Thread t) {
            return t;
        }
    };
}
