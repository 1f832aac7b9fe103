package gcnc.controller;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The program memory: the lines a {@code DL} stored, exactly as they came (so that {@code UL} gives them
 * back byte for byte), each also split into its statements, and the labels. A download that breaks a
 * limit of the model (a line over 80 characters, more lines than the model holds, a bad or duplicate
 * label, more than 510 labels) is refused whole and leaves the memory as it was.
 */
final class ProgramMemory {
    /** One program line: its text and its statements ({@code ;}-separated, quotes respected). */
    record Line(String text, List<String> statements) {
    }

    private final List<Line> lines = new ArrayList<>();
    private final Map<String, Integer> labels = new HashMap<>();

    int size() {
        return lines.size();
    }

    Line line(int n) {
        return lines.get(n);
    }

    int labelCount() {
        return labels.size();
    }

    /** The line of {@code #name}, or -1. */
    int label(String name) {
        Integer n = labels.get(name);
        return n == null ? -1 : n;
    }

    /**
     * Replaces the program by {@code text} (lines end with CR, LF or CR LF), or with {@code append} adds
     * it at the end ({@code DL #}).
     */
    void download(String text, boolean append, Model model) throws GalilException {
        List<String> texts = new ArrayList<>();
        int from = 0;
        for (int i = 0; i <= text.length(); i++) {
            if (i == text.length() || text.charAt(i) == '\r' || text.charAt(i) == '\n') {
                if (i > from || i < text.length()) {
                    texts.add(text.substring(from, i));
                }
                if (i < text.length() && text.charAt(i) == '\r' && i + 1 < text.length() && text.charAt(i + 1) == '\n') {
                    i++;
                }
                from = i + 1;
            }
        }
        List<Line> next = new ArrayList<>(append ? lines : List.of());
        Map<String, Integer> nextLabels = new HashMap<>(append ? labels : Map.of());
        for (String t : texts) {
            if (t.length() > model.lineChars || next.size() >= model.lines) {
                throw new GalilException(Tc.DOWNLOAD);
            }
            List<String> statements = statements(t);
            for (String st : statements) {
                if (st.startsWith("#")) {
                    String name = st.substring(1);
                    if (!name.matches("[A-Za-z][A-Za-z0-9]{0,6}") || nextLabels.containsKey(name)) {
                        throw new GalilException(Tc.BAD_LABEL);
                    }
                    nextLabels.put(name, next.size());
                    if (nextLabels.size() > model.labels) {
                        throw new GalilException(Tc.TOO_MANY_LABELS);
                    }
                }
            }
            next.add(new Line(t, statements));
        }
        lines.clear();
        lines.addAll(next);
        labels.clear();
        labels.putAll(nextLabels);
    }

    /** What {@code UL} sends before its end marker: every line followed by CR LF. */
    String upload() {
        StringBuilder b = new StringBuilder();
        for (Line l : lines) {
            b.append(l.text()).append("\r\n");
        }
        return b.toString();
    }

    /**
     * The statements of a line: split at {@code ;} outside quotes, blanks around each removed, empty ones
     * dropped; a {@code '} comment, {@code REM} or {@code NO} runs to the end of the line.
     */
    static List<String> statements(String line) {
        List<String> out = new ArrayList<>(2);
        boolean quoted = false;
        int from = 0;
        for (int i = 0; i <= line.length(); i++) {
            char c = i < line.length() ? line.charAt(i) : ';';
            if (c == '"') {
                quoted = !quoted;
            } else if (c == ';' && !quoted || i == line.length()) {
                String st = line.substring(from, Math.min(i, line.length())).strip();
                if (st.startsWith("'") || st.equals("REM") || st.startsWith("REM ") || st.equals("NO")
                        || st.startsWith("NO ")) {
                    return out;
                }
                if (!st.isEmpty()) {
                    out.add(st);
                }
                from = i + 1;
            }
        }
        return out;
    }
}
