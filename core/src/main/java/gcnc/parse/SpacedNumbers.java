package gcnc.parse;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.Letter;

/**
 * The number of a word as the control reads it, without the spaces it ignores ({@code G 01},
 * {@code X- 2.5}, {@code T1 01}), for {@link BlockReader}; a space between two characters of the
 * number itself is warned about (E600).
 */
final class SpacedNumbers {
    private SpacedNumbers() {
    }

    /** The index of the first character from {@code i} on that is not a blank (a space or a tab). */
    static int skipBlanks(char[] buf, int i) {
        while (buf[i] == ' ' || buf[i] == '\t') {
            i++;
        }
        return i;
    }

    /**
     * The number of a word, {@code buf[from, stop)} after its letter (the word starts at {@code
     * word}, on line {@code line}), without the spaces the control ignores ({@code G 01}, {@code X-
     * 2.5}, {@code T1 01}). A space between two characters of the number itself ({@code X10 5} =
     * X105) is warned about (E600), as it may be a lost letter, except in a T word: {@code T1 01}
     * (tool 1, offset 01) is how shops write a tool change.
     */
    static String number(Letter letter, char[] buf, int word, int from, int stop, int line, Diagnostics diagnostics) {
        StringBuilder sb = null;
        int split = -1;
        for (int i = from; i < stop; i++) {
            char c = buf[i];
            if (c == ' ' || c == '\t') {
                if (sb == null) {
                    sb = new StringBuilder(stop - from).append(buf, from, i - from);
                }
                char before = sb.length() > 0 ? sb.charAt(sb.length() - 1) : ' ';
                if (split < 0 && (Character.isDigit(before) || before == '.')) {
                    split = i;
                }
            } else if (sb != null) {
                sb.append(c);
            }
        }
        if (sb == null) {
            return new String(buf, from, stop - from);
        }
        String number = sb.toString();
        if (split >= 0 && letter != Letter.T) {
            diagnostics.report(Diagnostic.warning(Code.E600_SPACE_IN_NUMBER, Span.of(line, split + 1),
                    new String(buf, word, stop - word), (buf[word] == ',' ? "," : "") + letter.name() + number));
        }
        return number;
    }
}
