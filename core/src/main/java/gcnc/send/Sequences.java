package gcnc.send;

import gcnc.dmc.Command;
import java.util.ArrayList;
import java.util.List;

/**
 * Where a compiled program's motions lie in the vector plane, command by command: the vector
 * sequences with their pieces (Galil plane coordinates: what the controller's {@code _CSS} and
 * positions are compared with on a resume) and which sequence each command belongs to. No time: the
 * seconds of every line are the simulator's cycle clock, as the compile replayed it
 * ({@link DmcProgram.Clock}), so the run's time left ends on the compile's cycle time. For {@link DmcProgram}.
 */
final class Sequences {
    final DmcProgram.Plane plane;
    final List<Sequence> sequences = new ArrayList<>();
    final List<Integer> owner = new ArrayList<>();
    private final DmcProgram.Clock clock;
    double[] pos;
    double[] cursor;
    double speed;
    int first = -1;
    List<Sequence.Piece> pieces = new ArrayList<>();
    boolean thread;

    Sequences(DmcProgram.Plane plane, double[] home, DmcProgram.Clock clock) {
        this.plane = plane;
        this.pos = home.clone();
        this.cursor = home.clone();
        this.clock = clock;
    }

    void line(int i, Command c) {
        owner.add(first >= 0 ? sequences.size() : -1);
        if (c instanceof Command.VectorSpeed v) {
            speed = v.countsPerSecond().value();
            begin(i);
        } else if (c instanceof Command.VectorPosition v) {
            begin(i);
            double[] to = {pos[0] + v.first(), pos[1] + v.second()};
            pieces.add(new Sequence.Line(i, cursor, to));
            cursor = to;
        } else if (c instanceof Command.CircularArc a) {
            begin(i);
            double r = a.radius().value();
            double[] g = Command.CircularArc.geometry(cursor[0], cursor[1], r, a.start().value(), a.sweep().value());
            double[] to = {g[2], g[3]};
            pieces.add(new Sequence.Arc(i, cursor, to, new double[] {g[0], g[1]}, r, a.start().value(),
                    a.sweep().value()));
            cursor = to;
        } else if (c instanceof Command.GearMaster) {
            begin(i);
            thread = true;
        } else if (c instanceof Command.PositionAbsolute p) {
            double[] at = cursor.clone();
            place(at, DmcProgram.Plane.channel(p.first()), p.firstCount());
            place(at, DmcProgram.Plane.channel(p.second()), p.secondCount());
            cursor = at;
        } else if (c instanceof Command.AwaitSequence || c instanceof Command.AfterMotion) {
            end(i);
        }
        if (first >= 0 && owner.get(i) < 0) {
            owner.set(i, sequences.size());
        }
    }

    private void place(double[] at, int channel, long count) {
        if (channel == plane.first()) {
            at[0] = count;
        } else if (channel == plane.second()) {
            at[1] = count;
        }
    }

    private void begin(int i) {
        if (first < 0) {
            first = i;
            cursor = pos.clone();
            pieces = new ArrayList<>();
            thread = false;
        }
    }

    private void end(int i) {
        if (first < 0) {
            return;
        }
        // its time as the simulator's clock ran over its lines (the compile's replay: corners, ramps, a
        // thread pass's spindle-bound speed)
        double t = clock.after(i) - clock.before(first);
        sequences.add(new Sequence(first, i, pos.clone(), cursor.clone(), thread ? 0 : speed,
                thread ? List.of() : List.copyOf(pieces), t));
        for (int k = first; k <= i; k++) {
            owner.set(k, sequences.size() - 1);
        }
        // the controller ends a sequence on whole counts: the next one's origin (VP is measured from it)
        pos = new double[] {Math.rint(cursor[0]), Math.rint(cursor[1])};
        first = -1;
    }

    int[] sequenceOf(int n) {
        int[] a = new int[n];
        for (int i = 0; i < n; i++) {
            a[i] = owner.get(i);
        }
        return a;
    }

    /**
     * Seconds of work done when each of the first {@code n} lines starts: the clock before it, and for
     * a line of a sequence the clock where its sequence starts (the progress adds how far along it the
     * axes are).
     */
    double[] secondsBefore(int n) {
        double[] a = new double[n];
        for (int i = 0; i < n; i++) {
            int s = owner.get(i);
            a[i] = s < 0 ? clock.before(i) : clock.before(sequences.get(s).first());
        }
        return a;
    }
}
