package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.send.Event;
import gcnc.tables.ErrorMessages;
import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

/** The status line's position: program terms first, in the program's units, the Galil counts after them. */
class StatusLineTest {
    static String line(double[] program, boolean inch) {
        StringWriter w = new StringWriter();
        StatusText t = new StatusText(new PrintWriter(w), new PrintWriter(w), "part.nc", false, false,
                new Phrases(ErrorMessages.Lang.EN));
        return t.line(new Event.Status(12, 37, null, null, program, new double[] {149747, 9375}, 0.2, true, inch, 1200,
                "cw", 0.5, 8, 1, false));
    }

    @Test
    void programTermsFirstThenTheCounts() {
        assertEquals("line 37  X40.020 Z-1.792 (Galil counts 149747,9375)  F0.2/rev  S1200 cw  50%  0:00:08 left",
                line(new double[] {40.02, -1.792}, false));
        // inch: four places, as the program writes them
        assertEquals("line 37  X1.5750 Z-0.0700 (Galil counts 149747,9375)  F0.2/rev  S1200 cw  50%  0:00:08 left",
                line(new double[] {1.575, -0.07}, true));
        // no frame (the program could not be read again): the counts alone, said to be counts
        assertEquals("line 37  149747,9375 (Galil counts)  F0.2/rev  S1200 cw  50%  0:00:08 left", line(null, false));
    }
}
