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

    /**
     * Random texts of letters and line ends, read in random chunks, against the rule read one
     * character at a time (how BoundedReader read before issue 23 made its loop faster): the same
     * characters kept, the same E503 and E504 at the same places.
     */
    @Test
    void randomTextsInRandomChunksFollowTheRuleCharacterByCharacter() throws IOException {
        java.util.Random random = new java.util.Random(23);
        String alphabet = "aaaaab\n\r";
        for (int n = 0; n < 5000; n++) {
            StringBuilder t = new StringBuilder();
            for (int i = random.nextInt(60); i > 0; i--) {
                t.append(alphabet.charAt(random.nextInt(alphabet.length())));
            }
            int lineLimit = 1 + random.nextInt(8);
            long textLimit = 1 + random.nextInt(70);
            Diagnostics d = new Diagnostics();
            long seed = random.nextLong();
            Reader chunks = new Reader() {
                private final java.util.Random sizes = new java.util.Random(seed);
                private final StringReader in = new StringReader(t.toString());

                @Override
                public int read(char[] b, int off, int len) throws IOException {
                    return in.read(b, off, Math.min(len, 1 + sizes.nextInt(5)));
                }

                @Override
                public void close() {
                }
            };
            String kept = readAll(new BoundedReader(chunks, d, Origin.PROGRAM, lineLimit, textLimit));
            StringBuilder expected = new StringBuilder();
            List<String> findings = new ArrayList<>();
            int line = 1;
            int col = 0;
            boolean cr = false;
            boolean skip = false;
            for (int k = 0; k < t.length(); k++) {
                if (k + 1 > textLimit) {
                    findings.add(line + ":" + Math.max(1, col + 1) + ":E504 [" + textLimit + "]");
                    break;
                }
                char c = t.charAt(k);
                if (c == '\n' || c == '\r') {
                    if (!(c == '\n' && cr)) {
                        line++;
                    }
                    cr = c == '\r';
                    col = 0;
                    skip = false;
                    expected.append(c);
                } else {
                    cr = false;
                    if (!skip && ++col > lineLimit) {
                        skip = true;
                        findings.add(line + ":" + col + ":E503 [" + lineLimit + "]");
                    } else if (!skip) {
                        expected.append(c);
                    }
                }
            }
            String what = t.toString().replace("\r", "\\r").replace("\n", "\\n") + " limits " + lineLimit + ", " + textLimit;
            assertEquals(expected.toString(), kept, what);
            findings.sort(null);
            List<String> actual = new ArrayList<>(List.of(found(d).split(", ")));
            actual.removeIf(String::isEmpty);
            actual.sort(null);
            assertEquals(findings, actual, what);
        }
    }
}
