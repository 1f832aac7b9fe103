package gcnc.diag;

import com.google.gson.stream.JsonWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A run's findings as SARIF 2.1.0, the format GitHub code scanning and GitLab read to annotate a
 * pull request: one run, gcnc as {@code tool.driver} with one rule per diagnostic code, and one
 * result per finding with its rule, level, message and place (file and 1-based line and column);
 * a finding a shop's waiver accepts keeps its level and has a {@code suppressions} entry of kind
 * {@code inSource} with the waiver's reason as its justification.
 * Columns count UTF-16 code units, as gcnc's do (SARIF's default column kind).
 */
public final class SarifRenderer {
    /**
     * A diagnostic code as SARIF describes it: its default severity, the text of its message, and
     * from gcnc explain's prose (tables/explain/) why it is reported ({@code fullDescription}) and
     * the usual fix with an example ({@code help}, plain and Markdown); empty where there is none.
     */
    public record Rule(Code code, Severity severity, String text, String fullDescription, String help,
                       String helpMarkdown) {
        public Rule(Code code, Severity severity, String text) {
            this(code, severity, text, "", "", "");
        }
    }

    static final String SCHEMA = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json";

    private SarifRenderer() {
    }

    public static void write(List<Finding> findings, List<Rule> rules, String toolVersion, Writer out) throws IOException {
        JsonWriter json = new JsonWriter(out);
        json.setIndent("  ");
        json.beginObject();
        json.name("$schema").value(SCHEMA);
        json.name("version").value("2.1.0");
        json.name("runs").beginArray().beginObject();
        Map<Code, Integer> index = driver(json, rules, toolVersion);
        json.name("columnKind").value("utf16CodeUnits");
        json.name("results").beginArray();
        for (Finding f : findings) {
            result(json, f, index);
        }
        json.endArray();
        json.endObject().endArray();
        json.endObject();
        json.flush();
        out.write('\n');
        out.flush();
    }

    private static Map<Code, Integer> driver(JsonWriter json, List<Rule> rules, String toolVersion) throws IOException {
        Map<Code, Integer> index = new HashMap<>();
        json.name("tool").beginObject().name("driver").beginObject();
        json.name("name").value("gcnc");
        json.name("version").value(toolVersion);
        json.name("rules").beginArray();
        for (Rule r : rules) {
            index.put(r.code(), index.size());
            json.beginObject();
            json.name("id").value(r.code().id());
            json.name("name").value(name(r.code()));
            json.name("shortDescription").beginObject()
                    .name("text").value(r.text().replaceAll("\\{[0-9]+\\}", "…")).endObject();
            if (!r.fullDescription().isEmpty()) {
                json.name("fullDescription").beginObject().name("text").value(r.fullDescription()).endObject();
            }
            json.name("defaultConfiguration").beginObject().name("level").value(level(r.severity())).endObject();
            if (!r.help().isEmpty()) {
                json.name("help").beginObject().name("text").value(r.help())
                        .name("markdown").value(r.helpMarkdown()).endObject();
            }
            json.endObject();
        }
        json.endArray();
        json.endObject().endObject();
        return index;
    }

    private static void result(JsonWriter json, Finding f, Map<Code, Integer> index) throws IOException {
        Diagnostic d = f.diagnostic();
        json.beginObject();
        json.name("ruleId").value(d.code().id());
        Integer i = index.get(d.code());
        if (i != null) {
            json.name("ruleIndex").value(i);
        }
        json.name("level").value(level(d.severity()));
        // SARIF message strings treat braces as placeholders: literal ones are doubled (§3.11.5).
        json.name("message").beginObject()
                .name("text").value(f.message().replace("{", "{{").replace("}", "}}")).endObject();
        json.name("locations").beginArray().beginObject().name("physicalLocation").beginObject();
        json.name("artifactLocation").beginObject();
        String file = f.file().replace('\\', '/');
        if (file.startsWith("/")) {
            json.name("uri").value("file://" + encode(file));
        } else {
            while (file.startsWith("./")) {
                file = file.substring(2);
            }
            json.name("uri").value(encode(file));
            json.name("uriBaseId").value("%SRCROOT%");
        }
        json.endObject();
        json.name("region").beginObject()
                .name("startLine").value(d.span().line())
                .name("startColumn").value(d.span().column());
        if (d.span().hasEnd()) {
            json.name("endColumn").value(d.span().endColumn());
        }
        json.endObject();
        json.endObject().endObject().endArray();
        if (d.waived()) {
            // a shop's waiver in the program's own text: SARIF 2.1.0 §3.35, a suppression of kind inSource
            json.name("suppressions").beginArray().beginObject()
                    .name("kind").value("inSource")
                    .name("status").value("accepted")
                    .name("justification").value(d.waiver())
                    .endObject().endArray();
        }
        json.endObject();
    }

    static String level(Severity s) {
        return switch (s) {
            case ERROR -> "error";
            case WARNING -> "warning";
            case NOTE -> "note";
        };
    }

    /** E037_SPINDLE_DIRECTION -> SpindleDirection: SARIF's rule name is an identifier without the number. */
    static String name(Code code) {
        String[] words = code.name().split("_");
        StringBuilder b = new StringBuilder();
        for (int i = 1; i < words.length; i++) {
            b.append(words[i].charAt(0)).append(words[i].substring(1).toLowerCase(Locale.ROOT));
        }
        return b.length() == 0 ? code.id() : b.toString();
    }

    /** A path as a URI reference: every byte outside RFC 3986's unreserved set (and '/') percent-encoded. */
    static String encode(String path) {
        StringBuilder b = new StringBuilder();
        for (byte x : path.getBytes(StandardCharsets.UTF_8)) {
            int c = x & 0xff;
            if (c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z' || c >= '0' && c <= '9' || "-._~/".indexOf(c) >= 0) {
                b.append((char) c);
            } else {
                b.append('%').append(String.format("%02X", c));
            }
        }
        return b.toString();
    }
}
