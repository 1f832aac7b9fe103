package gcnc.send;

import com.google.gson.stream.JsonWriter;
import java.io.PrintWriter;
import java.lang.reflect.RecordComponent;
import java.util.Locale;

/**
 * The JSON event stream: one object per line, {@code {"event":"status","dmcLine":12,...}}, each
 * {@link Event} record's components as fields in declaration order (docs/run.md lists them).
 * Numbers that are not known (NaN) are {@code null}; arrays of numbers are JSON arrays.
 */
public final class JsonEvents implements EventSink {
    private final PrintWriter out;

    public JsonEvents(PrintWriter out) {
        this.out = out;
    }

    @Override
    public synchronized void accept(Event e) {
        out.println(json(e));
        out.flush();
    }

    /** One event as a JSON object on one line (Gson's writer: its string escapes, gcnc's numbers). */
    public static String json(Event e) {
        java.io.StringWriter text = new java.io.StringWriter();
        try (JsonWriter w = new JsonWriter(text)) {
            w.beginObject().name("event").value(kebab(e.getClass().getSimpleName()));
            for (RecordComponent c : e.getClass().getRecordComponents()) {
                w.name(c.getName());
                value(w, accessor(c, e));
            }
            w.endObject();
        } catch (java.io.IOException x) {
            throw new java.io.UncheckedIOException(x); // a StringWriter does not fail
        }
        return text.toString();
    }

    private static Object accessor(RecordComponent c, Event e) {
        try {
            return c.getAccessor().invoke(e);
        } catch (ReflectiveOperationException x) {
            throw new IllegalStateException(x);
        }
    }

    private static void value(JsonWriter w, Object v) throws java.io.IOException {
        if (v == null) {
            w.nullValue();
        } else if (v instanceof Double d) {
            number(w, d);
        } else if (v instanceof Number n) {
            w.value(n);
        } else if (v instanceof Boolean b) {
            w.value(b);
        } else if (v instanceof double[] a) {
            w.beginArray();
            for (double d : a) {
                number(w, d);
            }
            w.endArray();
        } else {
            w.value(v.toString());
        }
    }

    /** Not known (NaN, infinite) is null; a whole number without a point; else at most four decimals. */
    private static void number(JsonWriter w, double d) throws java.io.IOException {
        if (Double.isNaN(d) || Double.isInfinite(d)) {
            w.nullValue();
        } else if (d == Math.rint(d) && Math.abs(d) < 1e15) {
            w.value((long) d);
        } else {
            w.jsonValue(String.format(Locale.ROOT, "%.4f", d).replaceAll("0+$", ""));
        }
    }

    static String kebab(String name) {
        return name.replaceAll("([a-z])([A-Z])", "$1-$2").toLowerCase(Locale.ROOT);
    }
}
