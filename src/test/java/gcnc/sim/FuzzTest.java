package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Diagnostics;
import java.io.BufferedReader;
import java.io.StringReader;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Bad DMC is reported, never thrown: random lines built from the DMC's own pieces. */
class FuzzTest {
    private static final String[] PIECES = {"VP", "CR", "VS", "VA", "VD", "VE", "BG", "AM", "S", "SB", "CB", "OF",
        "WT", "EN", "SH", "VM", "XY", "TOOL=", "Revolver ", "M", "#", "NO ", " ", ",", "-", "+", ".", "0", "1", "9",
        "360", "99999999999", "2147483648", "1e9", "NaN", "A", "Z"};

    @Test
    void randomLinesNeverThrow() throws Exception {
        Random rnd = new Random(42);
        for (String machine : new String[] {"generic", "thesis-2004"}) {
            StringBuilder dmc = new StringBuilder();
            for (int line = 0; line < 20000; line++) {
                int n = 1 + rnd.nextInt(6);
                for (int i = 0; i < n; i++) {
                    dmc.append(PIECES[rnd.nextInt(PIECES.length)]);
                }
                dmc.append('\n');
            }
            Diagnostics d = new Diagnostics();
            SimReport r = DmcReplay.replay(new BufferedReader(new StringReader(dmc.toString())),
                    ReplayTest.profile(machine), SimOptions.defaults().withPath().withTrace(new StringBuilder()), d);
            assertTrue(d.size() > 0);
            java.io.StringWriter svg = new java.io.StringWriter();
            SvgWriter.write(r, "fuzz", svg);
            assertTrue(svg.toString().endsWith("</svg>\n"));
        }
    }
}
