package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.time.Duration;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.Set;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Seeded fuzzing: BlockReader never throws or hangs, every rejection is a numbered parse
 * diagnostic on the line of a malformed block, and every accepted word has a valid shape.
 * A failure message names the seed; rerun one with -Dgcnc.fuzz.seed=N.
 */
class BlockReaderFuzzTest {
    private static final Set<Code> PARSE_CODES = EnumSet.of(Code.E001_G_NUMBER_EXPECTED,
            Code.E002_M_NUMBER_EXPECTED, Code.E003_ILLEGAL_CHARACTER, Code.E005_COMMENT_NOT_CLOSED,
            Code.E006_NUMBER_EXPECTED, Code.E010_SYNTAX, Code.E013_INTEGER_EXPECTED, Code.E014_DECIMAL_EXPECTED,
            Code.E054_NESTED_COMMENT, Code.E109_TEXT_OUTSIDE_COMMENT, Code.E111_MACRO_NOT_SUPPORTED_YET,
            Code.E120_LETTER_O_IN_NUMBER, Code.E121_DECIMAL_COMMA, Code.E600_SPACE_IN_NUMBER,
            Code.E602_TEXT_AFTER_END_OF_FILE_MARK, Code.E702_DOTTED_G_NOT_SUPPORTED,
            Code.E261_DENFORD_SETUP_LINE); // a "[" and a word at a line's start: a training control's set-up line
    private static final Pattern INTEGER = Pattern.compile("[0-9]+");
    private static final Pattern FEED = Pattern.compile("([0-9]+(\\.[0-9]*)?|\\.[0-9]+)");
    private static final Pattern COORD = Pattern.compile("[+-]?([0-9]+(\\.[0-9]*)?|\\.[0-9]+)");

    private static long[] seeds() {
        Long fixed = Long.getLong("gcnc.fuzz.seed");
        return fixed != null ? new long[] {fixed} : new long[] {1, 2, 3, 42, 2004, System.nanoTime()};
    }

    @Test
    void tokenSoupAndRandomCharactersNeverBreakTheReader() {
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            for (long seed : seeds()) {
                Soup soup = new Soup(seed);
                for (int round = 0; round < 300; round++) {
                    String src = round % 3 == 0 ? soup.tokenSoup(1 + round % 80)
                            : round % 3 == 1 ? soup.mutatedProgram(round % 30) : soup.bytes(round * 3);
                    check(seed, src);
                }
            }
        });
    }

    private static void check(long seed, String src) {
        String where = "seed " + seed + ", source " + escape(src);
        Parsed p;
        try {
            p = Parsed.of(src);
        } catch (RuntimeException e) {
            fail("threw " + e + " on " + where, e);
            return;
        }
        Set<Integer> badLines = new HashSet<>();
        for (Diagnostic d : p.diagnostics()) {
            if (d.code() == Code.E115_SAME_CAUSE && d.severity() == gcnc.diag.Severity.NOTE) {
                continue; // a repeated warning folded into one (Diagnostics): the note that lists the others
            }
            assertTrue(PARSE_CODES.contains(d.code()), "unexpected " + d + " for " + where);
            assertTrue(d.span().line() <= Math.max(p.lines(), 1), "diagnostic past the end: " + d + " for " + where);
            if (d.code() != Code.E005_COMMENT_NOT_CLOSED && d.severity() == gcnc.diag.Severity.ERROR) {
                assertTrue(badLines.add(d.span().line()), "two errors on one line: " + p.errors() + " for " + where);
            }
        }
        int previous = 0;
        for (RawBlock b : p.blocks()) {
            assertTrue(b.line() > previous, "blocks out of order for " + where);
            previous = b.line();
            assertEquals(b.malformed(), badLines.remove(b.line()), "malformed iff reported, line " + b.line() + " " + where);
            assertTrue(b.malformed() || !b.words().isEmpty(), "empty good block for " + where);
            assertTrue(b.blockDelete() >= 0 && b.blockDelete() <= 9, "block delete level for " + where);
            b.words().forEach(w -> assertTrue(shapeOk(w), "bad word " + w + " for " + where));
        }
        assertTrue(badLines.isEmpty(), "error lines without a malformed block " + badLines + " for " + where);
    }

    private static boolean shapeOk(Word w) {
        switch (w.letter()) {
            case G: case M: case N: case O: case S: case T:
                return INTEGER.matcher(w.number()).matches();
            case F:
                return FEED.matcher(w.number()).matches();
            default:
                return COORD.matcher(w.number()).matches();
        }
    }

    static String escape(String s) {
        StringBuilder sb = new StringBuilder("\"");
        for (char c : s.toCharArray()) {
            if (c >= 32 && c < 127 && c != '"' && c != '\\') {
                sb.append(c);
            } else {
                sb.append(String.format("\\u%04x", (int) c));
            }
        }
        return sb.append('"').toString();
    }
}
