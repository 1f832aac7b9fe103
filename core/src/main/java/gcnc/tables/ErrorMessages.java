package gcnc.tables;

import gcnc.diag.Code;
import gcnc.diag.Phrase;
import java.text.MessageFormat;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Table 5 and gcnc's own codes: the message template of every code, in English and Spanish, and the
 * phrases a message may take as arguments (tables/phrases.csv, {@link Phrase}), rendered in the same
 * language as the message.
 */
public final class ErrorMessages {
    /** The same messages bound to one language, for renderers. */
    public gcnc.diag.Messages in(Lang lang) {
        return new gcnc.diag.Messages() {
            @Override
            public String render(Code code, List<String> args) {
                return ErrorMessages.this.render(code, args, lang);
            }

            @Override
            public List<String> arguments(List<String> args) {
                return ErrorMessages.this.arguments(args, lang);
            }
        };
    }

    public enum Lang { EN, ES }

    private final Map<Code, String[]> templates;
    private final Map<Phrase, String[]> phrases;

    ErrorMessages(Map<Code, String[]> templates, Map<Phrase, String[]> phrases) {
        this.templates = new EnumMap<>(templates);
        this.phrases = new EnumMap<>(phrases);
    }

    public boolean has(Code code) {
        return templates.containsKey(code);
    }

    /** The message template as written in errors.csv, placeholders {0}, {1}... unfilled. */
    public String template(Code code, Lang lang) {
        String[] t = templates.get(code);
        return t == null ? "" : t[lang.ordinal()];
    }

    /** The message of a code with its arguments filled in, a phrase among them in the same language. */
    public String render(Code code, List<String> args, Lang lang) {
        String[] t = templates.get(code);
        if (t == null) {
            return code.id() + " " + args;
        }
        List<String> shown = arguments(args, lang);
        try {
            return new MessageFormat(pattern(Plurals.choose(t[lang.ordinal()], shown)), Locale.ROOT).format(shown.toArray());
        } catch (IllegalArgumentException e) {
            return code.id() + " " + shown;
        }
    }

    /** The arguments as a message shows them: a phrase in the language, any other as it is. */
    public List<String> arguments(List<String> args, Lang lang) {
        List<String> out = new java.util.ArrayList<>(args.size());
        for (String a : args) {
            out.add(phrase(a, lang));
        }
        return out;
    }

    /**
     * One argument as a message shows it: a phrase in the language (a phrase in its arguments too),
     * any other as it is. A phrase that cannot be put into words (not in this gcnc, no row) is
     * shown by its name and arguments rather than failing the message.
     */
    private String phrase(String a, Lang lang) {
        if (!Phrase.marked(a)) {
            return a;
        }
        Phrase p = Phrase.of(a);
        String[] texts = p == null ? null : phrases.get(p);
        if (texts == null) {
            return Phrase.plain(a);
        }
        List<String> inner = new java.util.ArrayList<>();
        for (String i : Phrase.arguments(a)) {
            inner.add(phrase(Phrase.unnested(i), lang));
        }
        try {
            return new MessageFormat(pattern(Plurals.choose(texts[lang.ordinal()], inner)), Locale.ROOT).format(inner.toArray());
        } catch (IllegalArgumentException e) {
            return Phrase.plain(a);
        }
    }

    /**
     * The English message of a diagnostic with the messages built into gcnc.jar, for logs and
     * exceptions ({@link TableException#getMessage}): it never fails, even while the built-in tables
     * are broken (then a phrase shows as its name and arguments).
     */
    public static String english(Code code, List<String> args) {
        ErrorMessages m = BuiltIn.MESSAGES;
        if (m != null) {
            return m.render(code, args, Lang.EN);
        }
        List<String> plain = new java.util.ArrayList<>();
        for (String a : args) {
            plain.add(Phrase.plain(a));
        }
        return plain.size() == 1 ? plain.get(0) : code.id() + " " + plain;
    }

    /** The built-in messages, read once when first needed; null when they cannot be read. */
    private static final class BuiltIn {
        static final ErrorMessages MESSAGES = read();

        private static ErrorMessages read() {
            try {
                TableSource src = TableSource.builtIn();
                return load(src.csv("errors.csv"), src.csv("phrases.csv"));
            } catch (TableException | RuntimeException e) {
                return null;
            }
        }
    }

    /** A template as MessageFormat reads it: an apostrophe in errors.csv is a plain apostrophe. */
    private static String pattern(String template) {
        return template.replace("'", "''");
    }

