package gcnc.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The program lines a GNU report shows under its findings, GCC-style: the line as written, then a
 * caret under the finding's column. Read from a regular file when the first finding in it is
 * reported (the compile has read it already: this is only for the person reading the report); a
 * program from standard input or a pipe, or a file too large to keep, shows no lines.
 */
final class SourceLines {
    /** Files larger than this show no source lines (their lines would be held in memory). */
    private static final long MAX_BYTES = 8L << 20;

    private final Map<String, List<String>> files = new HashMap<>();

    /** Line {@code n} (1-based) of the file, or null when it cannot be shown. */
    String line(String path, int n) {
        List<String> lines = files.computeIfAbsent(path, SourceLines::read);
        return n >= 1 && n <= lines.size() ? lines.get(n - 1) : null;
    }

    private static List<String> read(String path) {
        Path p = Path.of(path);
        try {
            if (!Files.isRegularFile(p) || Files.size(p) > MAX_BYTES) {
                return List.of();
            }
            List<String> lines = new ArrayList<>();
            try (BufferedReader r = Files.newBufferedReader(p, StandardCharsets.UTF_8)) {
                for (String l = r.readLine(); l != null; l = r.readLine()) {
                    lines.add(l);
                }
            }
            return lines;
        } catch (IOException | RuntimeException e) {
            return List.of(); // not readable again (or not UTF-8): the finding stands without its line
        }
    }

    /**
     * The line, indented by a space as GCC does, and under it a caret at the span's column (1-based,
     * in characters as the parser counts them) and tildes under the rest of its text where its end is
     * known ({@code ^~~~} under {@code X10.}); tabs before the column are kept, and a control
     * character shown escaped is counted as wide as it is shown, so the caret lines up.
     */
    static String withCaret(String line, gcnc.diag.Span span) {
        int column = span.column();
        int start = Math.min(column - 1, line.length());
        String before = Printable.escape(line.substring(0, start));
        String marks = "^";
        if (span.hasEnd() && span.endColumn() - 1 <= line.length() && span.endColumn() - 1 > start + 1) {
            marks += Printable.escape(line.substring(start + 1, span.endColumn() - 1)).replaceAll(".", "~");
        }
        return " " + Printable.escape(line) + "\n " + before.replaceAll("[^\t]", " ") + marks;
    }
}
