package gcnc.cli;

/**
 * Text from outside (a file name, a word of the program) made safe to print on a terminal: control
 * characters (C0, DEL, C1) and the invisible bidirectional controls are shown as escapes such as
 * {@code \x1B} or {@code \u202E}, so a name cannot move the cursor, recolour the terminal, split a
 * diagnostic into two lines or reorder what the reader sees.
 */
final class Printable {
    private Printable() {
    }

    static String escape(String s) {
        int i = 0;
        while (i < s.length() && !unsafe(s.charAt(i))) {
            i++;
        }
        if (i == s.length()) {
            return s;
        }
        StringBuilder b = new StringBuilder(s.length() + 8).append(s, 0, i);
        for (; i < s.length(); i++) {
            char c = s.charAt(i);
            if (!unsafe(c)) {
                b.append(c);
            } else if (c < 0x100) {
                b.append(String.format("\\x%02X", (int) c));
            } else {
                b.append(String.format("\\u%04X", (int) c));
            }
        }
        return b.toString();
    }

    static boolean unsafe(char c) {
        return c < 0x20 || c == 0x7f || c >= 0x80 && c <= 0x9f
                || c == 0x061c || c == 0x200e || c == 0x200f
                || c >= 0x202a && c <= 0x202e || c >= 0x2066 && c <= 0x2069
                || c == 0x2028 || c == 0x2029;
    }
}
