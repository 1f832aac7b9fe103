package gcnc.sim;

import java.io.IOException;
import java.io.Writer;
import java.util.Locale;

/**
 * Draws a simulation as an SVG half-section for setting up the machine (Z to the right, radius
 * up, machine mm): the chuck's jaws, the tailstock, the blank, the finished part outline (mirrored
 * below the centreline too), the axes' travel, the tool path (rapids dashed, feeds solid, rapids in
 * a layer of their own that can be left out), each finding with its block and the tool's outline
 * where it was, and a grid in the program's coordinates (X as the program writes it, Z from work
 * zero). The view ({@link SvgView}) fits the blank and the chuck's face, within a capped aspect
 * ratio; below it a legend, the view's extent in program and machine terms, and a title block
 * ({@link SvgTitle}). Nothing in it depends on the date or the machine it was drawn on, so a
 * drawing of the same run is the same bytes.
 */
public final class SvgWriter {
    static final double WIDTH = 1000;

    private SvgWriter() {
    }

    public static void write(SimReport report, String title, Writer w) throws IOException {
        write(report, title, w, true);
    }

    /** The drawing, with the rapid moves or without them ({@code rapids} false: feeds and findings only). */
    public static void write(SimReport report, String title, Writer w, boolean rapids) throws IOException {
        write(report, title, null, w, rapids);
    }

