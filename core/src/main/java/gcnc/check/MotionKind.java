package gcnc.check;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;

/**
 * What a motion does, as a closed set: the checker's questions of a block's motions (does it cut,
 * does it move the tool) are answered from its kind, found once through {@link Motion.Visitor},
 * so that a new kind of motion does not compile until it is placed here.
 */
enum MotionKind {
    RAPID(false, true), FEED(true, true), ARC(true, true), DWELL(false, false), THREAD(true, true);

    /** Whether the motion cuts: a feed, an arc or a thread pass (not a rapid or a dwell). */
    final boolean cuts;
    /** Whether the motion moves the tool: everything but a dwell. */
    final boolean moves;

    MotionKind(boolean cuts, boolean moves) {
        this.cuts = cuts;
        this.moves = moves;
    }

    /** Whether the motion is a straight line of the path (a rapid or a feed; not a thread pass). */
    boolean linear() {
        return this == RAPID || this == FEED;
    }

    static MotionKind of(Motion m) {
        return m.accept(KIND);
    }

    /** Whether the block cuts: a feed, an arc or a thread pass (not a rapid or a dwell). */
    static boolean cuts(CheckedBlock b) {
        for (Motion m : b.motions()) {
            if (of(m).cuts) {
                return true;
            }
        }
        return false;
    }

    /** Whether the block moves the tool (a dwell does not). */
    static boolean moves(CheckedBlock b) {
        for (Motion m : b.motions()) {
            if (of(m).moves) {
                return true;
            }
        }
        return false;
    }

    /** The motion as an arc, or null when it is not one. */
    static Motion.Arc arc(Motion m) {
        return gcnc.check.geom.MotionParts.arc(m);
    }

    /** The motion as a thread pass, or null when it is not one (its lead, rpm and end are read then). */
    static Motion.Thread thread(Motion m) {
        return gcnc.check.geom.MotionParts.thread(m);
    }

    private static final Motion.Visitor<MotionKind> KIND = new Motion.Visitor<>() {
        @Override
        public MotionKind linear(Motion.Linear l) {
            return l.rapid() ? RAPID : FEED;
        }

        @Override
        public MotionKind arc(Motion.Arc a) {
            return ARC;
        }

        @Override
        public MotionKind dwell(Motion.Dwell d) {
            return DWELL;
        }

        @Override
        public MotionKind thread(Motion.Thread t) {
            return THREAD;
        }
    };
}
