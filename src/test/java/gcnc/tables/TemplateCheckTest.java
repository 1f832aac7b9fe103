package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.text.MessageFormat;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * errors.csv's templates are judged without a MessageFormat when every brace is a plain {n}
 * (issue 23: making one for each of a thousand templates was a part of every start). The quick
 * judgement may send a template on to MessageFormat, never pass one MessageFormat would refuse.
 */
class TemplateCheckTest {
    @Test
    void theQuickJudgementPassesOnlyWhatMessageFormatAccepts() {
        Random random = new Random(23);
        String alphabet = "{}{}0123456789a ,'";
        int passed = 0;
        for (int n = 0; n < 200_000; n++) {
            StringBuilder t = new StringBuilder();
            for (int i = random.nextInt(9); i > 0; i--) {
                t.append(alphabet.charAt(random.nextInt(alphabet.length())));
            }
            String template = t.toString();
            if (ErrorMessages.plainPlaceholders(template)) {
                passed++;
                assertDoesNotThrow(() -> new MessageFormat(template.replace("'", "''"), Locale.ROOT), template);
            }
        }
        assertTrue(passed > 1000, "too few templates passed to test anything: " + passed);
    }

    @Test
    void plainPlaceholdersPassAndOthersGoToMessageFormat() {
        assertTrue(ErrorMessages.plainPlaceholders("G{0} at line {1}, can't {12}"));
        assertTrue(ErrorMessages.plainPlaceholders("no placeholder"));
        assertFalse(ErrorMessages.plainPlaceholders("{0"));
        assertFalse(ErrorMessages.plainPlaceholders("{a}"));
        assertFalse(ErrorMessages.plainPlaceholders("{}"));
        assertFalse(ErrorMessages.plainPlaceholders("{12345}"));
        assertFalse(ErrorMessages.plainPlaceholders("a } alone"));
    }
}
