package gcnc.tables;

import gcnc.diag.Code;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * The prose of {@code gcnc explain} (tables/explain/): for each code a program can meet, why it is
 * reported, what the control would do, a typical fix (one file per language, {@code en.md} and
 * {@code es.md}), and an example program that triggers it ({@code examples.md}, the same for both
 * languages: G-code has no language). Loaded only when asked for (explain, SARIF's rules), never
 * on a plain check. Markdown so that it reads well on GitHub as it is; the format is:
 *
 * <pre>
 * ## E037
 * cause: why gcnc reports it (one paragraph; may wrap onto lines that start with two spaces)
 * control: what the control does (optional: else tables/error_basis.csv's row, else the severity's)
 * fix: the usual fix
 * </pre>
 *
 * and in examples.md
 *
 * <pre>
 * ## E037
 * machine: haas          (optional; haas unless said)
 * control: fanuc-b       (optional: another control than the profile's own)
 * dialect: thesis        (optional; galil unless said)
 * after: start           (optional: the lines of "## start" go before it, unshown)
 *     G01 X20. Z-5. F0.2 (the example, indented four spaces)
 * </pre>
 *
 * Codes a program cannot meet (a broken table, a file the command line cannot write, the
 * simulator's checks on gcnc's own DMC) have no entry: {@link #INTERNAL} lists them and says why.
 */
public final class Explanations {
    /** One code's prose in one language. {@code control} is empty when the basis table or the severity says it. */
    public record Prose(String cause, String control, String fix) {
    }

    /**
     * A program that triggers a code: what is shown, what runs before it unshown, and where; or,
     * for a code no short program can bring about (10,000 errors, a file beside the program),
     * no lines and the reason in {@code none}.
     */
    public record Example(String machine, String control, String dialect, List<String> prelude, List<String> lines,
                          String none) {
        /** The whole program the example stands for, prelude and lines, one block a line. */
        public String program() {
            StringBuilder b = new StringBuilder();
            for (String s : prelude) {
                b.append(s).append('\n');
            }
            for (String s : lines) {
                b.append(s).append('\n');
            }
            return b.toString();
        }
    }

    /**
     * Codes no G-code program can bring about (no entry, no example), and why: they report a
     * broken table or profile, a file the command line cannot read or write, or an inconsistency
     * in the DMC gcnc itself wrote (the simulator checking the backend), or a DMC file given to
     * simulate. ExplainTest holds the list to the files.
     */
    public static final Map<Code, String> INTERNAL = internal();

    private static Map<Code, String> internal() {
        Map<Code, String> m = new EnumMap<>(Code.class);
        String table = "a broken table or machine profile (tables/, --tables, --machine FILE), not a program";
        range(m, 400, 500, table); // the tables' and profiles' range (docs/architecture.md)
        // E220-E239: the DMC gcnc writes held against the controller's own limits (gcnc.galil.LimitCheck);
        // docs/galil.md explains each, with the reference's page
        range(m, 220, 240, "the DMC gcnc writes held against the Galil model's limits (tables/galil_models.csv;"
                + " docs/galil.md, \"The controller's limits\")");
        // E243-E245: the stream form's own limits and its two files (docs/galil.md, "Two forms")
        each(m, "the form gcnc writes for a long program: its resident program and its stream (docs/galil.md,"
                + " \"Two forms\"), and the pair given to simulate", 243, 244, 245);
        m.put(Code.E253_ON_THE_FLY_NOT_OUTPUT, table);
        m.put(Code.E850_CYCLE_START_INPUT, table); // a profile's key (stop.cycle_start), numbered with the program stop's codes
        each(m, "the command line's files (reading, writing, links), not the program's text", 500, 501, 502, 510);
        each(m, "the simulator checking the DMC gcnc wrote (a gcnc bug, or a DMC file given to simulate)",
                300, 301, 308, 309, 310, 311, 312, 313, 314, 317, 318, 319, 331, 340, 332, 333, 334, 335, 336, 864);
        each(m, "the backend's or the simulator's guard behind a check that comes first for any program"
                + " (E015 the travel; E102 an arc off its circle)", 205, 206, 302);
        m.put(Code.byNumber(45), "the thesis's out-of-memory error: gcnc reports E116 at its cap instead");
        m.put(Code.byNumber(506), "the Java heap running out (an input gcnc failed to bound, or -Xmx set too small),"
                + " not the program's text");
        String link = "running a program on a controller (gcnc run, docs/run.md): the link and the controller,"
                + " not the program's text";
        // E815-E849: the link, the probe and the controller the profile names; E851: the link dropped during a run;
        // E890-E899: feeding a running sequence (the stream form's host or the program form's thread)
        range(m, 815, 850, link);
        range(m, 890, 900, link);
        m.put(Code.E851_LINK_DROPPED_RUNNING, link);
        m.put(Code.E865_PORT_NOT_A_DEVICE, link);
        range(m, 870, 880, "the test cut (gcnc offsets wear): its arguments, the wear limits and the offsets file,"
                + " not the program's text (docs/command-line.md)");
        return java.util.Collections.unmodifiableMap(m);
    }

    /** Every code numbered from {@code from} up to {@code to} (not included) is internal for {@code why}. */
    private static void range(Map<Code, String> m, int from, int to, String why) {
        for (Code c : Code.values()) {
            if (c.number() >= from && c.number() < to) {
                m.put(c, why);
            }
        }
    }

    /** The codes numbered {@code numbers} are internal for {@code why}. */
    private static void each(Map<Code, String> m, String why, int... numbers) {
        for (int n : numbers) {
            m.put(Code.byNumber(n), why);
        }
    }

    public static final String DIR = "explain/";

    private final Map<Code, Prose> english;
    private final Map<Code, Prose> spanish;
    private final Map<Code, Example> examples;

    private Explanations(Map<Code, Prose> english, Map<Code, Prose> spanish, Map<Code, Example> examples) {
        this.english = english;
        this.spanish = spanish;
        this.examples = examples;
    }

    public static Explanations load(TableSource source) throws TableException {
        return new Explanations(prose(source, "en.md"), prose(source, "es.md"), examples(source));
    }

    /** The built-in explanations (the jar's tables/explain/); a broken copy there is a bug of the build. */
    public static Explanations builtIn() {
        try {
            return load(TableSource.builtIn());
        } catch (TableException e) {
            throw new IllegalStateException("the explanations built into gcnc.jar are broken", e);
        }
    }

    public Optional<Prose> prose(Code code, ErrorMessages.Lang lang) {
        return Optional.ofNullable((lang == ErrorMessages.Lang.ES ? spanish : english).get(code));
    }

    public Optional<Example> example(Code code) {
        return Optional.ofNullable(examples.get(code));
    }

    public java.util.Set<Code> explained(ErrorMessages.Lang lang) {
        return (lang == ErrorMessages.Lang.ES ? spanish : english).keySet();
    }

    public java.util.Set<Code> exemplified() {
        return examples.keySet();
    }

    /** One {@code ## E037} section: its heading's line and its lines up to the next heading. */
    private record Section(Code code, int line, List<String> body) {
    }

    private static List<Section> sections(TableSource source, String name) throws TableException {
        String file = DIR + name;
        String[] lines = source.read(file).split("\n", -1);
        List<Section> out = new ArrayList<>();
        Section current = null;
        for (int i = 0; i < lines.length; i++) {
            String s = lines[i].stripTrailing();
            if (s.startsWith("## ")) {
                String id = s.substring(3).trim();
                Code code = null;
                if (!id.equals("start")) {
                    try {
                        code = Code.byNumber(Integer.parseInt(id.toUpperCase(Locale.ROOT).replaceFirst("^E", "")));
                    } catch (IllegalArgumentException e) {
                        throw Csv.fault(source.describe(file), i + 1, 4, gcnc.diag.Phrase.NO_SUCH_CODE.with(id));
                    }
                }
                current = new Section(code, i + 1, new ArrayList<>());
                out.add(current);
            } else if (current != null) {
                current.body().add(s);
            }
        }
        return out;
    }

    private static Map<Code, Prose> prose(TableSource source, String name) throws TableException {
        Map<Code, Prose> m = new EnumMap<>(Code.class);
        for (Section s : sections(source, name)) {
            Map<String, String> fields = fields(s.body());
            String cause = fields.getOrDefault("cause", "");
            String fix = fields.getOrDefault("fix", "");
            if (s.code() == null || cause.isEmpty() || fix.isEmpty()) {
                throw Csv.fault(source.describe(DIR + name), s.line(), 1,
                        gcnc.diag.Phrase.CSV_MISSING_VALUE.with(cause.isEmpty() ? "cause" : "fix"));
            }
            m.put(s.code(), new Prose(cause, fields.getOrDefault("control", ""), fix));
        }
        return m;
    }

    /** {@code key: text} lines; a line that starts with two spaces goes on with the field before it. */
    private static Map<String, String> fields(List<String> body) {
        Map<String, String> f = new java.util.LinkedHashMap<>();
        String key = null;
        for (String s : body) {
            int colon = s.indexOf(':');
            if (s.startsWith("  ") && key != null) {
                f.put(key, f.get(key) + " " + s.strip());
            } else if (colon > 0 && !s.startsWith(" ")) {
                key = s.substring(0, colon).strip();
                f.put(key, s.substring(colon + 1).strip());
            }
        }
        return f;
    }

    private static Map<Code, Example> examples(TableSource source) throws TableException {
        List<Section> sections = sections(source, "examples.md");
        List<String> start = List.of();
        Map<Code, Example> m = new EnumMap<>(Code.class);
        for (Section s : sections) {
            String machine = "haas";
            String dialect = "galil";
            String control = "";
            String none = "";
            boolean after = false;
            List<String> lines = new ArrayList<>();
            for (String line : s.body()) {
                if (line.startsWith("    ")) {
                    lines.add(line.substring(4));
                } else if (line.startsWith("machine:")) {
                    machine = line.substring(8).strip();
                } else if (line.startsWith("control:")) {
                    control = line.substring(8).strip();
                } else if (line.startsWith("dialect:")) {
                    dialect = line.substring(8).strip();
                } else if (line.startsWith("none:")) {
                    none = line.substring(5).strip();
                } else if (line.startsWith("after:")) {
                    after = true; // the one prelude there is: "## start"
                }
            }
            if (s.code() == null) {
                start = List.copyOf(lines);
            } else {
                m.put(s.code(), new Example(machine, control, dialect, after ? start : List.of(), List.copyOf(lines), none));
            }
        }
        return m;
    }
}