    /**
     * Reads errors.csv: each code once, each template renderable, and a row for every code of this
     * gcnc, so that no diagnostic can fail to print in the middle of a run.
     */
    static ErrorMessages load(Csv csv, Csv phraseCsv) throws TableException {
        Map<Code, String[]> m = new EnumMap<>(Code.class);
        Map<Code, Integer> lines = new EnumMap<>(Code.class);
        for (Csv.Row r : csv.rows()) {
            Code code = code(r);
            Integer first = lines.putIfAbsent(code, r.line());
            if (first != null) {
                throw r.faultAt("code", Phrase.LISTED_TWICE_FIRST.with(code.id(), first));
            }
            m.put(code, new String[] {template(r, "en"), template(r, "es")});
        }
        for (Code c : Code.values()) {
            if (!m.containsKey(c)) {
                throw Csv.fault(csv.path(), 1, 1, Phrase.NO_ROW_FOR_CODE.with(c.id()));
            }
        }
        return new ErrorMessages(m, phrases(phraseCsv));
    }

    /** Reads phrases.csv: each phrase once, renderable, and a row for every {@link Phrase}. */
    private static Map<Phrase, String[]> phrases(Csv csv) throws TableException {
        Map<Phrase, String[]> m = new EnumMap<>(Phrase.class);
        Map<Phrase, Integer> lines = new EnumMap<>(Phrase.class);
        for (Csv.Row r : csv.rows()) {
            Phrase p;
            try {
                p = Phrase.valueOf(r.get("key"));
            } catch (IllegalArgumentException e) {
                throw r.faultAt("key", Phrase.NO_SUCH_PHRASE.with(r.get("key")));
            }
            Integer first = lines.putIfAbsent(p, r.line());
            if (first != null) {
                throw r.faultAt("key", Phrase.LISTED_TWICE_FIRST.with(p, first));
            }
            m.put(p, new String[] {template(r, "en"), template(r, "es")});
        }
        for (Phrase p : Phrase.values()) {
            if (!m.containsKey(p)) {
                throw Csv.fault(csv.path(), 1, 1, Phrase.NO_ROW_FOR_PHRASE.with(p));
            }
        }
        return m;
    }

    private static Code code(Csv.Row r) throws TableException {
        int n = r.integer("code");
        try {
            return Code.byNumber(n);
        } catch (IllegalArgumentException e) {
            throw r.faultAt("code", Phrase.NO_SUCH_CODE.with(n));
        }
    }

    /**
     * The template in a column, checked as {@link #render} will use it: MessageFormat throws on an
     * unbalanced '{' or a placeholder that is not {n}. (A typed one, {0,number}, cannot occur: the
     * comma would end the field.) The fault points at the offending '{'.
     */
    private static String template(Csv.Row r, String column) throws TableException {
        String t = r.get(column);
        if (plainPlaceholders(t)) {
            return t; // what MessageFormat accepts, told without making one for each of ~1000 templates at every start
        }
        try {
            new MessageFormat(pattern(Plurals.choose(t, List.of())), Locale.ROOT); // the plural forms
            new MessageFormat(pattern(Plurals.choose(t, List.of("1", "1", "1", "1", "1", "1", "1", "1"))), Locale.ROOT);
            return t;
        } catch (IllegalArgumentException e) {
            int open = badPlaceholder(t);
            throw r.faultAt(column, Math.max(open, 0), open < 0 ? Phrase.TEMPLATE_BROKEN.with(e.getMessage())
                    : placeholderProblem(t, open));
        }
    }

    /**
     * Every brace of the template is a plain placeholder {n} of one to four digits, and no '}' stands
     * alone: a template MessageFormat surely accepts (with its apostrophes doubled by {@link #pattern},
     * everything else is literal text). A template with any other brace is judged by MessageFormat itself.
     */
    static boolean plainPlaceholders(String t) {
        int n = t.length();
        for (int i = 0; i < n; i++) {
            char c = t.charAt(i);
            if (c == '}') {
                return false;
            }
            if (c == '{') {
                int digits = 0;
                while (i + 1 < n && t.charAt(i + 1) >= '0' && t.charAt(i + 1) <= '9') {
                    i++;
                    digits++;
                }
                if (digits == 0 || digits > 4 || i + 1 >= n || t.charAt(i + 1) != '}') {
                    return false;
                }
                i++; // the closing brace
            }
        }
        return true;
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

    /** Why the template cannot be rendered, a phrase (its braces are arguments: a phrase's own would be placeholders). */
    private static String placeholderProblem(String t, int open) {
        if (unclosed(t, open)) {
            return Phrase.TEMPLATE_UNCLOSED.with("'{'", "'}'");
        }
        return Phrase.TEMPLATE_PLACEHOLDER.with(t.substring(open, t.indexOf('}', open) + 1), "{0}, {1}...");
    }
}
