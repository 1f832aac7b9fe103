package gcnc.parse;

import gcnc.diag.Span;
import gcnc.ir.Letter;
import gcnc.ir.Word;
import java.util.List;

/**
 * The hot path: a hand-written scan of a line that is plainly well formed (words, spaces, tabs,
 * one-line comments, ';' or '%'). It follows the lexer rules of grammar/GCode.g4 for that subset,
 * longest match included, and gives up on anything else (an error, but also a ':' program number,
 * a '/' block delete, a macro), in which case BlockReader lexes the line with the ANTLR lexer,
 * which is the authority for every error. Measured: the ANTLR lexer alone
 * manages about 1.5 million lines/s, too slow for the 1,000,000 blocks/s target of the whole
 * check; this scan is several times faster. BlockReaderAgreementTest checks that both agree.
 */
final class FastScanner {
    private static final byte NONE = 0;
    private static final byte INTEGER = 1; // G M N O S T: DIGIT+
    private static final byte FEED = 2;    // F: UNSIGNED
    private static final byte COORD = 3;   // every other letter: [+-]? UNSIGNED
    private static final byte[] KIND = new byte[128];

    static {
        for (char c = 'A'; c <= 'Z'; c++) {
            byte kind = "GMNOST".indexOf(c) >= 0 ? INTEGER : c == 'F' ? FEED : COORD;
            KIND[c] = kind;
            KIND[Character.toLowerCase(c)] = kind;
        }
    }

    private FastScanner() {
    }

    /**
     * Adds the words of {@code buf[0, end)} to {@code out} and returns true, or returns false
     * (leaving {@code out} in any state) when the line needs the full lexer. The words' number
     * texts come from {@code texts} (N and O numbers, which do not repeat, are made afresh).
     */
    static boolean scan(char[] buf, int end, int line, List<Word> out, NumberTexts texts) {
        int i = 0;
        while (i < end) {
            char c = buf[i];
            if (c == ' ' || c == '\t') {
                i++;
            } else if (c == ';' || c == '%') {
                return true;
            } else if (c == '(') {
                i = comment(buf, i + 1, end);
                if (i < 0) {
                    return false;
                }
            } else {
                int stop = word(buf, i, end);
                if (stop < 0) {
                    return false;
                }
                Letter letter = Letter.of(c);
                String number = letter == Letter.N || letter == Letter.O ? new String(buf, i + 1, stop - i - 1)
                        : texts.text(buf, i + 1, stop);
                out.add(new Word(letter, number, Span.of(line, i + 1, stop + 1)));
                i = stop;
            }
        }
        return true;
    }

    /** The offset after a one-line comment's ')', or -1 when it is nested or not closed here. */
    private static int comment(char[] buf, int i, int end) {
        for (; i < end; i++) {
            char c = buf[i];
            if (c == ')') {
                return i + 1;
            }
            if (c == '(') {
                return -1;
            }
        }
        return -1;
    }

    /** The end offset of a valid word starting at {@code i}, or -1 for anything else. */
    private static int word(char[] buf, int i, int end) {
        char c = buf[i];
        byte kind = c < 128 ? KIND[c] : NONE;
        int j = i + 1;
        if (kind == NONE) {
            return -1;
        }
        if (kind == INTEGER) {
            j = digits(buf, j, end);
            if (j == i + 1) {
                return -1;
            }
        } else {
            if (kind == COORD && j < end && (buf[j] == '+' || buf[j] == '-')) {
                j++;
            }
            j = unsigned(buf, j, end);
            if (j < 0) {
                return -1;
            }
        }
        // Where the lexer would find a longer NOT_INTEGER or BAD_NUMBER (N1.5, X1.2.3), the next
        // character is a digit, sign or point, which starts nothing here, so scan() gives up.
        return j;
    }

    /** UNSIGNED : DIGIT+ ('.' DIGIT*)? | '.' DIGIT+ ; the end offset, or -1. */
    private static int unsigned(char[] buf, int j, int end) {
        int k = digits(buf, j, end);
        if (k > j) {
            return k < end && buf[k] == '.' ? digits(buf, k + 1, end) : k;
        }
        if (k < end && buf[k] == '.') {
            int m = digits(buf, k + 1, end);
            return m > k + 1 ? m : -1;
        }
        return -1;
    }

    private static int digits(char[] buf, int j, int end) {
        while (j < end && buf[j] >= '0' && buf[j] <= '9') {
            j++;
        }
        return j;
    }
}
