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
    /** The messages; for the built-in tables null until first needed (see {@link #messages()}). */
    private volatile ErrorMessages messages;
    /** Where the messages are read from when first needed: the built-in source, else null (read already). */
    private final TableSource later;

    private Tables(Map<Character, ParameterLimit> limits, List<Offset> toolOffsets, List<Offset> workOffsets,
                   ErrorMessages messages, TableSource later) {
        this.limits = Collections.unmodifiableMap(limits);
        this.toolOffsets = List.copyOf(toolOffsets);
        this.workOffsets = List.copyOf(workOffsets);
        this.messages = messages;
        this.later = later;
    }

    /** The tables shipped inside gcnc.jar. */
    public static Tables builtIn() {
        try {
            return load(TableSource.builtIn());
        } catch (TableException e) {
            throw new IllegalStateException("the tables built into gcnc.jar are broken: " + e.getMessage(), e);
        }
    }

    /**
     * Reads the tables of {@code src}. Those of a directory ({@code --tables DIR}) are read and checked
     * whole, here, so that a broken one stops the run before it starts. The built-in messages
     * (errors.csv and phrases.csv, 97 KB, checked by the build's tests) are read only when a message
     * is first rendered (issue 35: a clean check never renders one, and reading them was a sixth of
     * a cold 2,000-block check's main thread).
     */
    public static Tables load(TableSource src) throws TableException {
        return new Tables(limits(src.csv("parameter_limits.csv")), offsets(src, "tool_offsets.csv"),
                offsets(src, "work_offsets.csv"), src.isBuiltIn() ? null : messages(src),
                src.isBuiltIn() ? src : null);
    }

    private static ErrorMessages messages(TableSource src) throws TableException {
        return ErrorMessages.load(src.csv("errors.csv"), src.csv("phrases.csv"));
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
        for (Csv.Row r : src.csv(name).rows()) {
            if (r.integer("offset") != list.size() + 1) {
                throw r.faultAt("offset", Phrase.OFFSETS_IN_ORDER.with("1, 2, 3..."));
            }
            list.add(new Offset(r.decimal("x"), r.decimal("z")));
        }
        return list;
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
        ErrorMessages m = messages;
        if (m == null) {
            try {
                m = messages(later);
            } catch (TableException e) {
                throw new IllegalStateException("the tables built into gcnc.jar are broken: " + e.getMessage(), e);
            }
            messages = m;
        }
        return m;
    }

    /**
     * The messages in one language, read when the first one is rendered: what a reporter holds from
     * the start of a run that may never print a finding.
     */
    public gcnc.diag.Messages messagesIn(ErrorMessages.Lang lang) {
        return new gcnc.diag.Messages() {
            @Override
            public String render(gcnc.diag.Code code, List<String> args) {
                return messages().render(code, args, lang);
            }

            @Override
            public List<String> arguments(List<String> args) {
                return messages().arguments(args, lang);
            }
        };
    }
}
