package gcnc.studio;

import com.google.gson.JsonArray;
import com.google.gson.JsonObject;
import gcnc.sim.Drawing;
import gcnc.sim.Shape;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The simulator's drawing as the page draws it ({@code POST /api/simulate}'s {@code drawing}, the
 * scrub's outlines): every point in the program's coordinates (Z as the program writes Z, X as it
 * writes X), each move and each finding with its G-code line.
 */
final class DrawingJson {
    private DrawingJson() {
    }

    /** A stock outline with the points of each flat stretch but its ends left out: the same steps, a much shorter answer. */
    static JsonObject outline(double[] z, double[] r, Frame f) {
        List<Integer> keep = new ArrayList<>();
        for (int i = 0; i < z.length; i++) {
            if (i == 0 || i == z.length - 1 || r[i] != r[i - 1] || r[i] != r[i + 1]) {
                keep.add(i);
            }
        }
        double[] zs = new double[keep.size()];
        double[] rs = new double[keep.size()];
        for (int k = 0; k < zs.length; k++) {
            zs[k] = z[keep.get(k)];
            rs[k] = r[keep.get(k)];
        }
        JsonObject o = new JsonObject();
        o.add("z", f.zs(zs));
        o.add("x", f.xs(rs));
        return o;
    }


    static JsonObject shape(Shape s, Frame f) {
        JsonObject o = new JsonObject();
        o.add("z", f.zs(java.util.Arrays.copyOf(s.z(), s.size())));
        o.add("x", f.xs(java.util.Arrays.copyOf(s.r(), s.size())));
        return o;
    }

    /**
     * The drawing in the program's coordinates: z along the spindle as the program writes Z, x as the
     * program writes X (a diameter on a lathe whose control reads one). Without a program frame (no
     * move), machine millimetres with x as twice the radius.
     */
    static JsonObject drawing(Drawing d, java.util.function.Function<String, Optional<String>> fileNames) {
        Frame f = new Frame(d.program());
        JsonObject o = new JsonObject();
        JsonArray moves = new JsonArray();
        for (Drawing.Move m : d.moves()) {
            JsonObject mv = new JsonObject();
            mv.addProperty("line", m.line());
            if (m.file() != null) { // a called program's line: the page opens that file to show it
                Optional<String> named = fileNames.apply(m.file());
                if (named.isPresent()) {
                    mv.addProperty("file", named.get());
                } else {
                    mv.addProperty("elsewhere", true);
                }
            }
            mv.addProperty("rapid", m.rapid());
            mv.add("z", f.zs(m.z()));
            mv.add("x", f.xs(m.r()));
            moves.add(mv);
        }
        o.add("moves", moves);
        o.add("chuck", shapes(d.chuck(), f));
        o.add("tailstock", shapes(d.tailstock(), f));
        if (!Double.isNaN(d.stockRadius())) {
            JsonObject stock = new JsonObject();
            stock.addProperty("zBack", f.z(d.stockBack()));
            stock.addProperty("zFace", f.z(d.stockFace()));
            stock.addProperty("x", f.x(d.stockRadius()));
            stock.addProperty("xAxis", f.x(0));
            JsonObject part = new JsonObject();
            part.add("z", f.zs(d.finalZ()));
            part.add("x", f.xs(d.finalR()));
            stock.add("final", part);
            o.add("stock", stock);
        }
        JsonArray marks = new JsonArray();
        for (Drawing.Mark m : d.marks()) {
            JsonObject mk = new JsonObject();
            mk.addProperty("code", m.code());
            mk.addProperty("block", m.block());
            mk.addProperty("line", Math.max(1, m.line())); // as its diagnostic's line (the error list's)
            mk.addProperty("z", f.z(m.z()));
            mk.addProperty("x", f.x(m.r()));
            marks.add(mk);
        }
        o.add("marks", marks);
        o.addProperty("programFrame", d.program() != null);
        return o;
    }

    private static JsonArray shapes(List<Shape> shapes, Frame f) {
        JsonArray a = new JsonArray();
        for (Shape s : shapes) {
            JsonObject o = new JsonObject();
            o.add("z", f.zs(s.z()));
            o.add("x", f.xs(s.r()));
            a.add(o);
        }
        return a;
    }

    /** From the drawing's (z, r) millimetres to the program's (Z, X). */
    record Frame(Drawing.ProgramAxes axes) {
        double z(double z) {
            return round(axes == null ? z : (z - axes.z0()) / axes.zPer());
        }

        double x(double r) {
            return round(axes == null ? 2 * r : (r - axes.r0()) / axes.xPer());
        }

        JsonArray zs(double[] v) {
            JsonArray a = new JsonArray();
            for (double d : v) {
                a.add(z(d));
            }
            return a;
        }

        JsonArray xs(double[] v) {
            JsonArray a = new JsonArray();
            for (double d : v) {
                a.add(x(d));
            }
            return a;
        }

        /** Micrometres are plenty for a drawing, and keep the JSON short. */
        private static double round(double v) {
            if (!Double.isFinite(v)) {
                return v > 0 ? 1e9 : -1e9;
            }
            return Math.round(v * 1000) / 1000.0;
        }
    }
}
