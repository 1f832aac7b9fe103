package gcnc.send;

import gcnc.dmc.Command;
import java.util.ArrayList;
import java.util.List;

/**
 * Follows a compiled program's geometry command by command, as the controller will move: the vector
 * sequences with their pieces in the plane, which sequence each command belongs to, and the estimated
 * seconds of work before each command (a trapezoid per sequence, the dwells). For {@link DmcProgram}.
 */
final class Walker {
    final DmcProgram.Plane plane;
    final double acceleration;
    final List<Sequence> sequences = new ArrayList<>();
    final List<Integer> owner = new ArrayList<>();
    final List<Double> before = new ArrayList<>();
    double[] pos;
    double[] cursor;
    double speed;
    int first = -1;
    List<Sequence.Piece> pieces = new ArrayList<>();
    /** Each piece's own speed ({@code <o}), else the sequence's VS. */
    List<Double> speeds = new ArrayList<>();
    boolean thread;
    double seconds;

    Walker(DmcProgram.Plane plane, double[] home, double acceleration) {
        this.plane = plane;
        this.pos = home.clone();
        this.cursor = home.clone();
        this.acceleration = acceleration > 0 ? acceleration : 256000;
    }

    void line(int i, Command c) {
        before.add(seconds);
        owner.add(first >= 0 ? sequences.size() : -1);
        if (c instanceof Command.VectorSpeed v) {
            speed = v.countsPerSecond().value();
            begin(i);
        } else if (c instanceof Command.VectorPosition v) {
            begin(i);
            double[] to = {pos[0] + v.first(), pos[1] + v.second()};
            pieces.add(new Sequence.Line(i, cursor, to));
            speeds.add(v.speeds().speed() > 0 ? v.speeds().speed() : speed);
            cursor = to;
        } else if (c instanceof Command.CircularArc a) {
            begin(i);
            double r = a.radius().value();
            double[] g = Command.CircularArc.geometry(cursor[0], cursor[1], r, a.start().value(), a.sweep().value());
            double[] to = {g[2], g[3]};
            pieces.add(new Sequence.Arc(i, cursor, to, new double[] {g[0], g[1]}, r, a.start().value(),
                    a.sweep().value()));
            speeds.add(a.speeds().speed() > 0 ? a.speeds().speed() : speed);
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
        } else if (c instanceof Command.Wait w) {
            seconds += w.milliseconds() / 1000.0;
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
            speeds = new ArrayList<>();
            thread = false;
        }
    }

    private void end(int i) {
        if (first < 0) {
            return;
        }
        double length = 0;
        double cruise = 0;
        double top = 0;
        for (int k = 0; k < pieces.size(); k++) {
            double v = speeds.get(k);
            length += pieces.get(k).length();
            cruise += v > 0 ? pieces.get(k).length() / v : 0;
            top = Math.max(top, v);
        }
        double t = 0;
        if (top > 0 && length > 0) {
            // a trapezoid: each piece at its own speed, plus the time to speed up and slow down; a
            // triangle on a short move (the blended corners' slowing is not counted: an estimate)
            double ramp = top * top / acceleration;
            t = length >= ramp ? cruise + top / acceleration : 2 * Math.sqrt(length / acceleration);
        }
        sequences.add(new Sequence(first, i, pos.clone(), cursor.clone(), thread ? 0 : speed,
                thread ? List.of() : List.copyOf(pieces), t));
        for (int k = first; k <= i; k++) {
            owner.set(k, sequences.size() - 1);
        }
        seconds += t;
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

    double[] secondsBefore(int n) {
        double[] a = new double[n];
        for (int i = 0; i < n; i++) {
            a[i] = before.get(i);
        }
        return a;
    }
}
