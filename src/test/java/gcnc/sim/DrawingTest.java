package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.galil.Dialect;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.io.StringWriter;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** The SVG a machinist reads (issue 9): a grid in program coordinates, the block at each finding, rapids that can be left out. */
class DrawingTest {
    private static final Tables TABLES = Tables.builtIn();
    /** Generic machine, blank D44 x 200; one pass to Z-30 then a rapid back into the blank at N110. */
    private static final String PROGRAM = "O1\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\n"
            + "N60 G00 X46. Z2.\nN70 G00 X41.\nN80 G01 Z-30. F100.\nN90 G00 U2.\nN100 G00 Z2.\nN110 G00 X30. Z-20.\n"
            + "N120 G00 X60.\nM05\nM30\n";

    static SimReport simulate(String program) throws Exception {
        Compiler.Result r = Compiler.compile(new StringReader(program), new Compiler.Settings(TABLES,
                ProfileLoader.load("generic", TableSource.builtIn(), TABLES), Dialect.Kind.GALIL,
                Optional.of(SimOptions.defaults().withPath())), l -> { });
        return r.simulation().orElseThrow();
    }

    static String svg(SimReport report, boolean rapids) throws Exception {
        StringWriter w = new StringWriter();
        SvgWriter.write(report, "t", w, rapids);
        return w.toString();
    }

    @Test
    void theFindingIsLabelledWithItsBlock() throws Exception {
        String svg = svg(simulate(PROGRAM), true);
        assertTrue(svg.contains(">E305 N110</text>"), svg);
    }

    @Test
    void theGridIsInProgramCoordinates() throws Exception {
        String svg = svg(simulate(PROGRAM), true);
        // the view runs from behind the jaws' face (Z-150, as the blank's face is 150 mm out) to Z2.:
        // program zero and every 20 mm of Z are grid lines
        assertTrue(svg.contains(">Z0</text>"), "Z0 line");
        assertTrue(svg.contains(">Z-20</text>"), "Z-20 line");
        assertTrue(svg.contains(">Z-140</text>"), "Z-140 line");
        assertTrue(svg.contains(">X40</text>"), "X as a diameter: the 44 mm blank reaches X44");
        assertFalse(svg.contains(">X22</text>"), "not the radius");
    }

    @Test
    void rapidsCanBeLeftOut() throws Exception {
        SimReport r = simulate(PROGRAM);
        assertTrue(svg(r, true).contains("<g id=\"rapids\">"));
        String without = svg(r, false);
        assertFalse(without.contains("<g id=\"rapids\">"));
        assertFalse(without.contains("stroke=\"#d03030\" stroke-dasharray=\"6 4\" stroke-width"), "no rapid polyline");
        assertTrue(without.contains("rapid (hidden)"));
        assertTrue(without.contains(">E305 N110</text>"), "findings stay");
    }

    @Test
    void everyLabelIsOnTheCanvas() throws Exception {
        // findings at the edge of the view: a rapid through the blank right at its face and far out
        String edge = "O1\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nN10 G00 X46. Z2.\nN20 G00 X0. Z-0.5\n"
                + "N30 G00 X46.\nN40 G00 Z-140.\nN50 G00 X10.\nN60 G00 X90.\nM05\nM30\n";
        String svg = svg(simulate(edge), true);
        Matcher size = Pattern.compile("width=\"(\\d+)\" height=\"(\\d+)\"").matcher(svg);
        assertTrue(size.find());
        double width = Double.parseDouble(size.group(1));
        double height = Double.parseDouble(size.group(2));
        Matcher text = Pattern.compile("<text[^>]* x=\"([-\\d.]+)\" y=\"([-\\d.]+)\"[^>]*>([^<]*)</text>").matcher(svg);
        int n = 0;
        while (text.find()) {
            n++;
            double x = Double.parseDouble(text.group(1));
            double y = Double.parseDouble(text.group(2));
            double w = 9.0 * text.group(3).length();
            assertTrue(x >= 0 && y >= 0 && y <= height && (x + w <= width || text.group(3).length() > 60),
                    "off the canvas: " + text.group());
        }
        assertTrue(svg.contains(">E305 N20</text>") && svg.contains(">E305 N50</text>"), svg);
        assertTrue(svg.contains(">Z0</text>"), "a grid from the first move when nothing is cut at feed");
        assertTrue(n > 10);
    }

    @Test
    void thePartOutlineCoversTheWholeBlank() throws Exception {
        Drawing d = simulate(PROGRAM).drawing();
        double last = d.finalZ()[d.finalZ().length - 1];
        assertEquals(d.stockFace(), last, 0.05, "the outline reaches the blank's face");
        assertEquals(d.stockBack(), d.finalZ()[0], 0.05);
    }
}
