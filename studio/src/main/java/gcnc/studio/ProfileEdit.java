package gcnc.studio;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import gcnc.Session;
import gcnc.diag.Messages;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.machine.Units;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Pattern;

/**
 * Configure: the machine profile's travel, work offsets, tool offsets and tool geometry as form
 * fields, and a profile edited from them. An edit is made on the profile's own text (each key's
 * value replaced on its line, its comment kept; a new key added at the end; an emptied key taken
 * out) and read by {@link ProfileLoader}, so it is refused for exactly what the loader refuses, at
 * the key where the loader puts the fault. Nothing here writes: {@link Api} saves the text.
 */
final class ProfileEdit {
    /** A key the form does not show, or a value the loader refuses: the key (null: the profile as a whole) and why. */
    static final class Invalid extends Exception {
        private final String key;

        Invalid(String key, String message) {
            super(message, null, false, false);
            this.key = key;
        }

        String key() {
            return key;
        }
    }

    /** The keys the form edits: travel, work offsets, tool offsets, nose radius and tip, the tool's outline. */
    private static final Pattern EDITABLE = Pattern.compile(
            "[xz]\\.travel|work\\.G5[4-9]|tool\\.[0-9]{1,2}|nose\\.[0-9]{1,2}|sim\\.tool\\.(default|[0-9]{1,2})");
    /** A value is one line of text: no line break, no comment mark (it would end the value), bounded. */
    private static final Pattern VALUE = Pattern.compile("[^\\r\\n#\\x00]{0,200}");

    private final Session session;
    /** Where the profile came from, and its text as written. */
    private final String source;
    private final String text;
    private final Messages messages;

    private ProfileEdit(Session session, String source, String text, Messages messages) {
        this.session = session;
        this.source = source;
        this.text = text;
        this.messages = messages;
    }

    /** The profile the session was opened with (a shipped name or a .machine file), as written. */
    static ProfileEdit of(Session session, Messages messages) throws IOException {
        String machine = session.options().machine();
        if (gcnc.machine.ProfileLoader.isPath(machine)) {
            Path p = Path.of(machine);
            return new ProfileEdit(session, p.toString(), Files.readString(p, StandardCharsets.UTF_8), messages);
        }
        TableSource tables = tables(session);
        String name = "machines/" + machine + ".machine";
        try {
            return new ProfileEdit(session, tables.describe(name), tables.read(name), messages);
        } catch (TableException e) {
            throw new IOException(e.getMessage(), e);
        }
    }

    /** The same, for a profile just saved as {@code file}: its text is the one edited from now on. */
    static ProfileEdit saved(Session session, Path file, String text, Messages messages) {
        return new ProfileEdit(session, file.toString(), text, messages);
    }

    private static TableSource tables(Session session) {
        return session.options().tables().map(TableSource::directory).orElse(TableSource.builtIn());
    }

    String text() {
        return text;
    }

    /**
     * {@code GET /api/profile}: the form. Each field is a key with its values as written (empty
     * when the file does not give it) and, as the placeholder, what is in force without it; beside
     * them, both in the terms of a program in {@code units} ({@link ProfileTerms}: {@code program},
     * {@code programPlaceholder}), which is what the page shows and edits.
     */
    JsonObject form(Units units) throws Invalid {
        MachineProfile p = session.profile();
        ProfileFile f = parse(text);
        boolean counts = f.entry("offsets.unit").map(e -> e.value().equals("counts")).orElse(false);
        ProfileTerms terms = ProfileTerms.of(p, f, units);
        JsonObject o = new JsonObject();
        o.addProperty("machine", p.name());
        o.addProperty("source", source);
        o.addProperty("offsetsUnit", counts ? "counts" : "mm");
        o.addProperty("units", terms.unit());
        o.addProperty("diameter", terms.diameter());
        o.addProperty("tools", p.tools());
        JsonArray travel = new JsonArray();
        travel.add(field(f, terms, "x.travel", mm(p.x().min() / p.x().countsPerMm(), p.x().max() / p.x().countsPerMm())));
        travel.add(field(f, terms, "z.travel", mm(p.z().min() / p.z().countsPerMm(), p.z().max() / p.z().countsPerMm())));
        o.add("travel", travel);
        JsonArray work = new JsonArray();
        for (int g = 54; g <= 59; g++) {
            work.add(field(f, terms, "work.G" + g, offset(p.workOffset(g), counts, p)));
        }
        o.add("work", work);
        JsonArray tools = new JsonArray();
        JsonArray geometry = new JsonArray();
        geometry.add(field(f, terms, "sim.tool.default", ""));
        for (int n = 1; n <= p.tools(); n++) {
            tools.add(field(f, terms, "tool." + n, offset(p.toolOffset(n), counts, p)));
            geometry.add(field(f, terms, "nose." + n, ""));
            geometry.add(field(f, terms, "sim.tool." + n, ""));
        }
        o.add("toolOffsets", tools);
        o.add("geometry", geometry);
        return o;
    }

    private static JsonObject field(ProfileFile f, ProfileTerms terms, String key, String inForce) {
        JsonObject o = new JsonObject();
        String value = f.entry(key).map(ProfileFile.Entry::value).orElse("");
        o.addProperty("key", key);
        o.addProperty("value", value);
        o.addProperty("placeholder", inForce);
        if (ProfileTerms.converted(key)) {
            o.addProperty("program", terms.shown(key, value));
            o.addProperty("programPlaceholder", terms.shown(key, inForce));
        }
        return o;
    }

