package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Csv splits its text into lines by hand (issue 23: no regular expression at every start), exactly
 * as {@code split("\r?\n", -1)} did: a line ends at \n, a \r just before it is dropped, a lone \r
 * stays in the line. Random texts of commas, letters, \r, \n and comments, compared row by row.
 */
class CsvLinesTest {
    @Test
    void linesAreSplitAsTheRegularExpressionSplitThem() throws Exception {
        Random random = new Random(23);
        String alphabet = "ab,,\r\n\n# ";
        for (int n = 0; n < 20_000; n++) {
            StringBuilder t = new StringBuilder("k,v\n");
            for (int i = random.nextInt(30); i > 0; i--) {
                t.append(alphabet.charAt(random.nextInt(alphabet.length())));
            }
            String text = t.toString();
            List<String> expected = new ArrayList<>();
            String[] lines = text.split("\r?\n", -1);
            boolean fault = false;
            for (int i = 1; i < lines.length; i++) {
                String l = lines[i];
                if (l.isBlank() || l.stripLeading().startsWith("#")) {
                    continue;
                }
                String[] f = l.split(",", -1);
                if (f.length != 2) {
                    expected.add("fault@" + (i + 1));
                    fault = true;
                    break;
                }
                expected.add((i + 1) + ":" + f[0].trim() + "|" + f[1].trim());
            }
            List<String> actual = new ArrayList<>();
            try {
                for (Csv.Row r : Csv.parse("t.csv", text).rows()) {
                    actual.add(r.line() + ":" + r.get("k") + "|" + r.get("v"));
                }
            } catch (TableException e) {
                actual.add("fault@" + e.getMessage().replaceAll("^t\\.csv:(\\d+):.*", "$1"));
            }
            // a row with the wrong number of fields fails the whole table, at its line
            List<String> shown = fault ? expected.subList(expected.size() - 1, expected.size()) : expected;
            assertEquals(shown, actual, text.replace("\r", "\\r").replace("\n", "\\n"));
        }
    }
}
