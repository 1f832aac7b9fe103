package gcnc.sim;

import java.util.List;

/**
 * Everything the SVG writer draws, in the half-section (z, r) in machine millimetres
 * (r = radius from the spindle centreline). Kept only when an SVG is asked for.
 *
 * @param chuck       chuck outlines
 * @param tailstock   tailstock outlines
 * @param stockBack   z where the blank starts (inside the chuck)
 * @param stockFace   z of the blank's face
 * @param stockRadius initial radius, NaN when there is no stock
 * @param finalZ      final part outline, back to face: z of each point (a face is two points at one z)
 * @param finalR      final part outline: the largest radius of material at each point
 * @param moves       the tool path, one polyline per sequence
 * @param marks       where findings were reported
 * @param program     where the program's coordinates are, for the grid; null when not known (a bare DMC replay)
 * @param machine     the machine: its name, control, chuck face and travel, for the view and the title block
 * @param scrub       the stock before and after one block, when asked for ({@link SimOptions#withScrub}); else null
 * @param pathTolerance the tolerance, mm, the path was compacted to past its budget (0: as recorded; {@code PathRecorder})
 */
public record Drawing(List<Shape> chuck, List<Shape> tailstock, double stockBack, double stockFace,
                      double stockRadius, double[] finalZ, double[] finalR, List<Move> moves, List<Mark> marks,
                      ProgramAxes program, Machine machine, Scrub scrub, double pathTolerance) {
    /** A drawing whose path is as recorded. */
    public Drawing(List<Shape> chuck, List<Shape> tailstock, double stockBack, double stockFace, double stockRadius,
                   double[] finalZ, double[] finalR, List<Move> moves, List<Mark> marks, ProgramAxes program,
                   Machine machine, Scrub scrub) {
        this(chuck, tailstock, stockBack, stockFace, stockRadius, finalZ, finalR, moves, marks, program, machine, scrub, 0);
    }

    /** A drawing without a scrub. */
    public Drawing(List<Shape> chuck, List<Shape> tailstock, double stockBack, double stockFace, double stockRadius,
                   double[] finalZ, double[] finalR, List<Move> moves, List<Mark> marks, ProgramAxes program,
                   Machine machine) {
        this(chuck, tailstock, stockBack, stockFace, stockRadius, finalZ, finalR, moves, marks, program, machine, null);
    }

    /**
     * The stock around the first run of one G-code line's moves (a block, or all the passes of a
     * cycle written on it): its outline before the run ({@code beforeZ}, {@code beforeR}: points of
     * the largest radius of material, as {@code finalZ}/{@code finalR}) and after it, so that
     * what the block removed lies between the two; the tool's insert and holder ({@code holder}
     * null when it has none) placed where the run ended; the run's moves, {@code first} to
     * {@code last} (indices into {@link #moves}). With no blank the outlines are empty.
     */
    public record Scrub(int line, int first, int last, int tool, double[] beforeZ, double[] beforeR, double[] afterZ,
                        double[] afterR, Shape insert, Shape holder) {
    }

    /**
     * The machine around the part, in the drawing's millimetres.
     *
     * @param name       the profile's name
     * @param control    its control's name
     * @param chuckFace  z of the jaws' front face, NaN without a chuck
     * @param travel     {zMin, zMax, rMin, rMax}: the axes' travel, r from the spindle centreline
     */
    public record Machine(String name, String control, double chuckFace, double[] travel) {
    }

    /** z of the tailstock centre's point, NaN without a tailstock. */
    public double tailstockTip() {
        return tailstock.isEmpty() ? Double.NaN : tailstock.get(0).z()[0];
    }

    /**
     * The program's coordinates in the drawing: programmed Z value q is at z = z0 + q * zPer mm,
     * programmed X value p (a diameter where the control reads one) at radius r0 + p * xPer mm.
     */
    public record ProgramAxes(double z0, double zPer, double r0, double xPer) {
        double z(double q) {
            return z0 + q * zPer;
        }

        double r(double p) {
            return r0 + p * xPer;
        }

        double programZ(double z) {
            return (z - z0) / zPer;
        }

        double programX(double r) {
            return (r - r0) / xPer;
        }
    }

    /**
     * One sequence of the path as a polyline; rapid ones are drawn dashed. {@code line} is the
     * G-code line it came from (as its findings are reported), so a front end can link the two;
     * {@code file} the file that line is in when it is not the program's own (a called program
     * beside it), else null.
     */
    public record Move(boolean rapid, double[] z, double[] r, int line, String file) {
        /** A move from a line of the program's own file. */
        public Move(boolean rapid, double[] z, double[] r, int line) {
            this(rapid, z, r, line, null);
        }
    }

    /**
     * A finding at a place: its code (E305 ...), the block it is on ("N110", "line 12"), the G-code
     * line its diagnostic is reported at (0: none known), the point, and the tool's outline
     * (insert, holder; mm, absolute) where its tip was then: empty for a tool without an outline.
     */
    public record Mark(String code, String block, int line, double z, double r, List<Shape> tool) {
        public Mark {
            tool = List.copyOf(tool);
        }
    }
}