    /**
     * The drawing of a program file ({@code file}, as the title block names it) whose program number
     * is {@code number} ("O1201"; null when it has none).
     */
    public static void write(SimReport report, String file, String number, Writer w, boolean rapids)
            throws IOException {
        Drawing d = report.drawing();
        if (d == null) {
            throw new IllegalStateException("simulate with SimOptions.withPath() to draw");
        }
        SvgView v = SvgView.of(d);
        double height = v.height();
        double total = height + SvgTitle.HEIGHT;
        w.write(String.format(Locale.ROOT, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\""
                + " viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"14\">\n",
                WIDTH, total, WIDTH, total));
        w.write("<title>" + escape(file) + "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
        w.write(String.format(Locale.ROOT, "<defs><clipPath id=\"view\"><rect x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.1f\"/>"
                + "</clipPath></defs>\n<g clip-path=\"url(#view)\">\n", WIDTH, height));
        travel(w, d.machine().travel(), v);
        if (!Double.isNaN(d.stockRadius())) {
            part(w, d, v);
        }
        for (Shape sh : d.chuck()) {
            w.write(shape(sh, v, "#888888", "0.8"));
        }
        for (Shape sh : d.tailstock()) {
            w.write(shape(sh, v, "#6688aa", "0.8"));
        }
        w.write(String.format(Locale.ROOT, "<line x1=\"0\" y1=\"%.1f\" x2=\"%.0f\" y2=\"%.1f\" stroke=\"black\""
                + " stroke-dasharray=\"12 4 2 4\"/>\n", v.y(0), WIDTH, v.y(0)));
        if (d.program() != null) {
            grid(w, d.program(), v);
        }
        path(w, d, v, rapids);
        marks(w, d, v);
        w.write("</g>\n");
        SvgTitle.write(w, report, v, rapids, file, number);
        w.write("</svg>\n");
    }

    /** The finished part over the blank, and mirrored below the centreline: the whole turned silhouette. */
    private static void part(Writer w, Drawing d, SvgView v) throws IOException {
        w.write("<polygon fill=\"#f3e3c3\" stroke=\"#c8a870\" points=\"" + v.pt(d.stockBack(), 0)
                + v.pt(d.stockBack(), d.stockRadius()) + v.pt(d.stockFace(), d.stockRadius()) + v.pt(d.stockFace(), 0)
                + "\"/>\n");
        StringBuilder part = new StringBuilder(v.pt(d.stockBack(), 0));
        for (int i = 0; i < d.finalZ().length; i++) {
            if (i == 0 || i == d.finalZ().length - 1 || d.finalR()[i] != d.finalR()[i - 1]
                    || d.finalR()[i] != d.finalR()[i + 1]) {
                part.append(v.pt(d.finalZ()[i], d.finalR()[i]));
            }
        }
        part.append(v.pt(d.stockFace(), 0));
        w.write("<polygon fill=\"#b08040\" stroke=\"#603010\" stroke-width=\"1.5\" points=\"" + part + "\"/>\n");
        w.write("<polygon fill=\"#b08040\" fill-opacity=\"0.55\" stroke=\"#603010\" transform=\"translate(0 "
                + String.format(Locale.ROOT, "%.2f", 2 * v.y(0)) + ") scale(1 -1)\" points=\"" + part + "\"/>\n");
    }

    /**
     * The travel of the axes as a dashed box (above the centreline, where the path is), labelled
     * inside each limit that falls in the view.
     */
    private static void travel(Writer w, double[] t, SvgView v) throws IOException {
        double x0 = clampX(v.x(t[0]));
        double x1 = clampX(v.x(t[1]));
        double y0 = clampY(v.y(t[3]), v);
        double y1 = clampY(v.y(Math.max(0, t[2])), v);
        w.write(String.format(Locale.ROOT, "<g id=\"travel\"><rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\""
                + " fill=\"none\" stroke=\"#20a020\" stroke-width=\"1.5\" stroke-dasharray=\"3 3\"/>\n", x0, y0,
                Math.max(0, x1 - x0), Math.max(0, y1 - y0)));
        if (v.x(t[0]) >= 0 && v.x(t[0]) < WIDTH) {
            w.write(label(v.x(t[0]) + 3, (y0 + y1) / 2, "Z travel", "#20a020", v));
        }
        if (v.x(t[1]) > 0 && v.x(t[1]) <= WIDTH) {
            w.write(label(v.x(t[1]) - 3 - textWidth("Z travel"), (y0 + y1) / 2, "Z travel", "#20a020", v));
        }
        if (v.y(t[3]) >= 0 && v.y(t[3]) < v.height()) {
            w.write(label(WIDTH / 2, v.y(t[3]) + 14, "X travel", "#20a020", v));
        }
        w.write("</g>\n");
    }

    private static double clampX(double x) {
        return Math.max(-10, Math.min(WIDTH + 10, x));
    }

    private static double clampY(double y, SvgView v) {
        return Math.max(-10, Math.min(v.height() + 10, y));
    }

    private static void path(Writer w, Drawing d, SvgView v, boolean rapids) throws IOException {
        for (boolean rapid : new boolean[] {true, false}) {
            if (rapid && !rapids) {
                continue;
            }
            w.write(rapid ? "<g id=\"rapids\">\n" : "<g id=\"feeds\">\n");
            for (Drawing.Move m : d.moves()) {
                if (m.rapid() != rapid) {
                    continue;
                }
                StringBuilder pts = new StringBuilder();
                for (int i = 0; i < m.z().length; i++) {
                    pts.append(v.pt(m.z()[i], m.r()[i]));
                }
                w.write("<polyline fill=\"none\" stroke=\"" + (m.rapid() ? "#d03030\" stroke-dasharray=\"6 4\"" : "#1040c0\"")
                        + " stroke-width=\"1.2\" points=\"" + pts + "\"/>\n");
            }
            w.write("</g>\n");
        }
    }

    /** Each finding: the tool's outline where its tip was, a circle at the place, its code and block. */
    private static void marks(Writer w, Drawing d, SvgView v) throws IOException {
        w.write("<g id=\"tools\">\n");
        for (Drawing.Mark m : d.marks()) {
            for (Shape part : m.tool()) {
                if (part.size() >= 3) {
                    w.write(shape(part, v, "#e8c0f0", "0.6"));
                }
            }
        }
        w.write("</g>\n");
        java.util.List<double[]> placed = new java.util.ArrayList<>();
        for (Drawing.Mark m : d.marks()) {
            String text = m.code() + " " + m.block();
            double x = v.x(m.z());
            double y = v.y(m.r());
            w.write(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"7\" fill=\"none\" stroke=\"#ff00ff\""
                    + " stroke-width=\"2.5\"/>", x, y));
            // the label right of and above the circle, moved back onto the canvas near an edge, and
            // below an earlier label it would cover (two findings close together)
            double lx = Math.max(2, Math.min(x + 9, WIDTH - 2 - textWidth(text)));
            double ly = Math.max(16, Math.min(y - 9, v.height() - 4));
            for (int tries = 0; tries < 40 && covers(placed, lx, ly, textWidth(text)); tries++) {
                ly = ly + 16 > v.height() - 4 ? 16 + tries : ly + 16;
            }
            placed.add(new double[] {lx, ly, textWidth(text)});
            w.write(label(lx, ly, text, "#ff00ff", v));
        }
    }

