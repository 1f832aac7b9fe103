package gcnc.parse;

/** Shows characters of the source in a message, readable even when they are invisible. */
final class Chars {
    /** The longest excerpt of a line a message quotes (then "..." follows). */
    static final int EXCERPT = 30;

    private Chars() {
    }

    /** The character (or surrogate pair) at {@code at}; control and odd characters as U+XXXX. */
    static String show(char[] buf, int at, int end) {
        int cp = Character.codePointAt(buf, at, end);
        boolean visible = !Character.isISOControl(cp) && Character.isDefined(cp)
                && !Character.isSurrogate((char) cp) && !Character.isWhitespace(cp)
                && Character.getType(cp) != Character.FORMAT;
        return visible ? new String(Character.toChars(cp)) : String.format("U+%04X", cp);
    }

    /**
     * The text of the line from {@code at}, up to its end or the start of a comment ('(', ';' or
     * '%'), trimmed, and cut to {@link #EXCERPT} characters with "..." appended when longer: what
     * the user wrote there, for messages such as errors 109 and 111.
     */
    static String excerpt(char[] buf, int at, int end) {
        int stop = at;
        while (stop < end && buf[stop] != '(' && buf[stop] != ';' && buf[stop] != '%') {
            stop++;
        }
        String text = new String(buf, at, stop - at).strip();
        if (text.length() <= EXCERPT) {
            return text;
        }
        int cut = Character.isHighSurrogate(text.charAt(EXCERPT - 1)) ? EXCERPT - 1 : EXCERPT;
        return text.substring(0, cut).stripTrailing() + "...";
    }
}
