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
        assertEquals(ErrorBasis.Behaviour.ALARM, basis.find(Code.E193_THREAD_TOO_DEEP).orElseThrow().behaviour());
        assertEquals(ErrorBasis.Source.GCNC, basis.find(Code.E193_THREAD_TOO_DEEP).orElseThrow().source());
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