    /** Whether a label at (x, y), {@code width} wide, would overlap one already placed ({x, y, width}). */
    private static boolean covers(java.util.List<double[]> placed, double x, double y, double width) {
        for (double[] p : placed) {
            if (Math.abs(p[1] - y) < 15 && x < p[0] + p[2] && p[0] < x + width) {
                return true;
            }
        }
        return false;
    }

    /** A label at (x, y), moved back onto the view near an edge. */
    private static String label(double x, double y, String text, String fill, SvgView v) {
        double lx = Math.max(2, Math.min(x, WIDTH - 2 - textWidth(text)));
        double ly = Math.max(16, Math.min(y, v.height() - 4));
        return String.format(Locale.ROOT, "<text x=\"%.1f\" y=\"%.1f\" fill=\"%s\">%s</text>\n", lx, ly, fill,
                escape(text));
    }

    /** About how wide a label is at the drawing's 14 px sans-serif (9 px a character, generously). */
    static double textWidth(String s) {
        return 9.0 * s.length();
    }

    /**
     * Grid lines every round step of the program's Z and X (1, 2 or 5 times a power of ten), labelled
     * inside the top and left edges; X only above the centreline, where the path is.
     */
    private static void grid(Writer w, Drawing.ProgramAxes a, SvgView v) throws IOException {
        w.write("<g id=\"grid\" stroke=\"#d8d8d8\" stroke-width=\"0.8\" fill=\"#707070\" font-size=\"11\">\n");
        double q0 = Math.min(a.programZ(v.zMin()), a.programZ(v.zMax()));
        double q1 = Math.max(a.programZ(v.zMin()), a.programZ(v.zMax()));
        double step = roundStep((q1 - q0) / 12);
        for (double q = Math.ceil(q0 / step) * step; q <= q1; q += step) {
            double x = v.x(a.z(q));
            String label = "Z" + MotionChecks.mm(Math.abs(q) < step / 1e6 ? 0 : q);
            w.write(String.format(Locale.ROOT, "<line x1=\"%.1f\" y1=\"0\" x2=\"%.1f\" y2=\"%.1f\"/>"
                    + "<text stroke=\"none\" x=\"%.1f\" y=\"12\">%s</text>\n", x, x, v.height(),
                    Math.max(2, Math.min(x + 2, WIDTH - 2 - textWidth(label))), label));
        }
        double p0 = Math.min(a.programX(Math.max(0, v.rMin())), a.programX(v.rMax()));
        double p1 = Math.max(a.programX(Math.max(0, v.rMin())), a.programX(v.rMax()));
        double xStep = roundStep((p1 - p0) / 8);
        for (double p = Math.ceil(p0 / xStep) * xStep; p <= p1; p += xStep) {
            double y = v.y(a.r(p));
            String label = "X" + MotionChecks.mm(Math.abs(p) < xStep / 1e6 ? 0 : p);
            w.write(String.format(Locale.ROOT, "<line x1=\"0\" y1=\"%.1f\" x2=\"%.0f\" y2=\"%.1f\"/>"
                    + "<text stroke=\"none\" x=\"4\" y=\"%.1f\">%s</text>\n", y, WIDTH, y,
                    Math.max(24, Math.min(y - 2, v.height() - 2)), label));
        }
        w.write("</g>\n");
    }

    /** The round step (1, 2 or 5 times a power of ten) nearest above {@code raw}. */
    static double roundStep(double raw) {
        if (!(raw > 0) || Double.isInfinite(raw)) {
            return 1;
        }
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        for (double m : new double[] {1, 2, 5, 10}) {
            if (m * p >= raw) {
                return m * p;
            }
        }
        return 10 * p;
    }

    private static String shape(Shape sh, SvgView v, String fill, String opacity) {
        StringBuilder p = new StringBuilder();
        for (int i = 0; i < sh.size(); i++) {
            p.append(v.pt(Math.max(-1e5, Math.min(1e5, sh.z()[i])), sh.r()[i]));
        }
        return "<polygon fill=\"" + fill + "\" fill-opacity=\"" + opacity + "\" stroke=\"#333\" points=\"" + p + "\"/>\n";
    }

    /** Text for XML or HTML, in an element or a quoted attribute (the SVG here, the setup sheet's page). */
    public static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
