package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** GCC's layout on a terminal: under each finding, the program's line and a caret at the column. */
class CaretTest {
    private static final String PROGRAM = "G21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X46. Z2.\n"
            + "\tG01 X41. Z-3O. F100.\nM30\n";

    @Test
    void theLineAndACaretUnderTheColumn() throws Exception {
        Path p = CliTest.program(PROGRAM);
        CliTest.Run r = CliTest.gcnc("check", p.toString(), "--caret", "always");
        String[] err = r.err().split("\n");
        assertTrue(err[0].contains(":7:11: error[E120]"), r.err());
        assertEquals(" \\x09G01 X41. Z-3O. F100.", err[1], "the line as written, its tab shown escaped");
        assertEquals('Z', err[1].charAt(err[2].indexOf('^')), "the caret under the Z word, column 11: " + err[2]);
        assertEquals(err[2].indexOf('^'), err[2].length() - 1);
    }

    @Test
    void tildesUnderTheRestOfTheWordAndItsEndInTheReports() throws Exception {
        Path p = CliTest.program(PROGRAM.replace("Z-3O.", "Z-3000."));
        CliTest.Run r = CliTest.gcnc("check", p.toString(), "--caret", "always");
        String[] err = r.err().split("\n");
        assertTrue(err[0].contains(":7:11: error[E015]"), r.err());
        assertEquals("^~~~~~~", err[2].strip(), "a caret under Z, tildes under -3000.: " + err[2]);
        assertEquals('Z', err[1].charAt(err[2].indexOf('^')));
        CliTest.Run json = CliTest.gcnc("check", p.toString(), "--format", "json");
        assertTrue(json.out().contains("\"column\": 11,\n      \"endColumn\": 18,"), json.out());
        CliTest.Run sarif = CliTest.gcnc("check", p.toString(), "--format", "sarif");
        assertTrue(sarif.out().replaceAll("\\s", "").contains("\"startColumn\":11,\"endColumn\":18"), sarif.out());
    }

    @Test
    void offTheTerminalOrWhenAskedNotToNoLines() throws Exception {
        Path p = CliTest.program(PROGRAM);
        for (String[] args : new String[][] {{"check", p.toString()}, {"check", p.toString(), "--caret", "never"}}) {
            CliTest.Run r = CliTest.gcnc(args);
            // the finding, and the closing hint to gcnc explain (ExplainHintTest)
            assertEquals(2, r.err().strip().split("\n").length, r.err());
        }
    }

    @Test
    void theJsonReportIsNotTouched() throws Exception {
        Path p = CliTest.program(PROGRAM);
        CliTest.Run r = CliTest.gcnc("check", p.toString(), "--caret", "always", "--format", "json");
        assertFalse(r.out().contains("^"), r.out());
    }
}
