package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Origin;
import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The input limits, with small limits so that each case is a few characters. */
class BoundedReaderTest {
    private static String readAll(Reader r) throws IOException {
        StringBuilder sb = new StringBuilder();
        char[] b = new char[3];
        for (int n = r.read(b, 0, b.length); n >= 0; n = r.read(b, 0, b.length)) {
            sb.append(b, 0, n);
        }
        return sb.toString();
    }

    private static String found(Diagnostics d) {
        List<String> out = new ArrayList<>();
        for (Diagnostic x : d.sorted()) {
            out.add(x.span().line() + ":" + x.span().column() + ":" + x.code().id() + " " + x.args());
        }
        return String.join(", ", out);
    }

    @Test
    void aLineLongerThanTheLimitIsCutWithAnErrorAtTheFirstCharacterPastIt() throws IOException {
        Diagnostics d = new Diagnostics();
        String text = readAll(new BoundedReader(new StringReader("G01\nX123456789\r\nZ1\rM30\n"), d, Origin.PROGRAM, 5, 1000));
        assertEquals("G01\nX1234\r\nZ1\rM30\n", text);
        assertEquals("2:6:E503 [5]", found(d));
    }

    @Test
    void aTextLongerThanTheLimitEndsThere() throws IOException {
        Diagnostics d = new Diagnostics();
        String text = readAll(new BoundedReader(new StringReader("G01\nG01\nG01\n"), d, Origin.PROGRAM, 100, 6));
        assertEquals("G01\nG0", text);
        assertEquals("2:3:E504 [6]", found(d));
    }

    @Test
    void aTextWithinTheLimitsIsUnchanged() throws IOException {
        Diagnostics d = new Diagnostics();
        String program = "%\nO0001\nG00 X10. Z2.\nM30\n%\n";
        assertEquals(program, readAll(new BoundedReader(new StringReader(program), d, Origin.PROGRAM)));
        assertEquals("", found(d));
    }
}
