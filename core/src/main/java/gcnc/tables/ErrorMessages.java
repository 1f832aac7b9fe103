package gcnc.tables;

import gcnc.diag.Code;
import java.text.MessageFormat;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/** Table 5 and gcnc's own codes: the message template of every code, in English and Spanish. */
public final class ErrorMessages {
    /** The same messages bound to one language, for renderers. */
    public gcnc.diag.Messages in(Lang lang) {
        return (code, args) -> render(code, args, lang);
    }

    public enum Lang { EN, ES }

    private final Map<Code, String[]> templates;

    ErrorMessages(Map<Code, String[]> templates) {
        this.templates = new EnumMap<>(templates);
    }

    public boolean has(Code code) {
        return templates.containsKey(code);
    }

    /** The message template as written in errors.csv, placeholders {0}, {1}... unfilled. */
    public String template(Code code, Lang lang) {
        String[] t = templates.get(code);
        return t == null ? "" : t[lang.ordinal()];
    }

    /** The message of a code with its arguments filled in. */
    public String render(Code code, List<String> args, Lang lang) {
        String[] t = templates.get(code);
        if (t == null) {
            return code.id() + " " + args;
        }
        return new MessageFormat(pattern(t[lang.ordinal()]), Locale.ROOT).format(args.toArray());
    }

    /** A template as MessageFormat reads it: an apostrophe in errors.csv is a plain apostrophe. */
    private static String pattern(String template) {
        return template.replace("'", "''");
    }

    /**
     * Reads errors.csv: each code once, each template renderable, and a row for every code of this
     * gcnc, so that no diagnostic can fail to print in the middle of a run.
     */
    static ErrorMessages load(Csv csv) throws TableException {
        Map<Code, String[]> m = new EnumMap<>(Code.class);
        Map<Code, Integer> lines = new EnumMap<>(Code.class);
        for (Csv.Row r : csv.rows()) {
            Code code = code(r);
            Integer first = lines.putIfAbsent(code, r.line());
            if (first != null) {
                throw r.faultAt("code", code.id() + " is listed twice (first on line " + first + ")");
            }
            m.put(code, new String[] {template(r, "en"), template(r, "es")});
        }
        for (Code c : Code.values()) {
            if (!m.containsKey(c)) {
                throw Csv.fault(csv.path(), 1, 1, "no row for " + c.id() + ": every diagnostic code needs its"
                        + " English and Spanish text");
            }
        }
        return new ErrorMessages(m);
    }

    private static Code code(Csv.Row r) throws TableException {
        int n = r.integer("code");
        try {
            return Code.byNumber(n);
        } catch (IllegalArgumentException e) {
            throw r.faultAt("code", "no diagnostic code " + n + " in this gcnc");
        }
    }

    /**
     * The template in a column, checked as {@link #render} will use it: MessageFormat throws on an
     * unbalanced '{' or a placeholder that is not {n}. (A typed one, {0,number}, cannot occur: the
     * comma would end the field.) The fault points at the offending '{'.
     */
    private static String template(Csv.Row r, String column) throws TableException {
        String t = r.get(column);
        try {
            new MessageFormat(pattern(t), Locale.ROOT);
            return t;
        } catch (IllegalArgumentException e) {
            int open = badPlaceholder(t);
            throw r.faultAt(column, Math.max(open, 0), "message template cannot be rendered: "
                    + (open < 0 ? e.getMessage() : placeholderProblem(t, open)));
        }
    }

    /** The index of the first '{' that does not start a plain {n} placeholder, or -1. */
    private static int badPlaceholder(String t) {
        for (int open = t.indexOf('{'); open >= 0; open = t.indexOf('{', open + 1)) {
            if (unclosed(t, open) || !t.substring(open + 1, t.indexOf('}', open)).matches("[0-9]{1,4}")) {
                return open;
            }
        }
        return -1;
    }

    /** No '}' closes the '{' at {@code open} before the next '{' (or the end). */
    private static boolean unclosed(String t, int open) {
        int close = t.indexOf('}', open);
        int next = t.indexOf('{', open + 1);
        return close < 0 || next >= 0 && next < close;
    }

    private static String placeholderProblem(String t, int open) {
        if (unclosed(t, open)) {
            return "'{' without '}'";
        }
        return "'" + t.substring(open, t.indexOf('}', open) + 1) + "' is not a placeholder {0}, {1}...";
    }
}