    /** The units a request names ({@code "units": "in"|"mm"}), else those the profile powers up in. */
    Units units(String named) throws Http.Fail {
        if (named == null) {
            return session.profile().units();
        }
        return switch (named) {
            case "in" -> Units.INCH;
            case "mm" -> Units.MM;
            default -> throw new Http.Fail(400, "\"units\" is in or mm");
        };
    }

    /**
     * The edits of a request in the file's terms: its {@code values} as they are, and its
     * {@code program} values (the form's fields in the terms of a program in {@code units})
     * converted by {@link ProfileTerms}, each part shown unchanged keeping the file's text.
     */
    Map<String, String> edits(JsonObject req) throws Http.Fail, Invalid {
        Map<String, String> out = values(req);
        JsonElement program = req.get("program");
        if (program == null) {
            return out;
        }
        if (!program.isJsonObject()) {
            throw new Http.Fail(400, "\"program\" is an object of profile keys and their values in the program's terms");
        }
        JsonObject wrapped = new JsonObject();
        wrapped.add("values", program);
        Map<String, String> typed = values(wrapped);
        ProfileFile f = parse(text);
        ProfileTerms terms = ProfileTerms.of(session.profile(), f, units(Http.string(req, "units")));
        for (Map.Entry<String, String> e : typed.entrySet()) {
            out.put(e.getKey(), terms.toFile(e.getKey(), e.getValue(), f.entry(e.getKey()).map(ProfileFile.Entry::value).orElse("")));
        }
        return out;
    }

    private static String offset(Optional<Point> counts, boolean inCounts, MachineProfile p) {
        Point c = counts.orElse(Point.ORIGIN);
        return inCounts ? ProfileFile.written(c.x()) + ", " + ProfileFile.written(c.z())
                : mm(c.x() / p.x().countsPerMm(), c.z() / p.z().countsPerMm());
    }

    private static String mm(double a, double b) {
        return ProfileFile.written(Math.round(a * 1e6) / 1e6) + ", " + ProfileFile.written(Math.round(b * 1e6) / 1e6);
    }

    /** The edits of a request ({@code {"values": {"x.travel": "-100, 0", ...}}}), refused when a key is not the form's. */
    static Map<String, String> values(JsonObject req) throws Http.Fail {
        JsonElement v = req.get("values");
        if (v == null || !v.isJsonObject()) {
            throw new Http.Fail(400, "the request needs \"values\": an object of profile keys and their values");
        }
        Map<String, String> out = new LinkedHashMap<>();
        for (Map.Entry<String, JsonElement> e : v.getAsJsonObject().entrySet()) {
            if (!EDITABLE.matcher(e.getKey()).matches()) {
                throw new Http.Fail(400, "Configure does not edit \"" + Workspace.shown(e.getKey()) + "\"");
            }
            if (!e.getValue().isJsonPrimitive() || !e.getValue().getAsJsonPrimitive().isString()
                    || !VALUE.matcher(e.getValue().getAsString()).matches()) {
                throw new Http.Fail(400, "the value of " + e.getKey() + " must be one line of text without '#'");
            }
            out.put(e.getKey(), e.getValue().getAsString().strip());
        }
        return out;
    }

    /** The profile's text with the edits: values replaced where they stand, new keys at the end, emptied ones taken out. */
    String edited(Map<String, String> values) {
        Map<String, String> left = new LinkedHashMap<>(values);
        List<String> out = new ArrayList<>();
        for (String line : text.split("\r?\n", -1)) {
            int hash = line.indexOf('#');
            String body = hash >= 0 ? line.substring(0, hash) : line;
            int eq = body.indexOf('=');
            String key = eq < 0 ? null : body.substring(0, eq).trim();
            if (key == null || !left.containsKey(key)) {
                out.add(line);
                continue;
            }
            String value = left.remove(key);
            if (value.isEmpty()) {
                continue; // the key taken out: the loader's default (or the tool table) again
            }
            String comment = hash >= 0 ? "  " + line.substring(hash) : "";
            out.add(body.substring(0, eq + 1) + " " + value + comment);
        }
        while (!out.isEmpty() && out.get(out.size() - 1).isEmpty()) {
            out.remove(out.size() - 1);
        }
        boolean first = true;
        for (Map.Entry<String, String> e : left.entrySet()) {
            if (e.getValue().isEmpty()) {
                continue;
            }
            if (first) {
                out.add("");
                out.add("# set in gcnc studio's Configure");
                first = false;
            }
            out.add(e.getKey() + " = " + e.getValue());
        }
        return String.join("\n", out) + "\n";
    }

    /**
     * The profile an edited text makes, read as {@link ProfileLoader} reads any profile (its
     * control from the session's --control, else its own key; among the session's tables).
     */
    MachineProfile load(String edited) throws Invalid {
        ProfileFile f = parse(edited);
        try {
            return ProfileLoader.read(f, session.tables(), tables(session), session.options().control().orElse(null));
        } catch (TableException e) {
            throw invalid(f, e);
        }
    }

    private ProfileFile parse(String t) throws Invalid {
        try {
            return ProfileFile.parse(source, t);
        } catch (TableException e) {
            throw new Invalid(null, say(e));
        }
    }

    /** The loader's fault, at the key on its line (null when it is not on a key's line). */
    private Invalid invalid(ProfileFile f, TableException e) {
        int line = e.diagnostic().span().line();
        String key = null;
        for (String k : f.keys()) {
            if (f.entry(k).orElseThrow().line() == line) {
                key = k;
            }
        }
        return new Invalid(key, say(e));
    }

    private String say(TableException e) {
        return messages.render(e.diagnostic().code(), e.diagnostic().args());
    }
}
