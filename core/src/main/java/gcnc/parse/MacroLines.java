package gcnc.parse;

/**
 * Tells a Fanuc macro B statement line from a line of words, for a control with macros: a '#',
 * '[' or ']' outside a comment, or a line that starts (after its N word) with GOTO, IF, WHILE or
 * END. Asked only of lines the fast scanner gave up on, which every such line is.
 */
final class MacroLines {
    private static final String[] KEYWORDS = {"GOTO", "IF", "WHILE", "END"};

    private MacroLines() {
    }

    /** Whether {@code buf[0, end)} is a macro statement line. */
    static boolean isStatement(char[] buf, int end) {
        boolean inComment = false;
        for (int i = 0; i < end; i++) {
            char c = buf[i];
            if (inComment) {
                inComment = c != ')';
            } else if (c == '(') {
                inComment = true;
            } else if (c == ';') {
                break;
            } else if (c == '#' || c == '[' || c == ']') {
                return true;
            }
        }
        return startsWithKeyword(buf, end);
    }

    /** The offset of the first character that is not a space or tab, or {@code end}. */
    static int firstNonBlank(char[] buf, int end) {
        int i = 0;
        while (i < end && (buf[i] == ' ' || buf[i] == '\t')) {
            i++;
        }
        return i;
    }

    private static boolean startsWithKeyword(char[] buf, int end) {
        int i = firstNonBlank(buf, end);
        if (i < end && buf[i] == '/') { // a block delete mark, with its level
            i++;
            if (i < end && Character.isDigit(buf[i])) {
                i++;
            }
            while (i < end && (buf[i] == ' ' || buf[i] == '\t')) {
                i++;
            }
        }
        if (i < end && (buf[i] == 'N' || buf[i] == 'n')) {
            int j = i + 1;
            while (j < end && Character.isDigit(buf[j])) {
                j++;
            }
            if (j > i + 1) {
                i = j;
                while (i < end && (buf[i] == ' ' || buf[i] == '\t')) {
                    i++;
                }
            }
        }
        for (String k : KEYWORDS) {
            int n = k.length();
            if (i + n <= end && new String(buf, i, n).equalsIgnoreCase(k)
                    && (i + n == end || !Character.isLetter(buf[i + n]))) {
                return true;
            }
        }
        return false;
    }
}
