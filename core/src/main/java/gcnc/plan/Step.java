package gcnc.plan;

import gcnc.ir.CheckedBlock;
import java.util.List;

/**
 * What the planner hands the emitter, in the order of decision D2 (thesis §4.5): a block's setup
 * before its motions, its motions (alone, or joined with the next blocks' into one sequence), and
 * what comes after them. A sequence ends because of its type: every step but {@link Group} stands
 * still.
 */
public sealed interface Step {
    /**
     * The dispatch the compiler checks: every consumer of steps (the dialects) implements all of it,
     * so a new kind of step does not compile until each handles it (Java 17 has no pattern switch).
     */
    interface Visitor {
        void before(Before s);

        void alone(Alone s);

        void group(Group g);

        void after(After s);
    }

    void accept(Visitor v);

    /** The spindle speed, tool change and M functions applied at the block's start. */
    record Before(CheckedBlock block) implements Step {
        @Override
        public void accept(Visitor v) {
            v.before(this);
        }
    }

    /** One motion written by itself: a dwell, a thread pass, or a path motion the planner did not join. */
    record Alone(CheckedBlock block, int motion) implements Step {
        @Override
        public void accept(Visitor v) {
            v.alone(this);
        }
    }

    /**
     * Path motions the machine runs in one vector sequence without stopping, and why it stops after
     * them; {@code onTheWay}: whether any piece sets something as the tool reaches it
     * ({@link Piece#onTheWay}), so that the emitter measures the written path for its trip points.
     * A sequence longer than the planner's window comes as several groups, one window each
     * ({@link Contouring#WINDOW}): {@code continues} when earlier pieces of the same sequence came in
     * the groups before, {@code goesOn} when later ones follow in the next group (its {@code stop} is
     * then null: the machine does not stop after it, and its last piece's exit is the join's speed).
     */
    record Group(List<Piece> pieces, Stop stop, boolean onTheWay, boolean continues, boolean goesOn)
            implements Step {
        public Group {
            pieces = List.copyOf(pieces);
            if (goesOn != (stop == null)) {
                throw new IllegalArgumentException("a group that goes on has no stop, and only it");
            }
        }

        /** A whole sequence in one group. */
        public Group(List<Piece> pieces, Stop stop, boolean onTheWay) {
            this(pieces, stop, onTheWay, false, false);
        }

        /** A group whose pieces are asked whether they set anything on the way. */
        public Group(List<Piece> pieces, Stop stop) {
            this(pieces, stop, anyOnTheWay(pieces));
        }

        private static boolean anyOnTheWay(List<Piece> pieces) {
            for (Piece p : pieces) {
                if (p.onTheWay()) {
                    return true;
                }
            }
            return false;
        }

        @Override
        public void accept(Visitor v) {
            v.group(this);
        }
    }

    /** The M functions applied at the block's end. */
    record After(CheckedBlock block) implements Step {
        @Override
        public void accept(Visitor v) {
            v.after(this);
        }
    }
}
