package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Colour in the GNU report: on a terminal, never with NO_COLOR, never into a pipe or a file. */
class ColourTest {
    @Test
    void autoIsOnOnlyOnATerminalWithoutNoColor() {
        assertTrue(Colour.enabled(Colour.When.AUTO, Map.of(), true));
        assertFalse(Colour.enabled(Colour.When.AUTO, Map.of(), false), "a pipe or a file");
        assertFalse(Colour.enabled(Colour.When.AUTO, Map.of("NO_COLOR", "1"), true), "no-color.org");
        assertTrue(Colour.enabled(Colour.When.AUTO, Map.of("NO_COLOR", ""), true), "set but empty: no effect");
        assertFalse(Colour.enabled(Colour.When.AUTO, Map.of("TERM", "dumb"), true));
        assertTrue(Colour.enabled(Colour.When.ALWAYS, Map.of("NO_COLOR", "1"), false), "asked for on the command line");
        assertFalse(Colour.enabled(Colour.When.NEVER, Map.of(), true));
    }

    private static Path mistakes() throws IOException {
        Path p = Files.createTempDirectory("gcnc-colour").resolve("part.nc");
        Files.writeString(p, "G21 G99\nG00 X20\nG01 X20. F0.2\nM30\n");
        return p;
    }

    @Test
    void notOnATerminalTheReportHasNoEscapeCodeAndIsTheSameAsNever() throws IOException {
        Path p = mistakes();
        CliTest.Run auto = CliTest.gcnc("check", p.toString(), "--machine", "haas", "--caret", "always");
        CliTest.Run never = CliTest.gcnc("check", p.toString(), "--machine", "haas", "--caret", "always", "--color", "never");
        assertFalse(auto.err().contains("\u001b"), auto.err());
        assertEquals(never.err(), auto.err());
        assertEquals(never.out(), auto.out());
    }

    @Test
    void alwaysColoursThePlaceTheSeverityTheCaretAndTheHintButNotTheText() throws IOException {
        Path p = mistakes();
        CliTest.Run r = CliTest.gcnc("check", p.toString(), "--machine", "haas", "--caret", "always", "--color", "always");
        String err = r.err();
        assertTrue(err.contains("\u001b[1m" + p + ":3:1:\u001b[0m \u001b[1m\u001b[31merror\u001b[0m[E051]"), err);
        assertTrue(err.contains("\u001b[1m\u001b[35mwarning\u001b[0m"), err);
        assertTrue(err.contains("\u001b[1m\u001b[32m ^"), "the caret: " + err);
        assertTrue(err.contains("try \u001b[1m`gcnc explain E051`\u001b[0m."), err);
        // without the escape codes, the very same report
        CliTest.Run plain = CliTest.gcnc("check", p.toString(), "--machine", "haas", "--caret", "always", "--color", "never");
        assertEquals(plain.err(), err.replaceAll("\u001b\\[[0-9;]*m", ""));
        assertFalse(r.out().contains("\u001b"), "summaries are not coloured");
    }

    @Test
    void jsonAndSarifAreNeverColoured() throws IOException {
        Path p = mistakes();
        for (String f : new String[] {"json", "sarif"}) {
            CliTest.Run r = CliTest.gcnc("check", p.toString(), "--machine", "haas", "--format", f, "--color", "always");
            assertFalse(r.out().contains("\u001b") || r.err().contains("\u001b"), f);
        }
    }
}
