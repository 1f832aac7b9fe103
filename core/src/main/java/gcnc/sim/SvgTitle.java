package gcnc.sim;

import java.io.IOException;
import java.io.Writer;
import java.util.Locale;

/**
 * What stands under a drawing's view: the legend, the view's extent in the program's terms first
 * (Z from work zero, X as the program writes it, in its units) and in the machine frame second,
 * and a title block (program number, file, machine and control, units). No date: the same run
 * draws the same bytes, so a drawing can be a golden file.
 */
final class SvgTitle {
    /** The height below the view, pixels. */
    static final double HEIGHT = 190;

    private SvgTitle() {
    }

    static void write(Writer w, SimReport report, SvgView v, boolean rapids, String file, String number)
            throws IOException {
        Drawing d = report.drawing();
        double y = v.height() + 25;
        legend(w, y, rapids);
        Drawing.ProgramAxes a = d.program();
        if (a != null) {
            String unit = a.zPer() > 2 ? "in" : "mm";
            double x0 = a.programX(Math.max(0, v.rMin()));
            double x1 = a.programX(v.rMax());
            w.write(text(10, y + 30, String.format(Locale.ROOT, "view: Z %s .. %s %s from work zero (right = +Z),"
                    + " X %s .. %s %s as the program writes it (%s); grid: the same, for the first cutting tool",
                    MotionChecks.mm(a.programZ(v.zMin())), MotionChecks.mm(a.programZ(v.zMax())), unit,
                    MotionChecks.mm(Math.min(x0, x1)), MotionChecks.mm(Math.max(x0, x1)), unit,
                    a.xPer() * 2 < a.zPer() * 1.5 ? "diameter" : "radius")));
        }
        double tip = d.tailstockTip();
        String tail = Double.isNaN(tip) || tip <= v.zMax() ? ""
                : "; the tailstock's centre, beyond the view, at Z " + MotionChecks.mm(tip) + " mm";
        // a long path drawn to what its pixels show (PathRecorder): said, so that no one reads it as every move
        String compacted = d.pathTolerance() > 0 ? String.format(Locale.ROOT, "; path drawn to %s mm",
                d.pathTolerance() >= 0.001 ? MotionChecks.mm(d.pathTolerance())
                        : String.format(Locale.ROOT, "%.1e", d.pathTolerance())) : "";
        w.write(text(10, y + 52, String.format(Locale.ROOT, "machine frame: Z %s .. %s mm, radius %s .. %s mm;"
                + " path above the centreline, part mirrored below%s%s", MotionChecks.mm(v.zMin()),
                MotionChecks.mm(v.zMax()), MotionChecks.mm(v.rMin()), MotionChecks.mm(v.rMax()), tail, compacted)));
        titleBlock(w, y + 70, report, file, number);
    }

    private static void legend(Writer w, double y, boolean rapids) throws IOException {
        w.write(String.format(Locale.ROOT, "<line x1=\"10\" y1=\"%.0f\" x2=\"50\" y2=\"%.0f\" stroke=\"#d03030\" stroke-dasharray=\"6 4\"/>"
                + "<text x=\"56\" y=\"%.0f\">%s</text>\n", y, y, y + 5, rapids ? "rapid" : "rapid (hidden)"));
        w.write(String.format(Locale.ROOT, "<line x1=\"170\" y1=\"%.0f\" x2=\"200\" y2=\"%.0f\" stroke=\"#1040c0\"/>"
                + "<text x=\"206\" y=\"%.0f\">feed</text>\n", y, y, y + 5));
        String[][] boxes = {{"#f3e3c3", "blank"}, {"#b08040", "part"}, {"#888888", "chuck"}, {"#6688aa", "tailstock"},
            {"#e8c0f0", "tool"}};
        double x = 250;
        for (String[] b : boxes) {
            w.write(String.format(Locale.ROOT, "<rect x=\"%.0f\" y=\"%.0f\" width=\"24\" height=\"12\" fill=\"%s\" stroke=\"#333\"/>"
                    + "<text x=\"%.0f\" y=\"%.0f\">%s</text>\n", x, y - 6, b[0], x + 30, y + 5, b[1]));
            x += 40 + SvgWriter.textWidth(b[1]);
        }
        w.write(String.format(Locale.ROOT, "<rect x=\"%.0f\" y=\"%.0f\" width=\"24\" height=\"12\" fill=\"none\" stroke=\"#20a020\""
                + " stroke-dasharray=\"3 3\"/><text x=\"%.0f\" y=\"%.0f\">travel</text>\n", x, y - 6, x + 30, y + 5));
        x += 40 + SvgWriter.textWidth("travel");
        w.write(String.format(Locale.ROOT, "<circle cx=\"%.0f\" cy=\"%.0f\" r=\"7\" fill=\"none\" stroke=\"#ff00ff\" stroke-width=\"2.5\"/>"
                + "<text x=\"%.0f\" y=\"%.0f\">finding</text>\n", x + 8, y, x + 20, y + 5));
    }

    /** Four cells: the program's number, its file, machine and control, units and what X is. */
    private static void titleBlock(Writer w, double top, SimReport report, String file, String number)
            throws IOException {
        Drawing.Machine m = report.drawing().machine();
        ProgramEnvelope p = report.program();
        String units = p == null ? "not known" : (p.units() == gcnc.machine.Units.INCH ? "inch (G20)" : "mm (G21)")
                + ", X " + p.xMode();
        String[][] cells = {{"program", number == null ? "(no O number)" : number}, {"file", file},
            {"machine / control", m.name() + " / " + m.control()}, {"units", units}};
        double cell = SvgWriter.WIDTH / cells.length;
        w.write(String.format(Locale.ROOT, "<g id=\"title\"><rect x=\"1\" y=\"%.0f\" width=\"%.0f\" height=\"80\""
                + " fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n", top, SvgWriter.WIDTH - 2));
        for (int i = 0; i < cells.length; i++) {
            double x = i * cell;
            if (i > 0) {
                w.write(String.format(Locale.ROOT, "<line x1=\"%.0f\" y1=\"%.0f\" x2=\"%.0f\" y2=\"%.0f\" stroke=\"black\"/>",
                        x, top, x, top + 80));
            }
            w.write(String.format(Locale.ROOT, "<text x=\"%.0f\" y=\"%.0f\" font-size=\"11\" fill=\"#707070\">%s</text>",
                    x + 8, top + 22, cells[i][0]));
            w.write(String.format(Locale.ROOT, "<text x=\"%.0f\" y=\"%.0f\" font-size=\"16\">%s</text>\n", x + 8, top + 52,
                    SvgWriter.escape(fit(cells[i][1], cell - 16))));
        }
        w.write("</g>\n");
    }

    /** The text, cut with an ellipsis where it would not fit {@code width} pixels (16 px type: 9 px a character). */
    static String fit(String s, double width) {
        int max = (int) (width / 9);
        return s.length() <= max ? s : "…" + s.substring(s.length() - max + 1);
    }

    private static String text(double x, double y, String s) {
        return String.format(Locale.ROOT, "<text x=\"%.0f\" y=\"%.0f\">%s</text>\n", x, y, SvgWriter.escape(s));
    }
}
