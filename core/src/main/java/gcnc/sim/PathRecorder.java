package gcnc.sim;

import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Keeps the tool path and the places of findings for the SVG (only when one is asked for), in the
 * drawing's half-section millimetres.
 *
 * <p>The path is bounded (issue 35): it holds at most {@link #MOST_POINTS} points. A program whose
 * path fits is kept as recorded, one polyline per G-code line of each sequence, so a small
 * program's drawing is what it always was. Past the budget the path is compacted to what its
 * drawing can show: consecutive moves of one kind (rapid or feed) and one tool that join end to
 * end become one polyline, a point within the tolerance of the segment between its kept
 * neighbours goes ({@link PathDecimation}), and a polyline that, snapped to the tolerance, is one
 * already kept (a roughing cycle run again) is left out. The tolerance starts at a quarter of a
 * pixel of a drawing of the whole path so far ({@link SvgWriter#WIDTH} pixels across its extent;
 * never below one count) and doubles for as long as the path is still over half the budget, so
 * a long program costs the same memory as a short one. What is never merged nor dropped: a
 * change between rapid and feed, a change of tool, and every finding (its marks are kept apart).
 * With a scrub asked for (the studio) the path is kept whole: the scrub's run is indices into it.
 */
final class PathRecorder {
    /** Points of the path kept at most (about 8 MiB); and so at most half as many polylines. */
    static final int MOST_POINTS = 1 << 18;
    /** An open polyline is closed (and a new one begun at its last point) at this many points. */
    private static final int OPEN_MOST = 4096;
    private final double kx;
    private final double kz;
    private final double centre;
    private final List<Drawing.Move> moves = new ArrayList<>();
    private final List<Drawing.Mark> marks = new ArrayList<>();

    private final MachineProfile profile;
    /** Whether the path may be compacted (not with a scrub, whose run indexes the moves). */
    private final boolean compactable;
    /** The tool of each move, to keep a tool change where two moves would otherwise join. */
    private int[] tools = new int[64];
    /** Points held, the open polyline's included. */
    private long points;
    /** The compaction's tolerance, mm; 0 while the path is as recorded. */
    private double tolerance;
    /** The snapped hashes of the polylines kept since the last compaction. */
    private PathDecimation.LongSet seen;
    private boolean compacting;
    /** The extent of every point recorded, {zMin, zMax, rMin, rMax}. */
    private final double[] extent = {Double.MAX_VALUE, -Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE};

    /** The polyline being joined (compacted path only): its points, kind, tool and first line. */
    private double[] openZ = new double[64];
    private double[] openR = new double[64];
    private int openN;
    private boolean openRapid;
    private int openTool;
    private int openLine;
    private String openFile;

    PathRecorder(MachineProfile profile, double centreX) {
        this(profile, centreX, true);
    }

    PathRecorder(MachineProfile profile, double centreX, boolean compactable) {
        this.profile = profile;
        this.kx = profile.x().countsPerMm();
        this.kz = profile.z().countsPerMm();
        this.centre = centreX;
        this.compactable = compactable;
    }

    /** One sequence as points {x, z} in machine counts, from G-code line {@code line} of {@code file} (null: the program's). */
    void move(boolean rapid, List<double[]> points, int line, String file) {
        move(rapid, points, line, file, 0);
    }

    /** The same with the tool that made it: two tools' moves are never joined. */
    void move(boolean rapid, List<double[]> poly, int line, String file, int tool) {
        double[] z = new double[poly.size()];
        double[] r = new double[poly.size()];
        for (int i = 0; i < z.length; i++) {
            z[i] = poly.get(i)[1] / kz;
            r[i] = (poly.get(i)[0] - centre) / kx;
            extent[0] = Math.min(extent[0], z[i]);
            extent[1] = Math.max(extent[1], z[i]);
            extent[2] = Math.min(extent[2], r[i]);
            extent[3] = Math.max(extent[3], r[i]);
        }
        if (tolerance == 0) {
            keep(new Drawing.Move(rapid, z, r, line, file), tool);
        } else {
            join(rapid, tool, z, r, line, file);
        }
        if (compactable && !compacting && points > MOST_POINTS) {
            compact();
        }
    }

    /** The tolerance the path was compacted to, mm; 0 when it is as recorded. */
    double tolerance() {
        return tolerance;
    }

    private void keep(Drawing.Move m, int tool) {
        if (moves.size() == tools.length) {
            tools = Arrays.copyOf(tools, 2 * tools.length);
        }
        tools[moves.size()] = tool;
        moves.add(m);
        points += m.z().length;
    }

    /** Adds points to the open polyline, closing it first where they do not continue it. */
    private void join(boolean rapid, int tool, double[] z, double[] r, int line, String file) {
        if (z.length == 0) {
            return;
        }
        boolean continues = openN > 0 && openRapid == rapid && openTool == tool && openZ[openN - 1] == z[0]
                && openR[openN - 1] == r[0];
        if (openN > 0 && (!continues || openN + z.length > OPEN_MOST)) {
            double lz = openZ[openN - 1];
            double lr = openR[openN - 1];
            close();
            if (continues) { // the same polyline, split at its last point
                begin(rapid, tool, line, file);
                add(lz, lr);
            }
        }
        if (openN == 0) {
            begin(rapid, tool, line, file);
        }
        for (int i = 0; i < z.length; i++) {
            if (i > 0 || openN == 0 || openZ[openN - 1] != z[i] || openR[openN - 1] != r[i]) {
                add(z[i], r[i]);
            }
        }
    }

    private void begin(boolean rapid, int tool, int line, String file) {
        openRapid = rapid;
        openTool = tool;
        openLine = line;
        openFile = file;
    }

    private void add(double z, double r) {
        if (openN == openZ.length) {
            openZ = Arrays.copyOf(openZ, 2 * openN);
            openR = Arrays.copyOf(openR, 2 * openN);
        }
        openZ[openN] = z;
        openR[openN++] = r;
        points++;
    }

    /** Decimates the open polyline and keeps it unless one like it is kept already. */
    private void close() {
        if (openN == 0) {
            return;
        }
        points -= openN;
        double[][] d = PathDecimation.decimate(Arrays.copyOf(openZ, openN), Arrays.copyOf(openR, openN), tolerance);
        openN = 0;
        if (seen.add(PathDecimation.snappedHash(openRapid, openTool, d[0], d[1], tolerance))) {
            keep(new Drawing.Move(openRapid, d[0], d[1], openLine, openFile), openTool);
        }
    }

    /** Compacts the path at a coarser tolerance until it holds at most half the budget (see the class comment). */
    private void compact() {
        compacting = true;
        do {
            if (tolerance > 0) {
                close();
            }
            tolerance = tolerance == 0 ? firstTolerance() : 2 * tolerance;
            List<Drawing.Move> old = new ArrayList<>(moves);
            int[] oldTools = tools;
            moves.clear();
            tools = new int[64];
            points = 0;
            seen = new PathDecimation.LongSet();
            for (int i = 0; i < old.size(); i++) {
                Drawing.Move m = old.get(i);
                old.set(i, null);
                join(m.rapid(), oldTools[i], m.z(), m.r(), m.line(), m.file());
            }
        } while (points > MOST_POINTS / 2);
        compacting = false;
    }

    /** A quarter of a pixel of a drawing of everything recorded so far, and at least one count. */
    private double firstTolerance() {
        double across = Math.max(extent[1] - extent[0], extent[3] - extent[2]);
        return Math.max(1 / Math.min(kx, kz), across / SvgWriter.WIDTH / 4);
    }

    /** A finding on a block ("N110", "line 12"; reported at G-code {@code line}) at machine counts (x, z), drawn without the tool. */
    void mark(String code, String block, int line, double x, double z) {
        mark(code, block, line, x, z, null, 1, null);
    }

    /**
     * A finding on a block ("N110", "line 12"; reported at G-code {@code line}) at machine counts (x, z), with the tool's outline
     * (insert and holder, relative to its tip; mirrored for a tool on the -X side) placed at
     * {@code tip} (machine counts {x, z}; null: no outline).
     */
    void mark(String code, String block, int line, double x, double z, SimMachine.ToolShape tool, int side, double[] tip) {
        List<Shape> outline = new ArrayList<>();
        if (tool != null && tip != null) {
            double tz = tip[1] / kz;
            double tr = (tip[0] - centre) / kx;
            for (Shape part : tool.parts()) {
                double[] oz = new double[part.size()];
                double[] or = new double[part.size()];
                for (int i = 0; i < oz.length; i++) {
                    oz[i] = tz + part.z()[i] / kz;
                    or[i] = tr + side * part.r()[i] / kx;
                }
                outline.add(new Shape(oz, or));
            }
        }
        marks.add(new Drawing.Mark(code, block, line, z / kz, (x - centre) / kx, outline));
    }

    /** The program frame of the first feed move (else of the first move): the grid of the drawing is in its coordinates. */
    private Drawing.ProgramAxes program;
    private Drawing.ProgramAxes firstMove;

    void frame(gcnc.ir.ProgramFrame f, boolean rapid) {
        if (f == null || program != null) {
            return;
        }
        Drawing.ProgramAxes a = new Drawing.ProgramAxes(f.origin().z() / kz, f.perZ() / kz,
                (f.origin().x() - centre) / kx, f.perX() / kx);
        if (!rapid) {
            program = a;
        } else if (firstMove == null) {
            firstMove = a;
        }
    }

    /** The drawing; {@code scrub} the stock around one block when one was asked for, else null. */
    Drawing drawing(SimMachine machine, Stock stock, Drawing.Scrub scrub) {
        if (tolerance > 0) {
            close();
        }
        List<Shape> chuck = new ArrayList<>();
        List<Shape> tail = new ArrayList<>();
        for (Shape s : machine.chuck()) {
            chuck.add(scale(s));
        }
        for (Shape s : machine.tailstock()) {
            tail.add(scale(s));
        }
        Drawing.Machine m = new Drawing.Machine(profile.name(), profile.control().name(), machine.chuckFace() / kz,
                new double[] {profile.z().min() / kz, profile.z().max() / kz, (profile.x().min() - centre) / kx,
                    (profile.x().max() - centre) / kx});
        if (stock == null) {
            return new Drawing(chuck, tail, 0, 0, Double.NaN, new double[0], new double[0], moves, marks, axes(), m, scrub,
                    tolerance);
        }
        double[][] part = stock.profile();
        return new Drawing(chuck, tail, stock.back(), stock.face(), stock.initialRadius(), part[0], part[1],
                moves, marks, axes(), m, scrub, tolerance);
    }

    private Drawing.ProgramAxes axes() {
        return program != null ? program : firstMove;
    }

    private Shape scale(Shape s) {
        double[] z = Arrays.copyOf(s.z(), s.size());
        double[] r = Arrays.copyOf(s.r(), s.size());
        for (int i = 0; i < z.length; i++) {
            z[i] = Math.max(-1e6, Math.min(1e6, z[i] / kz));
            r[i] /= kx;
        }
        return new Shape(z, r);
    }
}
