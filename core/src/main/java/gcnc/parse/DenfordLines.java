package gcnc.parse;

/**
 * Tells a Denford / MIRAC set-up line: a line whose first character (after blanks) is '[' and
 * then a name of letters, such as {@code [BILLET X50 Z100} (the stock for Denford's own
 * simulation: X its diameter, Z its length) or {@code [TOOLDEF T1 ..}. The training control's
 * software reads these lines for its simulation and sends nothing of them to the machine, so
 * gcnc reads them as comments and names the dialect (E261) instead of the syntax or macro error a
 * '[' would be. A Fanuc macro line opens a bracket with an expression ({@code [#1+2]}), never a
 * name of two or more letters followed by a blank or the end of the line.
 */
final class DenfordLines {
    private DenfordLines() {
    }

    /** Whether {@code buf[0, end)} is a set-up line. */
    static boolean isSetUp(char[] buf, int end) {
        int i = MacroLines.firstNonBlank(buf, end);
        if (i >= end || buf[i] != '[') {
            return false;
        }
        int j = i + 1;
        while (j < end && Character.isLetter(buf[j])) {
            j++;
        }
        return j - i - 1 >= 2 && (j == end || buf[j] == ' ' || buf[j] == '\t');
    }

    /** The line after its '[', trimmed ("BILLET X50 Z100"). */
    static String text(char[] buf, int end) {
        int i = MacroLines.firstNonBlank(buf, end);
        return new String(buf, i + 1, end - i - 1).trim();
    }
}
