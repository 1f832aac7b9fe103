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

    private static final Motion.Visitor<Motion.Linear> LINE = new Motion.Visitor<>() {
        @Override
        public Motion.Linear linear(Motion.Linear l) {
            return l;
        }
    
        @Override
        public Motion.Linear arc(Motion.Arc a) {
            return null;
        }
    
        @Override
        public Motion.Linear dwell(Motion.Dwell d) {
            return null;
        }
    
        @Override
        public Motion.Linear thread(Motion.Thread t) {
            return null;
        }
    };

    private static final Motion.Visitor<Motion.Arc> ARC = new Motion.Visitor<>() {
        @Override
        public Motion.Arc linear(Motion.Linear l) {
            return null;
        }
    
        @Override
        public Motion.Arc arc(Motion.Arc a) {
            return a;
        }
    
        @Override
        public Motion.Arc dwell(Motion.Dwell d) {
            return null;
        }
    
        @Override
        public Motion.Arc thread(Motion.Thread t) {
            return null;
        }
    };

    private static final Motion.Visitor<Motion.Thread> THREAD = new Motion.Visitor<>() {
        @Override
        public Motion.Thread linear(Motion.Linear l) {
            return null;
        }
    
        @Override
        public Motion.Thread arc(Motion.Arc a) {
            return null;
        }
    
        @Override
        public Motion.Thread dwell(Motion.Dwell d) {
            return null;
        }
    
        @Override
        public Motion.Thread thread(Motion.Thread t) {
            return t;
        }
    };
}
