package gcnc.parse;

import gcnc.diag.Code;
import gcnc.parse.gen.GCodeLexer;
import org.antlr.v4.runtime.Token;

/**
 * Two typing slips that the lexer can only call malformed, though a machinist sees at once what
 * was meant: the letter O typed for a zero inside a number ({@code Z-3O.}, error 120) and a
 * decimal comma ({@code Z-30,5}, {@code Z,15}, error 121). Without a hint they read as a bare
 * letter, text outside a comment or a stray character (6, 109, 10), which send the reader
 * looking elsewhere.
 *
 * <p>A word here is a letter and the run of number characters after it, O and comma included
 * ({@code Z-3O.}, {@code G0O}, {@code Z,15}). An O or o in the run is a slip for 0 (unless the
 * run has no digit and a letter follows it: {@code GOTO} is a word); a comma is a slip for the
 * point only when a digit follows it ({@code X10,Z5} is a separator, not a decimal).
 * {@link #find} fixes every such slip of a line in place; {@link BlockReader} then gives the hint
 * only when the fixed line reads cleanly, so {@code GO HOME} stays text and {@code S1,200} (a
 * thousands separator: S1.200 is no speed) keeps its own error.
 */
final class Slips {
    /** A slip: the buffer offset of its word's letter, its code, the word as written and as meant. */
    record Slip(int at, Code code, String written, String meant) {
    }

    private Slips() {
    }

    /**
     * Whether {@code lexer} finds no error token in {@code text[0, end)} (the grammar's verdict on a
     * fixed line), read through {@code probe}.
     */
    static boolean readsCleanly(GCodeLexer lexer, LineCharStream probe, char[] text, int end, boolean open) {
        probe.reset(text, 0, end, open);
        lexer.setInputStream(probe);
        for (Token t = lexer.nextToken(); t.getType() != Token.EOF; t = lexer.nextToken()) {
            switch (t.getType()) {
                case GCodeLexer.BARE_LETTER, GCodeLexer.TEXT, GCodeLexer.NOT_INTEGER, GCodeLexer.BAD_NUMBER,
                        GCodeLexer.MACRO, GCodeLexer.STRAY, GCodeLexer.ILLEGAL, GCodeLexer.NESTED_COMMENT -> {
                    return false;
                }
                default -> { }
            }
        }
        return true;
    }

    /**
     * Fixes every slip of the line {@code buf[0, end)} in place (comments left alone; {@code open}:
     * the line starts inside a comment) and returns the slip whose word holds offset
     * {@code error}, or null when the line's error is not inside such a word.
     */
    static Slip find(char[] buf, int end, boolean open, int error) {
        Slip found = null;
        int i = open ? skipComment(buf, 0, end) : 0;
        while (i < end) {
            char c = buf[i];
            if (c == '(') {
                i = skipComment(buf, i + 1, end);
            } else if (c == ';' || c == '%') {
                break;
            } else if (isLetter(c)) {
                int stop = i + 1;
                while (stop < end && inRun(buf[stop])) {
                    stop++;
                }
                Slip s = fix(buf, i, stop, end);
                if (s != null && found == null && error >= i && error < stop) {
                    found = s;
                }
                i = stop;
            } else {
                i++;
            }
        }
        return found;
    }

    /**
     * Fixes the slips of the word {@code buf[letter, stop)}; the slip, or null when it has none.
     * An O with no digit beside it in the run, right before another letter, is a word of text
     * ({@code GOTO}), not a number.
     */
    private static Slip fix(char[] buf, int letter, int stop, int end) {
        boolean digits = false;
        for (int k = letter + 1; k < stop; k++) {
            digits |= isDigit(buf[k]);
        }
        boolean text = !digits && stop < end && isLetter(buf[stop]);
        String written = null;
        boolean o = false;
        for (int k = letter + 1; k < stop; k++) {
            char c = buf[k];
            boolean slipO = (c == 'O' || c == 'o') && !text;
            boolean comma = c == ',' && k + 1 < stop && isDigit(buf[k + 1]);
            if (slipO || comma) {
                if (written == null) {
                    written = new String(buf, letter, stop - letter);
                }
                o |= slipO;
                buf[k] = slipO ? '0' : '.';
            }
        }
        if (written == null) {
            return null;
        }
        // a word with both slips is first of all an O slip; its fix shows both
        return new Slip(letter, o ? Code.E120_LETTER_O_IN_NUMBER : Code.E121_DECIMAL_COMMA, written,
                new String(buf, letter, stop - letter));
    }

    /** The offset after the ')' that closes a comment whose text starts at {@code i} (or the end). */
    private static int skipComment(char[] buf, int i, int end) {
        while (i < end && buf[i] != ')') {
            i++;
        }
        return Math.min(i + 1, end);
    }

    /** The characters of a number, with the two slips: digits, sign, point, O and comma. */
    private static boolean inRun(char c) {
        return isDigit(c) || c == '.' || c == '+' || c == '-' || c == 'O' || c == 'o' || c == ',';
    }

    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    private static boolean isLetter(char c) {
        return c >= 'A' && c <= 'Z' || c >= 'a' && c <= 'z';
    }
}
