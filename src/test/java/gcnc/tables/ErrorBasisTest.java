package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.diag.Severity;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * tables/error_basis.csv against errors.csv (issue 17): a code whose control stops (alarm) or that
 * gcnc cannot follow yet is an error, one whose block the control runs is a warning or a note; each
 * code has one row; and every code of issue 17 (E640-E650) says what it stands for.
 */
class ErrorBasisTest {
    @Test
    void eachRowsBehaviourMatchesItsSeverity() throws TableException {
        ErrorBasis basis = ErrorBasis.load(TableSource.builtIn());
        CodeTable codes = CodeTable.load(TableSource.builtIn());
        assertFalse(basis.rows().isEmpty());
        for (ErrorBasis.Row r : basis.rows().values()) {
            Severity s = codes.find(r.code()).orElseThrow().severity();
            assertTrue(r.agrees(s), r.code() + " is " + s + " in errors.csv but the control " + r.behaviour());
            assertFalse(r.english().isBlank() || r.spanish().isBlank(), r.code() + " says what it stands for");
        }
    }

    @Test
    void everyCodeOfIssue17HasARow() throws TableException {
        ErrorBasis basis = ErrorBasis.load(TableSource.builtIn());
        for (int n = 640; n <= 650; n++) {
            assertTrue(basis.find(Code.byNumber(n)).isPresent(), "E" + n + " has no row in error_basis.csv");
        }
        // issue 31: the control cuts a thread deeper than the sharp V: a warning with the reason
        assertEquals(ErrorBasis.Behaviour.RUNS, basis.find(Code.E193_THREAD_TOO_DEEP).orElseThrow().behaviour());
        assertEquals(ErrorBasis.Source.GCNC, basis.find(Code.E193_THREAD_TOO_DEEP).orElseThrow().source());
    }

    /**
     * Issue 31: every error of errors.csv has a row, an alarm of the control or what gcnc cannot
     * generate, and the row cites its source: a manual row names the Fanuc or Haas alarm, a Galil
     * row the controller's answer or its reference, a thesis row the thesis; a gcnc or setup row
     * says why in words.
     */
    @Test
    void everyErrorHasARowThatCitesTheAlarmOrWhyGcncCannotGenerateIt() throws TableException {
        ErrorBasis basis = ErrorBasis.load(TableSource.builtIn());
        CodeTable codes = CodeTable.load(TableSource.builtIn());
        int errors = 0;
        for (Code c : Code.values()) {
            java.util.Optional<CodeTable.Entry> e = codes.find(c);
            if (e.isEmpty() || e.get().severity() != Severity.ERROR) {
                continue;
            }
            errors++;
            ErrorBasis.Row r = basis.find(c).orElse(null);
            assertTrue(r != null, c.id() + " is an error without a row in error_basis.csv");
            assertTrue(r.behaviour() != ErrorBasis.Behaviour.RUNS, c.id());
            String cite = r.english();
            switch (r.source()) {
                case MANUAL -> assertTrue(cite.contains("Fanuc") || cite.contains("Haas"), c.id() + ": " + cite);
                case GALIL -> assertTrue(cite.contains("TC ") || cite.contains("Galil") || cite.contains("reference"),
                        c.id() + ": " + cite);
                case THESIS -> assertTrue(cite.contains("thesis"), c.id() + ": " + cite);
                case GCNC, SETUP -> assertTrue(cite.split(" ").length >= 6, c.id() + " states no reason: " + cite);
            }
            if (r.source() == ErrorBasis.Source.GCNC && r.behaviour() == ErrorBasis.Behaviour.ALARM) {
                // a rule of gcnc's own is an alarm only where it says what the control does
                assertTrue(cite.contains("TC ") || cite.contains("Fanuc") || cite.contains("Haas")
                        || cite.contains("never"), c.id() + " is gcnc's alarm without the control's: " + cite);
            }
            if (r.source() == ErrorBasis.Source.GCNC && r.behaviour() == ErrorBasis.Behaviour.UNSUPPORTED) {
                assertTrue(cite.contains("gcnc") || cite.contains("simulator"), c.id() + " names no limit: " + cite);
            }
        }
        assertTrue(errors > 200, "errors.csv has its errors");
    }

    @Test
    void eachCodeHasOneRow() throws IOException {
        Set<String> seen = new HashSet<>();
        for (String line : Files.readAllLines(Path.of("tables/error_basis.csv"))) {
            if (line.isBlank() || line.startsWith("#") || line.startsWith("code,")) {
                continue;
            }
            assertTrue(seen.add(line.substring(0, line.indexOf(','))), "twice: " + line);
        }
    }

    @Test
    void aBehaviourThatIsNoneOfTheThreeIsALocatedFault() throws IOException {
        Path dir = Files.createTempDirectory("gcnc-basis");
        Files.writeString(dir.resolve(ErrorBasis.FILE), "code,source,control,en,es\n640,gcnc,stops,x,y\n");
        TableException e = org.junit.jupiter.api.Assertions.assertThrows(TableException.class,
                () -> ErrorBasis.load(TableSource.directory(dir)));
        assertTrue(e.getMessage().contains("error_basis.csv:2:"), e.getMessage());
    }
}
