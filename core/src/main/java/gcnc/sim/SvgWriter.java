package gcnc.sim;

import java.io.IOException;
import java.io.Writer;
import java.util.Locale;

/**
 * Draws a simulation as an SVG half-section (Z to the right, radius up, machine mm): chuck,
 * tailstock, the blank, the finished part outline (mirrored below the centreline too), the tool path (rapids dashed, feeds solid,
 * rapids in a layer of their own that can be left out), the findings with their block, and a grid in
 * the program's coordinates (X as the program writes it, Z from work zero). The view fits the blank
 * with a margin (the path is clipped to it), or the path when there is no blank; every label stays
 * on the canvas.
 */
public final class SvgWriter {
    private static final double WIDTH = 1000;

    private SvgWriter() {
    }

    public static void write(SimReport report, String title, Writer w) throws IOException {
        write(report, title, w, true);
    }

    /** The drawing, with the rapid moves or without them ({@code rapids} false: feeds and findings only). */
    public static void write(SimReport report, String title, Writer w, boolean rapids) throws IOException {
        Drawing d = report.drawing();
        if (d == null) {
            throw new IllegalStateException("simulate with SimOptions.withPath() to draw");
        }
        double[] v = view(d);
        double s = WIDTH / (v[1] - v[0]);
        double height = (v[3] - v[2]) * s;
        View t = new View(v[0], v[3], s);
        w.write(String.format(Locale.ROOT, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\""
                + " viewBox=\"0 0 %.0f %.0f\" font-family=\"sans-serif\" font-size=\"14\">\n",
                WIDTH, height + 110, WIDTH, height + 110));
        w.write("<title>" + escape(title) + "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n");
        w.write(String.format(Locale.ROOT, "<defs><clipPath id=\"view\"><rect x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.1f\"/>"
                + "</clipPath></defs>\n<g clip-path=\"url(#view)\">\n", WIDTH, height));
        if (!Double.isNaN(d.stockRadius())) {
            w.write("<polygon fill=\"#f3e3c3\" stroke=\"#c8a870\" points=\"" + t.pt(d.stockBack(), 0) + t.pt(d.stockBack(), d.stockRadius())
                    + t.pt(d.stockFace(), d.stockRadius()) + t.pt(d.stockFace(), 0) + "\"/>\n");
            StringBuilder part = new StringBuilder(t.pt(d.stockBack(), 0));
            for (int i = 0; i < d.finalZ().length; i++) {
                if (i == 0 || i == d.finalZ().length - 1 || d.finalR()[i] != d.finalR()[i - 1]
                        || d.finalR()[i] != d.finalR()[i + 1]) {
                    part.append(t.pt(d.finalZ()[i], d.finalR()[i]));
                }
            }
            part.append(t.pt(d.stockFace(), 0));
            w.write("<polygon fill=\"#b08040\" stroke=\"#603010\" stroke-width=\"1.5\" points=\"" + part + "\"/>\n");
            // The same outline mirrored below the centreline shows the whole turned silhouette.
            w.write("<polygon fill=\"#b08040\" fill-opacity=\"0.55\" stroke=\"#603010\" transform=\"translate(0 "
                    + String.format(Locale.ROOT, "%.2f", 2 * t.y(0)) + ") scale(1 -1)\" points=\"" + part + "\"/>\n");
        }
        for (Shape sh : d.chuck()) {
            w.write(shape(sh, t, "#888888"));
        }
        for (Shape sh : d.tailstock()) {
            w.write(shape(sh, t, "#6688aa"));
        }
        w.write(String.format(Locale.ROOT, "<line x1=\"0\" y1=\"%.1f\" x2=\"%.0f\" y2=\"%.1f\" stroke=\"black\""
                + " stroke-dasharray=\"12 4 2 4\"/>\n", t.y(0), WIDTH, t.y(0)));
        if (d.program() != null) {
            grid(w, d.program(), v, t, height);
        }
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
                    pts.append(t.pt(m.z()[i], m.r()[i]));
                }
                w.write("<polyline fill=\"none\" stroke=\"" + (m.rapid() ? "#d03030\" stroke-dasharray=\"6 4\"" : "#1040c0\"")
                        + " stroke-width=\"1.2\" points=\"" + pts + "\"/>\n");
            }
            w.write("</g>\n");
        }
        for (Drawing.Mark m : d.marks()) {
            String label = m.code() + " " + m.block();
            double x = t.x(m.z());
            double y = t.y(m.r());
            // the label right of and above the circle, moved back onto the canvas near an edge
            double lx = Math.max(2, Math.min(x + 9, WIDTH - 2 - textWidth(label)));
            double ly = Math.max(16, Math.min(y - 9, height - 4));
            w.write(String.format(Locale.ROOT, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"7\" fill=\"none\" stroke=\"#ff00ff\""
                    + " stroke-width=\"2.5\"/><text x=\"%.1f\" y=\"%.1f\" fill=\"#ff00ff\">%s</text>\n",
                    x, y, lx, ly, escape(label)));
        }
        w.write("</g>\n");
        legend(w, height, v, rapids, d.program() != null);
        w.write("</svg>\n");
    }

    /** About how wide a label is at the drawing's 14 px sans-serif (9 px a character, generously). */
    private static double textWidth(String s) {
        return 9.0 * s.length();
    }

    /**
     * Grid lines every round step of the program's Z and X (1, 2 or 5 times a power of ten), labelled
     * inside the top and left edges; X only above the centreline, where the path is.
     */
    private static void grid(Writer w, Drawing.ProgramAxes a, double[] v, View t, double height) throws IOException {
        w.write("<g id=\"grid\" stroke=\"#d8d8d8\" stroke-width=\"0.8\" fill=\"#707070\" font-size=\"11\">\n");
        double q0 = Math.min(a.programZ(v[0]), a.programZ(v[1]));
        double q1 = Math.max(a.programZ(v[0]), a.programZ(v[1]));
        double step = roundStep((q1 - q0) / 8);
        for (double q = Math.ceil(q0 / step) * step; q <= q1; q += step) {
            double x = t.x(a.z(q));
            String label = "Z" + MotionChecks.mm(Math.abs(q) < step / 1e6 ? 0 : q);
            w.write(String.format(Locale.ROOT, "<line x1=\"%.1f\" y1=\"0\" x2=\"%.1f\" y2=\"%.1f\"/>"
                    + "<text stroke=\"none\" x=\"%.1f\" y=\"12\">%s</text>\n", x, x, height,
                    Math.max(2, Math.min(x + 2, WIDTH - 2 - textWidth(label))), label));
        }
        double p0 = Math.min(a.programX(Math.max(0, v[2])), a.programX(v[3]));
        double p1 = Math.max(a.programX(Math.max(0, v[2])), a.programX(v[3]));
        double xStep = roundStep((p1 - p0) / 6);
        for (double p = Math.ceil(p0 / xStep) * xStep; p <= p1; p += xStep) {
            double y = t.y(a.r(p));
            String label = "X" + MotionChecks.mm(Math.abs(p) < xStep / 1e6 ? 0 : p);
            w.write(String.format(Locale.ROOT, "<line x1=\"0\" y1=\"%.1f\" x2=\"%.0f\" y2=\"%.1f\"/>"
                    + "<text stroke=\"none\" x=\"4\" y=\"%.1f\">%s</text>\n", y, WIDTH, y,
                    Math.max(24, Math.min(y - 2, height - 2)), label));
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

    private static void legend(Writer w, double top, double[] v, boolean rapids, boolean grid) throws IOException {
        double y = top + 25;
        w.write(String.format(Locale.ROOT, "<line x1=\"10\" y1=\"%.0f\" x2=\"50\" y2=\"%.0f\" stroke=\"#d03030\" stroke-dasharray=\"6 4\"/>"
                + "<text x=\"56\" y=\"%.0f\">%s</text>\n", y, y, y + 5, rapids ? "rapid" : "rapid (hidden)"));
        w.write(String.format(Locale.ROOT, "<line x1=\"120\" y1=\"%.0f\" x2=\"160\" y2=\"%.0f\" stroke=\"#1040c0\"/>"
                + "<text x=\"166\" y=\"%.0f\">feed</text>\n", y, y, y + 5));
        w.write(String.format(Locale.ROOT, "<rect x=\"220\" y=\"%.0f\" width=\"30\" height=\"12\" fill=\"#f3e3c3\" stroke=\"#c8a870\"/>"
                + "<text x=\"256\" y=\"%.0f\">blank</text>\n", y - 6, y + 5));
        w.write(String.format(Locale.ROOT, "<rect x=\"310\" y=\"%.0f\" width=\"30\" height=\"12\" fill=\"#b08040\"/>"
                + "<text x=\"346\" y=\"%.0f\">part</text>\n", y - 6, y + 5));
        w.write(String.format(Locale.ROOT, "<rect x=\"390\" y=\"%.0f\" width=\"30\" height=\"12\" fill=\"#888888\"/>"
                + "<text x=\"426\" y=\"%.0f\">chuck</text>\n", y - 6, y + 5));
        w.write(String.format(Locale.ROOT, "<rect x=\"480\" y=\"%.0f\" width=\"30\" height=\"12\" fill=\"#6688aa\"/>"
                + "<text x=\"516\" y=\"%.0f\">tailstock</text>\n", y - 6, y + 5));
        w.write(String.format(Locale.ROOT, "<circle cx=\"600\" cy=\"%.0f\" r=\"7\" fill=\"none\" stroke=\"#ff00ff\" stroke-width=\"2.5\"/>"
                + "<text x=\"612\" y=\"%.0f\">finding</text>\n", y, y + 5));
        w.write(String.format(Locale.ROOT, "<text x=\"10\" y=\"%.0f\">machine Z %s .. %s mm (right = +Z), radius %s .. %s mm;"
                + " path above the centreline, part mirrored below</text>\n",
                y + 35, MotionChecks.mm(v[0]), MotionChecks.mm(v[1]), MotionChecks.mm(v[2]), MotionChecks.mm(v[3])));
        if (grid) {
            w.write(String.format(Locale.ROOT, "<text x=\"10\" y=\"%.0f\">grid: program coordinates as the program writes"
                    + " them (X, Z from work zero) for the first cutting tool</text>\n", y + 57));
        }
    }

    /**
     * {zMin, zMax, rMin, rMax} to show: where the tool cut (feed moves and findings) and the blank's
     * face, so the part fills the picture; the whole path when there is no blank.
     */
    private static double[] view(Drawing d) {
        boolean stock = !Double.isNaN(d.stockRadius());
        double[] b = {Double.MAX_VALUE, -Double.MAX_VALUE, 0, stock ? d.stockRadius() : -Double.MAX_VALUE};
        for (Drawing.Move m : d.moves()) {
            if (stock && m.rapid()) {
                continue;
            }
            for (int i = 0; i < m.z().length; i++) {
                b[0] = Math.min(b[0], m.z()[i]);
                b[1] = Math.max(b[1], m.z()[i]);
                b[3] = Math.max(b[3], stock ? Math.min(m.r()[i], 1.2 * d.stockRadius()) : m.r()[i]);
            }
        }
        for (Drawing.Mark m : d.marks()) {
            b[0] = Math.min(b[0], m.z());
            b[1] = Math.max(b[1], m.z());
        }
        if (stock) {
            b[0] = Math.max(Math.min(b[0], d.stockFace()), d.stockBack());
            b[1] = Math.min(Math.max(b[1], d.stockFace()), d.stockFace() + 0.2 * (d.stockFace() - d.stockBack()));
        }
        if (b[0] > b[1]) {
            b = new double[] {0, 1, 0, 1};
        }
        double mz = Math.max(b[1] - b[0], 1e-9) * 0.08;
        double mr = Math.max(b[3] - b[2], 1e-9) * 0.15;
        // With a blank the part is mirrored below the centreline, so show both halves.
        return new double[] {b[0] - mz, b[1] + mz, stock ? -(b[3] + mr) : b[2] - mr * 0.3, b[3] + mr};
    }

    private static String shape(Shape sh, View t, String fill) {
        StringBuilder p = new StringBuilder();
        for (int i = 0; i < sh.size(); i++) {
            p.append(t.pt(Math.max(-1e5, Math.min(1e5, sh.z()[i])), sh.r()[i]));
        }
        return "<polygon fill=\"" + fill + "\" fill-opacity=\"0.8\" stroke=\"#333\" points=\"" + p + "\"/>\n";
    }

    private static String escape(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** Machine mm to SVG pixels: z right, radius up. */
    private record View(double z0, double rTop, double scale) {
        double x(double z) {
            return (z - z0) * scale;
        }

        double y(double r) {
            return (rTop - r) * scale;
        }

        String pt(double z, double r) {
            return String.format(Locale.ROOT, "%.2f,%.2f ", x(z), y(r));
        }
    }
}
