package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * {@code gcnc explain} in prose (tables/explain/), and the GCC-style report's closing line that
 * points to it, as rustc's "For more information about this error, try `rustc --explain E0308`."
 */
class ExplainHintTest {
    private static Path program(String text) throws IOException {
        Path p = Files.createTempDirectory("gcnc-hint").resolve("part.nc");
        Files.writeString(p, text);
        return p;
    }

    private static List<String> lines(String s) {
        return s.lines().toList();
    }

    @Test
    void explainGivesWhyWhatTheControlDoesTheFixAndAnExample() {
        CliTest.Run r = CliTest.gcnc("explain", "E051");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("  Why: A feed move before the spindle's direction was ever given"), r.out());
        assertTrue(r.out().contains("  the control stops (alarm) (gcnc's rule beyond the manuals): a cut before the spindle"
                + " was ever started"), r.out());
        assertTrue(r.out().contains("  Fix: Start the spindle with M03"), r.out());
        assertTrue(r.out().contains("  Example (machine haas):\n      G21 G99\n      G01 X20. Z-5. F0.2\n"), r.out());
    }

    @Test
    void explainInSpanishHasNoEnglishProse() {
        CliTest.Run r = CliTest.gcnc("explain", "--lang", "es", "E015");
        assertTrue(r.out().contains("  Por qué: El punto final de un movimiento queda fuera del recorrido"), r.out());
        assertTrue(r.out().contains("  Arreglo: Revise la coordenada"), r.out());
        assertTrue(r.out().contains("  Ejemplo (máquina haas; tras el inicio habitual de un programa: G21 G40 G99 /"),
                r.out());
        for (String english : List.of("Why:", "Fix:", "Example", "The control", "the control stops")) {
            assertFalse(r.out().contains(english), english + " in:\n" + r.out());
        }
    }

    @Test
    void aCodeNoProgramMeetsSaysSo() {
        CliTest.Run r = CliTest.gcnc("explain", "E500");
        assertTrue(r.out().contains("No G-code program brings this code about: the command line's files"), r.out());
    }

    @Test
    void aSimulatorCrashSaysTheControlWouldRunTheMove() {
        CliTest.Run r = CliTest.gcnc("explain", "E305");
        assertTrue(r.out().contains("What the control does: The control runs the rapid as written"), r.out());
    }

    @Test
    void theReportEndsWithOneHintNamingTheFirstError() throws IOException {
        Path p = program("G21 G99\nG01 X20. F0.2\nZ-10.\n");
        CliTest.Run r = CliTest.gcnc("check", p.toString(), p.toString(), "--machine", "haas");
        assertEquals(1, r.status());
        List<String> err = lines(r.err());
        assertEquals("For more information about this error try `gcnc explain E051`.", err.get(err.size() - 1));
        assertEquals(1, err.stream().filter(l -> l.startsWith("For more information")).count(), r.err());
    }

    @Test
    void anErrorIsNamedBeforeAnEarlierWarning() throws IOException {
        // E107 (a warning) at line 6 comes before the E015 at line 7
        Path p = program("G21 G40 G99\nG50 S2000\nT0101\nG97 S500 M03\nG00 X50. Z2.\nG00 X20\nG00 X2000.\nM30\n");
        List<String> err = lines(CliTest.gcnc("check", p.toString(), "--machine", "haas").err());
        assertTrue(err.get(0).contains("warning[E107]"), err.toString());
        assertEquals("For more information about this error try `gcnc explain E015`.", err.get(err.size() - 1));
    }

    @Test
    void warningsOnlyNameAWarningAndACleanRunNothing() throws IOException {
        Path warned = program("G21 G40 G99\nG50 S2000\nT0101\nG97 S500 M03\nG00 X20\nM30\n");
        List<String> err = lines(CliTest.gcnc("check", warned.toString(), "--machine", "haas").err());
        assertEquals("For more information about this warning try `gcnc explain E107`.", err.get(err.size() - 1));
        CliTest.Run clean = CliTest.gcnc("check", "samples/turning.nc");
        assertFalse(clean.err().contains("gcnc explain"), clean.err());
    }

    @Test
    void theHintIsInTheRunsLanguageAndNotInQuietJsonOrSarif() throws IOException {
        Path p = program("G21 G99\nG01 X20. F0.2\nM30\n");
        List<String> es = lines(CliTest.gcnc("--lang", "es", "check", p.toString(), "--machine", "haas").err());
        assertEquals("Para más información sobre este error pruebe `gcnc explain E051`.", es.get(es.size() - 1));
        assertFalse(CliTest.gcnc("check", "--quiet", p.toString(), "--machine", "haas").err().contains("explain"));
        for (String format : List.of("json", "sarif")) {
            CliTest.Run r = CliTest.gcnc("check", "--format", format, p.toString(), "--machine", "haas");
            assertFalse(r.err().contains("gcnc explain") || r.out().contains("try `gcnc explain"), format);
        }
    }

    @Test
    void aFileThatCannotBeReadGetsNoHint() {
        CliTest.Run r = CliTest.gcnc("check", "no/such/part.nc");
        assertTrue(r.err().contains("error[E500]"), r.err());
        assertFalse(r.err().contains("gcnc explain"), r.err());
    }
}
