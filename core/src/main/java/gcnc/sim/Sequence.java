package gcnc.sim;

import java.util.List;

/**
 * One motion of a program as the simulator's controller ran it, published to whoever listens
 * ({@link Simulator.Replayed#sequence}; the compile's observer, gcnc.CompileObserver#sequence): the
 * sender's sequences are these (gcnc.send.DmcProgram), so that its resume, progress and way back rest on
 * the replay that judged the program. It is a vector sequence ({@code VS},
 * {@code VP}/{@code CR}..., {@code VE}, {@code BGS}, {@code AMS}) or a thread pass ({@code GA} ...
 * {@code PA}, {@code BG}, {@code AM}), with where it starts and ends in Galil coordinates of the
 * vector plane (absolute: the program starts at the profile's home).
 *
 * @param first    index of its first DMC line (0-based, as the controller numbers program lines): its
 *                 {@code VS}, its first segment or a thread pass's {@code GA}, the first after the last wait
 * @param last     index of its last line ({@code AMS} or {@code AM}: the wait for it)
 * @param start    Galil coordinates where it starts: where the axes stand, whole counts
 * @param end      Galil coordinates where it ends: its last segment's end (an arc's may be a fraction
 *                 of a count off; the controller ends on the nearest count, where the next one starts)
 * @param speed    its VS, counts/s (0 for a thread pass)
 * @param pieces   its segments, in order; empty for a thread pass (it cannot be entered mid-way)
 * @param seconds  how long it takes: the simulator's cycle clock over its lines (corner speeds, ramps, a
 *                 thread pass at the spindle's speed), as the compile replayed them
 */
public record Sequence(int first, int last, double[] start, double[] end, double speed, List<Piece> pieces,
                       double seconds) {
    /** A segment of a vector sequence, and the program line (0-based) that gives it. */
    public sealed interface Piece permits Line, Arc {
        int line();

        double[] from();

        double[] to();

        /** Its length along the path, counts. */
        double length();
    }

    /** {@code VP}: a straight line. */
    public record Line(int line, double[] from, double[] to) implements Piece {
        public double length() {
            return Math.hypot(to[0] - from[0], to[1] - from[1]);
        }
    }

    /**
     * {@code CR r,theta,delta}: an arc about {@code centre}, from angle {@code theta} sweeping
     * {@code delta} degrees (counter-clockwise positive, 0 along the plane's first channel).
     */
    public record Arc(int line, double[] from, double[] to, double[] centre, double radius, double theta, double delta)
            implements Piece {
        public double length() {
            return Math.abs(radius * Math.toRadians(delta));
        }
    }

    public boolean isThreadPass() {
        return pieces.isEmpty();
    }

    /** The path length of its pieces before piece {@code k}, counts. */
    public double lengthBefore(int k) {
        double l = 0;
        for (int i = 0; i < k && i < pieces.size(); i++) {
            l += pieces.get(i).length();
        }
        return l;
    }

    /** The index of the piece that line {@code index} gives, or -1. */
    public int pieceAt(int index) {
        for (int k = 0; k < pieces.size(); k++) {
            if (pieces.get(k).line() == index) {
                return k;
            }
        }
        return -1;
    }
}
