package gcnc.ir;

/**
 * What one block makes the machine do, in machine counts. A block may hold several
 * (G28 = rapid to the intermediate point, then rapid to the reference point).
 */
public sealed interface Motion permits Motion.PathMotion, Motion.Dwell {

    /**
     * The dispatch the compiler checks: every consumer of motions (the backends, the simulator,
     * the checker) implements all of it, so a new kind of motion does not compile until each
     * handles it (Java 17 has no pattern switch).
     */
    interface Visitor<R> {
        R linear(Linear l);

        R arc(Arc a);

        R dwell(Dwell d);

        R thread(Thread t);
    }

    <R> R accept(Visitor<R> v);

    /** A motion along the path (a line, an arc, a thread pass: all but a dwell), from a point to a point at a feed. */
    sealed interface PathMotion extends Motion permits Linear, Arc, Thread {
        Point from();

        Point to();

        /** The feed, or null for a rapid. */
        Feed feed();
    }

    /** G00 (rapid: feed is null) or G01. */
    record Linear(boolean rapid, Point from, Point to, Feed feed) implements PathMotion {
        @Override
        public <R> R accept(Visitor<R> v) {
            return v.linear(this);
        }
    }

    /**
     * G02 (clockwise = true) or G03 as the lathe drawing shows them, with the exact centre and radius.
     * {@code words} keeps R / I,K as programmed (in counts) for the thesis dialect's formulas.
     */
    record Arc(boolean clockwise, Point from, Point to, Point centre, double radius, Feed feed, ArcWords words)
            implements PathMotion {
        @Override
        public <R> R accept(Visitor<R> v) {
            return v.arc(this);
        }
    }

    /** The radius words of an arc block, scaled to counts; r is null when I/K were given. */
    record ArcWords(Double r, Double i, Double k) {
    }

    /**
     * One spindle-synchronised thread pass (G32, Fanuc B G33; a pass of G92/G78 or G76) from
     * {@code from} to {@code to} on which Z advances {@code lead} counts per spindle revolution,
     * every pass starting at the same spindle angle. Never a plain feed: the backend gears the axes
     * to the spindle encoder (docs/threading.md). A straight line (X in proportion, for a taper),
     * or, with a chamfered pull-out (Haas M23), two geared segments: the straight line from
     * {@code from} to {@code chamferStart}, then the chamfer to {@code to}, on which Z goes on at the
     * same lead and X moves out at the chamfer's angle.
     *
     * @param lead          Z counts per spindle revolution, greater than 0
     * @param rpm           the spindle speed the pass is cut at (G97)
     * @param reverse       the spindle turns M04 (its encoder counts down)
     * @param feed          the lead as programmed (F) and the path speed it makes at {@code rpm} along
     *                      the straight part, counts/s
     * @param chamferStart  where the straight part ends and the chamfered pull-out begins; null when the
     *                      pass ends square at {@code to} (M24, G32)
     * @param joints        where the blocks of a continuous G32 thread meet (docs/threading.md,
     *                      "Continuous threads"): the pass runs geared through each, the ratios changing
     *                      there without a new synchronisation; empty for a pass of one block
     * @param startAngle    the spindle angle the pass starts at, degrees past the encoder's whole
     *                      revolution, 0 to less than 360: a multi-start thread's start (G92/Haas G76 Q)
     */
    record Thread(Point from, Point to, double lead, double rpm, boolean reverse, Feed feed, Point chamferStart,
                  java.util.List<Point> joints, double startAngle) implements PathMotion {
        public Thread {
            joints = java.util.List.copyOf(joints);
            if (!(startAngle >= 0 && startAngle < 360)) {
                throw new IllegalArgumentException("a thread's start angle is 0 to less than 360 degrees, not " + startAngle);
            }
        }

        /** A pass of one block that starts at the encoder's whole revolution (start angle 0). */
        public Thread(Point from, Point to, double lead, double rpm, boolean reverse, Feed feed, Point chamferStart) {
            this(from, to, lead, rpm, reverse, feed, chamferStart, java.util.List.of(), 0);
        }

        /** A continuous G32 thread through {@code joints}, from the whole revolution. */
        public Thread(Point from, Point to, double lead, double rpm, boolean reverse, Feed feed, Point chamferStart,
                      java.util.List<Point> joints) {
            this(from, to, lead, rpm, reverse, feed, chamferStart, joints, 0);
        }

        /** A pass of one block that starts {@code startAngle} degrees past the whole revolution. */
        public Thread(Point from, Point to, double lead, double rpm, boolean reverse, Feed feed, Point chamferStart,
                      double startAngle) {
            this(from, to, lead, rpm, reverse, feed, chamferStart, java.util.List.of(), startAngle);
        }

        /**
         * Where the geared ratios change, in order: the joints of a continuous thread, then the
         * chamfer's start. The pass is {@code corners().size() + 1} geared segments.
         */
        public java.util.List<Point> corners() {
            if (chamferStart == null) {
                return joints;
            }
            java.util.List<Point> all = new java.util.ArrayList<>(joints);
            all.add(chamferStart);
            return all;
        }

        /** Whether the pass ends with a chamfered pull-out (two geared segments). */
        public boolean chamfered() {
            return chamferStart != null;
        }

        /** Where the straight geared part ends: the chamfer's start, or {@code to}. */
        public Point straightEnd() {
            return chamferStart != null ? chamferStart : to;
        }

        @Override
        public <R> R accept(Visitor<R> v) {
            return v.thread(this);
        }
    }

    /** G04: wait this many seconds. */
    record Dwell(double seconds) implements Motion {
        @Override
        public <R> R accept(Visitor<R> v) {
            return v.dwell(this);
        }
    }
}
