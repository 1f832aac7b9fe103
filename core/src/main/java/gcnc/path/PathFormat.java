package gcnc.path;

import com.google.gson.stream.JsonWriter;
import java.util.List;

/**
 * How gcnc path writes its moves (docs/path.md, a stable format: a column is only ever added at
 * the end, and a change raises {@link #VERSION}): CSV with a header row of {@link PathMove#COLUMNS},
 * RFC 4180 quoting where a field needs it; or JSON Lines, one object per move with the same names
 * (a number bare, an empty value null), streamable and diffable line by line.
 *
 * <p>JSON through Gson's writer (core's JSON library). No CSV library: every field is a number, a
 * fixed word, a block name or a file name, and the one rule that can apply (a field holding a
 * comma, a quote or a line end is quoted, its quotes doubled) is the few lines of
 * {@link #csvField}; commons-csv would add a jar for that.
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
        if (this == CSV) {
            StringBuilder b = new StringBuilder(160);
            for (int i = 0; i < values.size(); i++) {
                if (i > 0) {
                    b.append(',');
                }
                b.append(csvField(values.get(i)));
            }
            return b.toString();
        }
        java.io.StringWriter text = new java.io.StringWriter(160);
        try (JsonWriter w = new JsonWriter(text)) {
            w.beginObject();
            for (int i = 0; i < values.size(); i++) {
                w.name(PathMove.COLUMNS.get(i));
                String v = values.get(i);
                if (v.isEmpty()) {
                    w.nullValue();
                } else if (PathMove.numeric(i)) {
                    w.jsonValue(v); // written by PathMove as a JSON number already
                } else {
                    w.value(v);
                }
            }
            w.endObject();
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e); // a StringWriter does not fail
        }
        return text.toString();
    }

    /** A CSV field (RFC 4180): quoted, its quotes doubled, when it holds a comma, a quote or a line end. */
    static String csvField(String v) {
        if (v.indexOf(',') < 0 && v.indexOf('"') < 0 && v.indexOf('\n') < 0 && v.indexOf('\r') < 0) {
            return v;
        }
        return '"' + v.replace("\"", "\"\"") + '"';
    }
}
