package gcnc.path;

import java.util.List;

/**
 * How gcnc path writes its moves (docs/path.md, a stable format: a column is only ever added at
 * the end, and a change raises {@link #VERSION}): CSV with a header row of {@link PathMove#COLUMNS},
 * RFC 4180 quoting where a field needs it; or JSON Lines, one object per move with the same names
 * (a number bare, an empty value null), streamable and diffable line by line.
 *
 * <p>No CSV library: every field is a number, a fixed word, a block name or a file name, and the
 * one rule that can apply (a field holding a comma, a quote or a line end is quoted, its quotes
 * doubled) is the few lines of {@link #csvField}; commons-csv would add a jar for that.
 */
public enum PathFormat {
    CSV, JSON;

    /** The layout's version, as docs/path.md names it (not written in the output: the header and the names say it). */
    public static final int VERSION = 1;

    /** The first line: the CSV header; none for JSON Lines (each object names its fields). */
    public String header() {
        return this == CSV ? String.join(",", PathMove.COLUMNS) : null;
    }

    /** One move as one line, without its line end. */
    public String line(PathMove m) {
        List<String> values = m.values();
        StringBuilder b = new StringBuilder(160);
        if (this == CSV) {
            for (int i = 0; i < values.size(); i++) {
                if (i > 0) {
                    b.append(',');
                }
                b.append(csvField(values.get(i)));
            }
            return b.toString();
        }
        b.append('{');
        for (int i = 0; i < values.size(); i++) {
            if (i > 0) {
                b.append(',');
            }
            b.append('"').append(PathMove.COLUMNS.get(i)).append("\":");
            String v = values.get(i);
            if (v.isEmpty()) {
                b.append("null");
            } else if (PathMove.numeric(i)) {
                b.append(v);
            } else {
                jsonString(v, b);
            }
        }
        return b.append('}').toString();
    }

    /** A CSV field (RFC 4180): quoted, its quotes doubled, when it holds a comma, a quote or a line end. */
    static String csvField(String v) {
        if (v.indexOf(',') < 0 && v.indexOf('"') < 0 && v.indexOf('\n') < 0 && v.indexOf('\r') < 0) {
            return v;
        }
        return '"' + v.replace("\"", "\"\"") + '"';
    }

    private static void jsonString(String v, StringBuilder b) {
        b.append('"');
        for (int i = 0; i < v.length(); i++) {
            char c = v.charAt(i);
            if (c == '"' || c == '\\') {
                b.append('\\').append(c);
            } else if (c < 0x20) {
                b.append(String.format("\\u%04x", (int) c));
            } else {
                b.append(c);
            }
        }
        b.append('"');
    }
}
