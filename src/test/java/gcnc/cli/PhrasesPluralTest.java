package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.tables.ErrorMessages;
import org.junit.jupiter.api.Test;

/** The command line's counts (summaries) by ChoiceFormat: none, one, several, in both languages. */
class PhrasesPluralTest {
    @Test
    void countsInEnglishAndSpanish() {
        Phrases en = new Phrases(ErrorMessages.Lang.EN);
        Phrases es = new Phrases(ErrorMessages.Lang.ES);
        assertEquals("0 blocks, 1 block, 12345 blocks",
                en.count(0, "block") + ", " + en.count(1, "block") + ", " + en.count(12345, "block"));
        assertEquals("0 errores, 1 error, 2 errores",
                es.count(0, "error") + ", " + es.count(1, "error") + ", " + es.count(2, "error"));
        for (String what : new String[] {"block", "error", "line", "finding", "sequence", "segment", "program"}) {
            assertEquals(false, en.count(1, what).endsWith("s"), what);
            assertEquals(true, en.count(2, what).endsWith("s"), what);
            assertEquals(true, es.count(2, what).endsWith("s"), what);
        }
    }

    @Test
    void aSummaryOfOneProgramWithOneBlockIsSingular() throws Exception {
        java.nio.file.Path p = java.nio.file.Files.createTempDirectory("gcnc-plural").resolve("one.nc");
        java.nio.file.Files.writeString(p, "M30\n");
        java.nio.file.Path q = p.resolveSibling("two.nc");
        java.nio.file.Files.writeString(q, "M30\n");
        CliTest.Run r = CliTest.gcnc("check", p.toString(), q.toString());
        assertEquals(true, r.out().contains(": 1 block, no errors"), r.out());
        assertEquals(true, r.out().contains("total: 2 programs, 2 blocks, no errors"), r.out());
    }
}
