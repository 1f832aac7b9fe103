package gcnc.tables;

import java.util.Collections;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;

/**
 * The thesis's tables 3-9 as typed, immutable views, loaded once per run from tables/
 * (inside the jar, or a directory given with --tables). Nothing outside this package parses them.
 */
public final class Tables {
    /** The parameter letters of Table 7, in the thesis's check order (errors 21-27, 36). */
    public enum Param { X, Z, U, W, I, K, R, P }

    private final Map<Integer, GFunction> g;
    private final Map<Integer, MFunction> m;
    private final Map<Character, ParameterLimit> limits;
    private final Map<Integer, Set<Param>> usage;
    private final List<Offset> toolOffsets;
    private final List<Offset> workOffsets;
    private final ErrorMessages messages;

    private Tables(Map<Integer, GFunction> g, Map<Integer, MFunction> m, Map<Character, ParameterLimit> limits,
                   Map<Integer, Set<Param>> usage, List<Offset> toolOffsets, List<Offset> workOffsets,
                   ErrorMessages messages) {
        this.g = Collections.unmodifiableMap(g);
        this.m = Collections.unmodifiableMap(m);
        this.limits = Collections.unmodifiableMap(limits);
        this.usage = Collections.unmodifiableMap(usage);
        this.toolOffsets = List.copyOf(toolOffsets);
        this.workOffsets = List.copyOf(workOffsets);
        this.messages = messages;
    }

    /** The tables shipped inside gcnc.jar. */
    public static Tables builtIn() {
        try {
            return load(TableSource.builtIn());
        } catch (TableException e) {
            throw new IllegalStateException("the tables built into gcnc.jar are broken: " + e.getMessage(), e);
        }
    }

    public static Tables load(TableSource src) throws TableException {
        Map<Integer, GFunction> g = new TreeMap<>();
        for (Csv.Row r : csv(src, "g_codes.csv").rows()) {
            g.put(r.integer("code"), new GFunction(r.integer("code"), r.integer("group"), r.get("en"), r.get("es")));
        }
        Map<Integer, MFunction> m = new TreeMap<>();
        for (Csv.Row r : csv(src, "m_codes.csv").rows()) {
            int moment = r.integer("moment");
            if (moment != 0 && moment != 1 && moment != 99) {
                throw r.faultAt("moment", "moment must be 0, 1 or 99, not " + moment);
            }
            m.put(r.integer("code"), new MFunction(r.integer("code"), r.integer("group"), moment, r.get("en"), r.get("es")));
        }
        Map<Character, ParameterLimit> limits = new HashMap<>();
        for (Csv.Row r : csv(src, "parameter_limits.csv").rows()) {
            String w = r.get("word");
            if (w.length() != 1) {
                throw r.faultAt("word", "word must be one letter, not '" + w + "'");
            }
            ParameterLimit l = new ParameterLimit(w.charAt(0), r.get("sign").equals("P"), r.get("type").equals("E"),
                    r.decimal("lower"), r.decimal("upper"));
            if (l.lower() > l.upper()) {
                throw r.faultAt("lower", "lower limit above upper limit");
            }
            limits.put(l.word(), l);
        }
        Map<Integer, Set<Param>> usage = new TreeMap<>();
        for (Csv.Row r : csv(src, "word_usage.csv").rows()) {
            Set<Param> allowed = EnumSet.noneOf(Param.class);
            for (Param p : Param.values()) {
                if (r.integer(p.name()) == 1) {
                    allowed.add(p);
                }
            }
            usage.put(r.integer("function"), Collections.unmodifiableSet(allowed));
        }
        return new Tables(g, m, limits, usage, offsets(src, "tool_offsets.csv"), offsets(src, "work_offsets.csv"),
                ErrorMessages.load(csv(src, "errors.csv")));
    }

    private static List<Offset> offsets(TableSource src, String name) throws TableException {
        List<Offset> list = new java.util.ArrayList<>();
        for (Csv.Row r : csv(src, name).rows()) {
            if (r.integer("offset") != list.size() + 1) {
                throw r.faultAt("offset", "offsets must be numbered 1, 2, 3... in order");
            }
            list.add(new Offset(r.decimal("x"), r.decimal("z")));
        }
        return list;
    }

    private static Csv csv(TableSource src, String name) throws TableException {
        return Csv.parse(src.describe(name), src.read(name));
    }

    public Optional<GFunction> g(int code) {
        return Optional.ofNullable(g.get(code));
    }

    public Optional<MFunction> m(int code) {
        return Optional.ofNullable(m.get(code));
    }

    public java.util.Collection<GFunction> allG() {
        return g.values();
    }

    public java.util.Collection<MFunction> allM() {
        return m.values();
    }

    public Optional<ParameterLimit> limit(char word) {
        return Optional.ofNullable(limits.get(word));
    }

    /** Table 7: the parameters a function accepts; empty when the function takes none listed. */
    public Optional<Set<Param>> allowedParameters(int function) {
        return Optional.ofNullable(usage.get(function));
    }

    /** Table 8, offset numbers 1..n. */
    public List<Offset> toolOffsets() {
        return toolOffsets;
    }

    /** Table 9, rows 1..n; rows 1-6 are G54-G59. */
    public List<Offset> workOffsets() {
        return workOffsets;
    }

    public ErrorMessages messages() {
        return messages;
    }
}
