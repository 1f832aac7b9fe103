package gcnc.diag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.tables.Tables;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The Code enum and tables/errors.csv describe the same codes, each number once (ANTLR's AllErrorCodesDistinct). */
class CodeTableTest {
    @Test
    void numbersAreDistinct() {
        Set<Integer> seen = new HashSet<>();
        for (Code c : Code.values()) {
            assertTrue(seen.add(c.number()), "number used twice: " + c.number());
        }
    }

    @Test
    void everyCodeHasEnglishAndSpanishText() {
        Tables t = Tables.builtIn();
        for (Code c : Code.values()) {
            assertTrue(t.messages().has(c), c + " has no row in tables/errors.csv");
        }
    }

    @Test
    void everyCsvRowIsACode() throws IOException {
        int rows = 0;
        for (String line : Files.readAllLines(Path.of("tables/errors.csv"))) {
            if (line.isBlank() || line.startsWith("#") || line.startsWith("code,")) {
                continue;
            }
            Code.byNumber(Integer.parseInt(line.substring(0, line.indexOf(','))));
            rows++;
        }
        assertEquals(Code.values().length, rows, "errors.csv rows vs Code constants");
    }

    @Test
    void thesisTableFiveHasAllFiftyFourErrors() {
        for (int n = 1; n <= 54; n++) {
            Code c = Code.byNumber(n);
            assertTrue(c.name().startsWith(String.format("E%03d_", n)), c.name());
        }
    }

    /** The number is read from the name (Code.number): every name is E, three digits, an underscore and words. */
    @Test
    void everyNameCarriesItsNumber() {
        for (Code c : Code.values()) {
            assertTrue(c.name().matches("E[0-9]{3}_[A-Z0-9_]+"), c.name());
            assertEquals(c.name().substring(0, 4), String.format("E%03d", c.number()), c.name());
        }
    }

    @Test
    void idIsThreeDigits() {
        assertEquals("E037", Code.byNumber(37).id());
        assertEquals("E500", Code.E500_IO.id());
    }

    @Test
    void rendersGnuStyleInBothLanguages() {
        Tables t = Tables.builtIn();
        Diagnostic d = Diagnostic.error(Code.byNumber(48), Span.of(12, 7), "3000", "2500");
        assertEquals("part.nc:12:7: error[E048]: S3000 exceeds the maximum S2500 set by G50",
                new GnuRenderer(t.messages().in(gcnc.tables.ErrorMessages.Lang.EN)).render("part.nc", d));
        assertEquals("part.nc:12:7: error[E048]: El valor de S3000 excede el máximo S2500 especificado por G50",
                new GnuRenderer(t.messages().in(gcnc.tables.ErrorMessages.Lang.ES)).render("part.nc", d));
    }
}
