package gcnc.sim;

import java.util.ArrayList;
import java.util.List;

/**
 * The motions the replay ran, each followed from its first line to the wait for it and handed on as a
 * {@link Sequence} (Galil plane coordinates, the DMC line of every segment, the cycle clock over its
 * lines) to whoever listens: the sender's view of the program (issue 32, item 2). The controller tells
 * it what it does ({@link ReplayCommands}, {@link VectorBuffer}); the {@link Simulator} tells it which
 * line runs and the clock around it. Nothing is kept or made while nobody listens.
 */
final class SequenceLog {
    private Simulator.Replayed out;
    /** The DMC line being run (0-based), and the clock before it. */
    private int index = -1;
    private double before;
    /** The first line of the motion under way, -1 when none; the clock before it. */
    private int first = -1;
    private double firstBefore;
    private double[] start;
    private double[] end;
    private double speed;
    private boolean thread;
    private List<Sequence.Piece> pieces;
    /** The line being run waits for the motion: it is handed on once the line's clock is known. */
    private boolean waited;

    void listen(Simulator.Replayed r) {
        out = r;
    }

    boolean listening() {
        return out != null;
    }

    /** The next line of the DMC starts running, the clock at {@code secondsBefore}. */
    void running(double secondsBefore) {
        index++;
        before = secondsBefore;
    }

    /**
     * A command of a motion runs (VS, a segment, a thread pass's GA) with the axes at ({@code g1, g2}),
     * Galil counts: the first after the last wait starts the motion's lines.
     */
    void open(double g1, double g2) {
        if (out == null || first >= 0) {
            return;
        }
        first = index;
        firstBefore = before;
        start = new double[] {g1, g2};
        end = start.clone();
        pieces = new ArrayList<>();
        thread = false;
    }

    /** VP: a straight segment between two points of the Galil plane. */
    void line(double from1, double from2, double to1, double to2) {
        if (first >= 0) {
            pieces.add(new Sequence.Line(index, new double[] {from1, from2}, new double[] {to1, to2}));
        }
    }

    /** CR: an arc about ({@code c1, c2}), from angle {@code theta} sweeping {@code delta} degrees, as the command gives them. */
    void arc(double from1, double from2, double to1, double to2, double c1, double c2, double r, double theta,
             double delta) {
        if (first >= 0) {
            pieces.add(new Sequence.Arc(index, new double[] {from1, from2}, new double[] {to1, to2},
                    new double[] {c1, c2}, r, theta, delta));
        }
    }

    /** The motion starts at {@code speed} and ends at ({@code e1, e2}); a thread pass when {@code geared}. */
    void started(double speed, double e1, double e2, boolean geared) {
        if (first >= 0) {
            this.speed = speed;
            end = new double[] {e1, e2};
            thread |= geared;
        }
    }

    /** AMS, a thread pass's AM: the line being run waits for the motion. */
    void waited() {
        waited = first >= 0;
    }

    /** The line run ends with the clock at {@code secondsAfter}: a motion it waited for is handed on. */
    void ran(double secondsAfter) {
        if (!waited) {
            return;
        }
        waited = false;
        out.sequence(new Sequence(first, index, start, end, thread ? 0 : speed,
                thread ? List.of() : List.copyOf(pieces), secondsAfter - firstBefore));
        first = -1;
    }
}
