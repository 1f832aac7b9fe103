package gcnc.flow;

import gcnc.diag.Code;

/**
 * The characters of one macro line and the reading of them: spaces and comments skipped
 * (Fanuc ignores spaces; a comment's text is kept for #3000), numbers, letters, keywords, and the
 * located fault that stops the line. {@link MacroExpression} and {@link MacroLine} read on from it.
 */
class MacroCursor {
    /** An error at a column of the line: reported by MacroLine.run. */
    static final class Fault extends Exception {
        final Code code;
        final int at;
        final transient Object[] args;

        Fault(Code code, int at, Object... args) {
            super(null, null, false, false);
            this.code = code;
            this.at = at;
            this.args = args;
        }
    }

    final String s;
    int i;
    /** The text of the last comment passed, for #3000's message. */
    String comment = "";

    MacroCursor(String s) {
        this.s = s;
    }

    char peek() {
        return i < s.length() ? s.charAt(i) : 0;
    }

    /** Skips spaces, tabs and comments (keeping the last comment's text). */
    void blank() throws Fault {
        while (i < s.length()) {
            char c = s.charAt(i);
            if (c == ' ' || c == '\t') {
                i++;
            } else if (c == '(') {
                int close = s.indexOf(')', i);
                if (close < 0) {
                    throw new Fault(Code.E005_COMMENT_NOT_CLOSED, i);
                }
                comment = s.substring(i + 1, close).strip();
                i = close + 1;
            } else {
                return;
            }
        }
    }

    boolean labelAhead() {
        return (peek() == 'N' || peek() == 'n') && i + 1 < s.length() && Character.isDigit(s.charAt(i + 1));
    }

    String digits() {
        int from = i;
        while (i < s.length() && Character.isDigit(s.charAt(i))) {
            i++;
        }
        return s.substring(from, i);
    }

    /** A number as written: [+-] digits [. digits]. */
    String literal() {
        int from = i;
        if (peek() == '+' || peek() == '-') {
            i++;
        }
        while (i < s.length() && (Character.isDigit(s.charAt(i)) || s.charAt(i) == '.')) {
            i++;
        }
        String t = s.substring(from, i);
        return t.equals("+") || t.equals("-") ? "" : t;
    }

    /** A run of letters, upper case. */
    String letters() throws Fault {
        blank();
        int from = i;
        while (i < s.length() && Character.isLetter(s.charAt(i))) {
            i++;
        }
        return s.substring(from, i).toUpperCase(java.util.Locale.ROOT);
    }

    boolean keywordAhead(String k) {
        int n = k.length();
        return i + n <= s.length() && s.regionMatches(true, i, k, 0, n)
                && (i + n == s.length() || !Character.isLetter(s.charAt(i + n)));
    }

    boolean keyword(String k) throws Fault {
        blank();
        if (keywordAhead(k)) {
            i += k.length();
            return true;
        }
        return false;
    }

    void expect(char c) throws Fault {
        blank();
        if (peek() != c) {
            throw syntax(i);
        }
        i++;
    }

    Fault syntax(int at) {
        return new Fault(Code.E010_SYNTAX, at, "'" + excerpt(at) + "'");
    }

    String excerpt(int from) {
        String t = from < s.length() ? s.substring(from).strip() : "";
        return t.isEmpty() ? "end of line" : t.length() > 30 ? t.substring(0, 30) + "..." : t;
    }

    /** The text from {@code from} to {@code to}, shortened as {@link #excerpt(int)} does. */
    String excerpt(int from, int to) {
        String t = s.substring(Math.min(from, s.length()), Math.min(Math.max(from, to), s.length())).strip();
        return t.isEmpty() ? excerpt(from) : t.length() > 30 ? t.substring(0, 30) + "..." : t;
    }

    /** A statement's text as written, from {@code from} to here. */
    String text(int from) {
        return s.substring(from, i);
    }

    /** A statement's text as messages show it: no comments, single spaces (worked out only for a message). */
    static String clean(String written) {
        return written.replaceAll("\\([^)]*\\)", "").strip().replaceAll("\\s+", " ");
    }
}
