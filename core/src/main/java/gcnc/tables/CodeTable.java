package gcnc.tables;

import gcnc.diag.Code;
import gcnc.diag.Phrase;
import gcnc.diag.SarifRenderer;
import gcnc.diag.Severity;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/**
 * errors.csv as a catalogue of codes, for {@code gcnc explain} and SARIF's rules (the command line and the Gradle plugin): each code's
 * severity and its message in both languages, and an explanation when the table has an
 * {@code explanation} column. (The messages a run prints come from {@link ErrorMessages}.)
 */
public final class CodeTable {
    /** One row of errors.csv. */
    public record Entry(Code code, Severity severity, String english, String spanish, String explanation) {
        public String text(ErrorMessages.Lang lang) {
            return lang == ErrorMessages.Lang.ES ? spanish : english;
        }
    }

    private final List<Entry> entries;

    private CodeTable(List<Entry> entries) {
        this.entries = List.copyOf(entries);
    }

    /** The row's diagnostic code ({@code code}, its number), a located fault when there is no such code. */
    static Code code(Csv.Row r) throws TableException {
        try {
            return Code.byNumber(r.integer("code"));
        } catch (IllegalArgumentException e) {
            throw r.faultAt("code", Phrase.NO_SUCH_CODE.with(r.integer("code")));
        }
    }

    public static CodeTable load(TableSource source) throws TableException {
        Csv csv = source.csv("errors.csv");
        List<Entry> entries = new ArrayList<>();
        for (Csv.Row r : csv.rows()) {
            Code code = code(r);
            entries.add(new Entry(code, severity(r), r.get("en"), r.get("es"), explanation(r)));
        }
        return new CodeTable(entries);
    }

    private static Severity severity(Csv.Row r) throws TableException {
        String s = r.get("severity");
        try {
            return Severity.valueOf(s.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw r.faultAt("severity", Phrase.SEVERITY.with(s, "error, warning"));
        }
    }

    /** The optional explanation column; a table without it explains nothing beyond the message. */
    private static String explanation(Csv.Row r) {
        try {
            return r.get("explanation");
        } catch (TableException e) {
            return "";
        }
    }

    public List<Entry> entries() {
        return entries;
    }

    public Optional<Entry> find(Code code) {
        return entries.stream().filter(e -> e.code() == code).findFirst();
    }

    /**
     * Every code as a SARIF rule, its description in {@code lang}; with gcnc explain's prose where
     * it has one (tables/explain/, read only here and by explain): why as the full description,
     * the fix and the example as the help.
     */
    public List<SarifRenderer.Rule> rules(ErrorMessages.Lang lang) {
        Explanations explain = Explanations.builtIn();
        return entries.stream().map(e -> rule(e, lang, explain)).toList();
    }

    private static SarifRenderer.Rule rule(Entry e, ErrorMessages.Lang lang, Explanations explain) {
        Optional<Explanations.Prose> p = explain.prose(e.code(), lang);
        if (p.isEmpty()) {
            return new SarifRenderer.Rule(e.code(), e.severity(), e.text(lang));
        }
        String full = p.get().control().isEmpty() ? p.get().cause() : p.get().cause() + " " + p.get().control();
        List<String> example = explain.example(e.code()).map(Explanations.Example::lines).orElse(List.of());
        String fix = (lang == ErrorMessages.Lang.ES ? "Arreglo: " : "Fix: ") + p.get().fix();
        String label = lang == ErrorMessages.Lang.ES ? "Ejemplo" : "Example";
        String text = example.isEmpty() ? fix : fix + "\n" + label + ":\n" + String.join("\n", example);
        String markdown = example.isEmpty() ? fix
                : fix + "\n\n" + label + " (`gcnc explain " + e.code().id() + "`):\n\n```gcode\n"
                        + String.join("\n", example) + "\n```";
        return new SarifRenderer.Rule(e.code(), e.severity(), e.text(lang), full, text, markdown);
    }
}
