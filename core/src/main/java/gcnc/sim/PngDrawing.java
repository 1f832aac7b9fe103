package gcnc.sim;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Line2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;

/**
 * The drawing of {@link SvgWriter} painted with the JDK's own Java 2D, for a setup sheet as a PNG
 * ({@code gcnc sheet FILE -o sheet.png}): the same view ({@link SvgView}), the travel box, the blank and
 * the finished part, the chuck and tailstock, the centreline, the path (rapids dashed red, feeds blue)
 * and each finding's tool outline, circle and label. The title block's text is the sheet's own (its
 * rows are drawn above the drawing), so only the view is painted here.
 */
public final class PngDrawing {
    private PngDrawing() {
    }

    /** The drawing's height in pixels at {@link #width()} pixels wide. */
    public static int height(SimReport report) {
        return (int) Math.ceil(SvgView.of(drawing(report)).height());
    }

    /** The drawing's width in pixels. */
    public static int width() {
        return (int) SvgWriter.WIDTH;
    }

    private static Drawing drawing(SimReport report) {
        Drawing d = report.drawing();
        if (d == null) {
            throw new IllegalStateException("simulate with SimOptions.withPath() to draw");
        }
        return d;
    }

    /** Paints the drawing with its top left corner at (0, 0) of {@code g}. */
    public static void paint(SimReport report, Graphics2D g, boolean rapids) {
        Drawing d = drawing(report);
        SvgView v = SvgView.of(d);
        java.awt.Shape clip = g.getClip();
        g.clip(new Rectangle2D.Double(0, 0, SvgWriter.WIDTH, v.height()));
        g.setColor(Color.WHITE);
        g.fill(new Rectangle2D.Double(0, 0, SvgWriter.WIDTH, v.height()));
        double[] t = d.machine().travel();
        g.setColor(new Color(0x20a020));
        g.setStroke(new BasicStroke(1.5f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {3, 3}, 0));
        double x0 = v.x(t[0]);
        double y0 = v.y(t[3]);
        g.draw(new Rectangle2D.Double(x0, y0, Math.max(0, v.x(t[1]) - x0), Math.max(0, v.y(Math.max(0, t[2])) - y0)));
        if (!Double.isNaN(d.stockRadius())) {
            fill(g, polygon(v, new double[] {d.stockBack(), d.stockBack(), d.stockFace(), d.stockFace()},
                    new double[] {0, d.stockRadius(), d.stockRadius(), 0}), new Color(0xf3e3c3), new Color(0xc8a870));
            int n = d.finalZ().length;
            double[] z = new double[n + 2];
            double[] r = new double[n + 2];
            z[0] = d.stockBack();
            System.arraycopy(d.finalZ(), 0, z, 1, n);
            System.arraycopy(d.finalR(), 0, r, 1, n);
            z[n + 1] = d.stockFace();
            Path2D part = polygon(v, z, r);
            fill(g, part, new Color(0xb08040), new Color(0x603010));
            double[] below = new double[n + 2];
            for (int i = 0; i < r.length; i++) {
                below[i] = -r[i];
            }
            fill(g, polygon(v, z, below), new Color(0xb0, 0x80, 0x40, 140), new Color(0x603010));
        }
        for (Shape s : d.chuck()) {
            fill(g, polygon(v, s.z(), s.r()), new Color(0x88, 0x88, 0x88, 204), new Color(0x333333));
        }
        for (Shape s : d.tailstock()) {
            fill(g, polygon(v, s.z(), s.r()), new Color(0x66, 0x88, 0xaa, 204), new Color(0x333333));
        }
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(1, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER, 10, new float[] {12, 4, 2, 4}, 0));
        g.draw(new Line2D.Double(0, v.y(0), SvgWriter.WIDTH, v.y(0)));
        for (boolean rapid : new boolean[] {true, false}) {
            if (rapid && !rapids) {
                continue;
            }
            g.setColor(rapid ? new Color(0xd03030) : new Color(0x1040c0));
            g.setStroke(rapid ? new BasicStroke(1.2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10, new float[] {6, 4}, 0)
                    : new BasicStroke(1.2f));
            for (Drawing.Move m : d.moves()) {
                if (m.rapid() == rapid && m.z().length > 0) {
                    Path2D p = new Path2D.Double();
                    p.moveTo(v.x(m.z()[0]), v.y(m.r()[0]));
                    for (int i = 1; i < m.z().length; i++) {
                        p.lineTo(v.x(m.z()[i]), v.y(m.r()[i]));
                    }
                    g.draw(p);
                }
            }
        }
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 14));
        for (Drawing.Mark m : d.marks()) {
            for (Shape s : m.tool()) {
                if (s.size() >= 3) {
                    fill(g, polygon(v, s.z(), s.r()), new Color(0xe8, 0xc0, 0xf0, 153), new Color(0x333333));
                }
            }
            double x = v.x(m.z());
            double y = v.y(m.r());
            g.setColor(new Color(0xff00ff));
            g.setStroke(new BasicStroke(2.5f));
            g.draw(new Ellipse2D.Double(x - 7, y - 7, 14, 14));
            String text = m.code() + " " + m.block();
            float lx = (float) Math.max(2, Math.min(x + 9, SvgWriter.WIDTH - 2 - SvgWriter.textWidth(text)));
            float ly = (float) Math.max(16, Math.min(y - 9, v.height() - 4));
            g.drawString(text, lx, ly);
        }
        g.setClip(clip);
    }

    private static Path2D polygon(SvgView v, double[] z, double[] r) {
        Path2D p = new Path2D.Double();
        for (int i = 0; i < z.length; i++) {
            double x = v.x(Math.max(-1e5, Math.min(1e5, z[i])));
            if (i == 0) {
                p.moveTo(x, v.y(r[i]));
            } else {
                p.lineTo(x, v.y(r[i]));
            }
        }
        p.closePath();
        return p;
    }

    private static void fill(Graphics2D g, Path2D p, Color fill, Color stroke) {
        g.setColor(fill);
        g.fill(p);
        g.setColor(stroke);
        g.setStroke(new BasicStroke(1));
        g.draw(p);
    }
}
