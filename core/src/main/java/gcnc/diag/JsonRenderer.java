package gcnc.diag;

import com.google.gson.stream.JsonWriter;
import java.io.IOException;
import java.io.Writer;
import java.util.List;

/**
 * gcnc's own JSON report: one document for a run, every finding with its file, line, column,
 * severity, code, rendered message and the arguments of the message as it shows them (and, for a
 * finding a shop's waiver accepts, {@code "waived"}: the waiver's reason). The schema is
 * documented in docs/command-line.md ("JSON report") and versioned by {@link #VERSION}: a field
 * is only ever added, and removing or changing one raises the version.
 */
public final class JsonRenderer {
    /** The version of the document's layout, written as "version". */
    public static final int VERSION = 1;

    private JsonRenderer() {
    }

    /**
     * More of the document after the diagnostics, written by a front end that knows more than
     * findings (the command line's {@code "simulations"}: gcnc.diag cannot know the simulator).
     */
    @FunctionalInterface
    public interface Section {
        void write(JsonWriter json) throws IOException;
    }

    public static void write(List<Finding> findings, String toolVersion, Writer out) throws IOException {
        write(findings, toolVersion, out, json -> { });
    }

    public static void write(List<Finding> findings, String toolVersion, Writer out, Section more) throws IOException {
        JsonWriter json = new JsonWriter(out);
        json.setIndent("  ");
        json.beginObject();
        json.name("format").value("gcnc-diagnostics");
        json.name("version").value(VERSION);
        json.name("tool").beginObject().name("name").value("gcnc").name("version").value(toolVersion).endObject();
        json.name("errors").value(count(findings, Severity.ERROR));
        json.name("warnings").value(count(findings, Severity.WARNING));
        json.name("waived").value(findings.stream().filter(f -> f.diagnostic().waived()).count());
        json.name("diagnostics").beginArray();
        for (Finding f : findings) {
            Diagnostic d = f.diagnostic();
            json.beginObject();
            json.name("file").value(f.file());
            json.name("line").value(d.span().line());
            json.name("column").value(d.span().column());
            if (d.span().hasEnd()) {
                json.name("endColumn").value(d.span().endColumn());
            }
            json.name("severity").value(d.severity().label());
            json.name("code").value(d.code().id());
            json.name("message").value(f.message());
            if (d.waived()) {
                json.name("waived").value(d.waiver());
            }
            json.name("arguments").beginArray();
            for (String a : f.arguments()) {
                json.value(a);
            }
            json.endArray();
            json.endObject();
        }
        json.endArray();
        more.write(json);
        json.endObject();
        json.flush();
        out.write('\n');
        out.flush();
    }

    /** Findings of severity {@code s} that no waiver accepts (a waived one is counted apart, "waived"). */
    static long count(List<Finding> findings, Severity s) {
        return findings.stream().filter(f -> f.diagnostic().severity() == s && !f.diagnostic().waived()).count();
    }
}
