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
        String template = t[lang.ordinal()].replace("'", "''");
        return new MessageFormat(template, Locale.ROOT).format(args.toArray());
    }

    static ErrorMessages load(Csv csv) throws TableException {
        Map<Code, String[]> m = new EnumMap<>(Code.class);
        for (Csv.Row r : csv.rows()) {
            int n = r.integer("code");
            Code code;
            try {
                code = Code.byNumber(n);
            } catch (IllegalArgumentException e) {
                throw r.faultAt("code", "no diagnostic code " + n + " in this gcnc");
            }
            m.put(code, new String[] {r.get("en"), r.get("es")});
        }
        return new ErrorMessages(m);
    }
}
