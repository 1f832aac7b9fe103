package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** {@code gcnc explain} says which control behaviour a rule stands for (tables/error_basis.csv, issue 17). */
class ExplainBasisTest {
    @Test
    void aWarningSaysTheControlRunsTheBlockAndAnErrorThatItStops() {
        CliTest.Run w = CliTest.gcnc("explain", "E642");
        assertEquals(0, w.status(), w.err());
        assertTrue(w.out().contains("  the control runs the block (the manual's rule): G70 takes P and Q"), w.out());
        CliTest.Run e = CliTest.gcnc("explain", "E193");
        assertTrue(e.out().contains("  the control runs the block (gcnc's rule beyond the manuals): the control cuts any height"),
                e.out());
        CliTest.Run a = CliTest.gcnc("explain", "E049");
        assertTrue(a.out().contains("  the control stops (alarm) (the manual's rule): Fanuc PS0022"), a.out());
        CliTest.Run es = CliTest.gcnc("explain", "--lang", "es", "E650");
        assertTrue(es.out().contains("  gcnc no lo genera (regla de gcnc más allá de los manuales): gcnc sigue"),
                es.out());
    }

    @Test
    void aCodeWithoutARowPrintsNoBasisButWhatTheControlDoesFromItsProse() {
        // no basis row: the prose (tables/explain/) says what the control does, else the severity does
        CliTest.Run r = CliTest.gcnc("explain", "E107");
        assertFalse(r.out().contains("the control stops (alarm)"), r.out());
        assertTrue(r.out().contains("  What the control does: it runs the block"), r.out());
        CliTest.Run e = CliTest.gcnc("explain", "E305");
        assertTrue(e.out().contains("  What the control does: The control runs the rapid as written"), e.out());
    }

    @Test
    void aTablesFolderWithoutTheBasisFileStillExplains() throws IOException {
        Path dir = Files.createTempDirectory("gcnc-basis");
        Files.copy(Path.of("tables/errors.csv"), dir.resolve("errors.csv"));
        CliTest.Run r = CliTest.gcnc("explain", "--tables", dir.toString(), "E642");
        assertEquals(0, r.status(), r.err());
        assertFalse(r.out().contains("the control runs"), r.out());
    }
}
