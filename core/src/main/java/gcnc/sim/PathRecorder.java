package gcnc.sim;

import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Keeps the tool path and the places of findings for the SVG (only when one is asked for: this
 * is the one part of the simulator whose memory grows with the program), in the drawing's
 * half-section millimetres.
 */
final class PathRecorder {
    private final double kx;
    private final double kz;
    private final double centre;
    private final List<Drawing.Move> moves = new ArrayList<>();
    private final List<Drawing.Mark> marks = new ArrayList<>();

    private final MachineProfile profile;

    PathRecorder(MachineProfile profile, double centreX) {
        this.profile = profile;
        this.kx = profile.x().countsPerMm();
        this.kz = profile.z().countsPerMm();
        this.centre = centreX;
    }

    /** One sequence as points {x, z} in machine counts, from G-code line {@code line} of {@code file} (null: the program's). */
    void move(boolean rapid, List<double[]> points, int line, String file) {
        double[] z = new double[points.size()];
        double[] r = new double[points.size()];
        for (int i = 0; i < z.length; i++) {
            z[i] = points.get(i)[1] / kz;
            r[i] = (points.get(i)[0] - centre) / kx;
        }
        moves.add(new Drawing.Move(rapid, z, r, line, file));
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
            return new Drawing(chuck, tail, 0, 0, Double.NaN, new double[0], new double[0], moves, marks, axes(), m, scrub);
        }
        double[][] part = stock.profile();
        return new Drawing(chuck, tail, stock.back(), stock.face(), stock.initialRadius(), part[0], part[1],
                moves, marks, axes(), m, scrub);
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
