package gcnc.ir;

/**
 * What one block makes the machine do, in machine counts. A block may hold several
 * (G28 = rapid to the intermediate point, then rapid to the reference point).
 */
public sealed interface Motion permits Motion.Linear, Motion.Arc, Motion.Dwell {

    /** G00 (rapid: feed is null) or G01. */
    record Linear(boolean rapid, Point from, Point to, Feed feed) implements Motion {
    }

    /**
     * G02 (clockwise = true) or G03 as the lathe drawing shows them, with the exact centre and radius.
     * {@code words} keeps R / I,K as programmed (in counts) for the thesis dialect's formulas.
     */
    record Arc(boolean clockwise, Point from, Point to, Point centre, double radius, Feed feed, ArcWords words)
            implements Motion {
    }

    /** The radius words of an arc block, scaled to counts; r is null when I/K were given. */
    record ArcWords(Double r, Double i, Double k) {
    }

    /** G04: wait this many seconds. */
    record Dwell(double seconds) implements Motion {
    }
}
