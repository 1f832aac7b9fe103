package gcnc.tables;

import gcnc.diag.Phrase;
import java.util.Collections;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.TreeMap;

/**
 * The thesis's tables 5, 6, 8 and 9 (errors, word ranges, offsets) as typed, immutable views, loaded once per run from tables/
 * (inside the jar, or a directory given with --tables). Nothing outside this package parses them.
 */
public final class Tables {
    /** The parameter letters of Table 7, in the thesis's check order (errors 21-27, 36). */
    public enum Param { X, Z, U, W, I, K, R, P }

    private final Map<Character, ParameterLimit> limits;
    private final List<Offset> toolOffsets;
    private final List<Offset> workOffsets;
    private final ErrorMessages messages;

    private Tables(Map<Character, ParameterLimit> limits, List<Offset> toolOffsets, List<Offset> workOffsets,
                   ErrorMessages messages) {
        this.limits = Collections.unmodifiableMap(limits);
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
        return new Tables(limits(csv(src, "parameter_limits.csv")), offsets(src, "tool_offsets.csv"),
                offsets(src, "work_offsets.csv"), ErrorMessages.load(csv(src, "errors.csv"), csv(src, "phrases.csv")));
    }

    /** Table 6: one row per word; a second row for a word would silently replace the first. */
    private static Map<Character, ParameterLimit> limits(Csv csv) throws TableException {
        Map<Character, ParameterLimit> limits = new HashMap<>();
        Map<Character, Integer> lines = new HashMap<>();
        for (Csv.Row r : csv.rows()) {
            String w = r.get("word");
            if (w.length() != 1) {
                throw r.faultAt("word", Phrase.WORD_ONE_LETTER.with(w));
            }
            Integer first = lines.putIfAbsent(w.charAt(0), r.line());
            if (first != null) {
                throw r.faultAt("word", Phrase.WORD_TWICE.with(w, first));
            }
            ParameterLimit l = new ParameterLimit(w.charAt(0), letter(r, "sign", "P", "N").equals("P"),
                    letter(r, "type", "E", "D").equals("E"), r.decimal("lower"), r.decimal("upper"));
            if (l.lower() > l.upper()) {
                throw r.faultAt("lower", Phrase.LOWER_ABOVE_UPPER.arg());
            }
            limits.put(l.word(), l);
        }
        return limits;
    }

    /** A column that holds one of two letters: anything else would silently read as the second. */
    private static String letter(Csv.Row r, String column, String first, String second) throws TableException {
        String v = r.get(column);
        if (!v.equals(first) && !v.equals(second)) {
            throw r.faultAt(column, Phrase.ONE_OF_TWO.with(column, first, second, v));
        }
        return v;
    }

    private static List<Offset> offsets(TableSource src, String name) throws TableException {
        List<Offset> list = new java.util.ArrayList<>();
        for (Csv.Row r : csv(src, name).rows()) {
            if (r.integer("offset") != list.size() + 1) {
                throw r.faultAt("offset", Phrase.OFFSETS_IN_ORDER.with("1, 2, 3..."));
            }
            list.add(new Offset(r.decimal("x"), r.decimal("z")));
        }
        return list;
    }

    private static Csv csv(TableSource src, String name) throws TableException {
        return Csv.parse(src.describe(name), src.read(name));
    }

    public Optional<ParameterLimit> limit(char word) {
        return Optional.ofNullable(limits.get(word));
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
