package gcnc.parse;

/** Shows one character of the source in a message, readable even when it is invisible. */
final class Chars {
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
}
