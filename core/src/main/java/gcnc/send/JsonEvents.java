package gcnc.send;

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

    /** One event as a JSON object on one line. */
    public static String json(Event e) {
        StringBuilder b = new StringBuilder("{\"event\":\"").append(kebab(e.getClass().getSimpleName())).append('"');
        for (RecordComponent c : e.getClass().getRecordComponents()) {
            Object v;
            try {
                v = c.getAccessor().invoke(e);
            } catch (ReflectiveOperationException x) {
                throw new IllegalStateException(x);
            }
            b.append(",\"").append(c.getName()).append("\":");
            value(b, v);
        }
        return b.append('}').toString();
    }

    private static void value(StringBuilder b, Object v) {
        if (v == null) {
            b.append("null");
        } else if (v instanceof Double d) {
            number(b, d);
        } else if (v instanceof Number || v instanceof Boolean) {
            b.append(v);
        } else if (v instanceof double[] a) {
            b.append('[');
            for (int i = 0; i < a.length; i++) {
                if (i > 0) {
                    b.append(',');
                }
                number(b, a[i]);
            }
            b.append(']');
        } else {
            string(b, v.toString());
        }
    }

    private static void number(StringBuilder b, double d) {
        if (Double.isNaN(d) || Double.isInfinite(d)) {
            b.append("null");
        } else if (d == Math.rint(d) && Math.abs(d) < 1e15) {
            b.append((long) d);
        } else {
            b.append(String.format(Locale.ROOT, "%.4f", d).replaceAll("0+$", ""));
        }
    }

    private static void string(StringBuilder b, String s) {
        b.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> {
                    if (c < 0x20) {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        b.append('"');
    }

    static String kebab(String name) {
        return name.replaceAll("([a-z])([A-Z])", "$1-$2").toLowerCase(Locale.ROOT);
    }
}
