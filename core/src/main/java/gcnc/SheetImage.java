package gcnc;

import gcnc.sim.PngDrawing;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;

/**
 * A setup sheet as one PNG image ({@code gcnc sheet FILE -o sheet.png}), for a shop that prints it or
 * pins it beside the machine: the sheet's title, every row of its head (blank, work zero, the top
 * spindle speed beside the program's G50/G92 limit, ...), its tool table and its findings as text
 * lines, then the drawing ({@link PngDrawing}). Drawn with the JDK's Java 2D in a headless image and
 * written by ImageIO: no dependency, no display. The text is in a monospaced font, wrapped at
 * {@link #COLUMNS} characters, so the image's size follows from its lines alone: {@link #WIDTH} wide,
 * {@code 2 * MARGIN + LINE * lines + drawing} high.
 */
public final class SheetImage {
    public static final int WIDTH = PngDrawing.width();
    public static final int MARGIN = 12;
    public static final int LINE = 18;
    /** Characters a text line holds at the sheet's 13 px monospaced font (about 7.8 px each). */
    public static final int COLUMNS = 122;

    /** How a line is drawn. */
    public enum Kind {
        TITLE, SECTION, ROW, TOOL, ERROR, WARNING, NOTE, TEXT
    }

    /** One line of the image's text. */
    public record Line(Kind kind, String text) {
    }

    private SheetImage() {
    }

    /** The text lines of {@code sheet}, in order, each at most {@link #COLUMNS} characters (a long row continues indented). */
    public static List<Line> lines(SetupSheet sheet) {
        List<Line> out = new ArrayList<>();
        out.add(new Line(Kind.TITLE, clip(sheet.heading())));
        for (String[] r : sheet.rows()) {
            wrap(out, Kind.ROW, r[0] + ": " + r[1]);
        }
        out.add(new Line(Kind.SECTION, "Tools"));
        List<String> tools = sheet.toolLines();
        if (tools.isEmpty()) {
            out.add(new Line(Kind.TEXT, "No tool moved."));
        }
        tools.forEach(t -> wrap(out, Kind.TOOL, t));
        out.add(new Line(Kind.SECTION, "Findings"));
        List<String> findings = sheet.findingLines();
        if (findings.isEmpty()) {
            out.add(new Line(Kind.TEXT, "None."));
        }
        for (String f : findings) {
            String severity = f.split(" ", 3)[1];
            wrap(out, severity.equals("error") ? Kind.ERROR : severity.equals("warning") ? Kind.WARNING : Kind.NOTE, f);
        }
        out.add(new Line(Kind.SECTION, "Drawing"));
        return out;
    }

    /** The image's height in pixels. */
    public static int height(SetupSheet sheet) {
        return 2 * MARGIN + LINE * lines(sheet).size() + PngDrawing.height(sheet.report());
    }

    /** The sheet as a PNG on {@code out}; {@code rapids} false leaves the rapid moves out of the drawing. */
    public static void write(SetupSheet sheet, boolean rapids, OutputStream out) throws IOException {
        List<Line> lines = lines(sheet);
        int textHeight = 2 * MARGIN + LINE * lines.size();
        BufferedImage image = new BufferedImage(WIDTH, textHeight + PngDrawing.height(sheet.report()), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, image.getWidth(), image.getHeight());
            Font plain = new Font(Font.MONOSPACED, Font.PLAIN, 13);
            Font bold = new Font(Font.MONOSPACED, Font.BOLD, 13);
            int y = MARGIN;
            for (Line l : lines) {
                y += LINE;
                g.setFont(l.kind() == Kind.TITLE ? new Font(Font.MONOSPACED, Font.BOLD, 15)
                        : l.kind() == Kind.SECTION ? bold : plain);
                g.setColor(switch (l.kind()) {
                    case ERROR -> new Color(0xbb0000);
                    case WARNING -> new Color(0xaa6600);
                    case NOTE -> new Color(0x3a444e);
                    default -> Color.BLACK;
                });
                g.drawString(l.text(), MARGIN, y - 4);
            }
            g.translate(0, textHeight);
            PngDrawing.paint(sheet.report(), g, rapids);
        } finally {
            g.dispose();
        }
        if (!javax.imageio.ImageIO.write(image, "png", out)) {
            throw new IOException("this Java has no PNG writer");
        }
    }

    private static void wrap(List<Line> out, Kind kind, String text) {
        String rest = text;
        boolean first = true;
        while (true) {
            String lead = first ? "" : "    ";
            int room = COLUMNS - lead.length();
            if (rest.length() <= room) {
                out.add(new Line(kind, lead + rest));
                return;
            }
            int cut = rest.lastIndexOf(' ', room);
            if (cut <= room / 2) {
                cut = room;
            }
            out.add(new Line(kind, lead + rest.substring(0, cut)));
            rest = rest.substring(cut).stripLeading();
            first = false;
        }
    }

    private static String clip(String s) {
        return s.length() <= COLUMNS ? s : s.substring(0, COLUMNS - 1) + "…";
    }
}
