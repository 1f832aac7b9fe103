package gcnc.tables;

import gcnc.diag.Code;
import gcnc.diag.Phrase;
import gcnc.diag.Severity;
import java.util.EnumMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * tables/error_basis.csv: which control behaviour a diagnostic stands for (issue 17: an error only
 * where the control stops, a warning where it runs the block and the result may not be what was
 * meant), and whether the rule is the control's manual's or one gcnc adds beyond the manuals
 * (geometry plausibility, thread proportions, cycle structure). {@code gcnc explain} prints it. A
 * code without a row is one whose basis is its message (the thesis's table, a file or the backend).
 */
public final class ErrorBasis {
    /** Where the rule comes from. */
    public enum Source {
        /** The Haas or Fanuc operator's manual (an alarm it lists, or what it says the control does). */
        MANUAL,
        /** gcnc's own judgement beyond the manuals. */
        GCNC,
        /** Galil's firmware command reference: a value the controller refuses or rounds (tables/galil_models.csv). */
        GALIL,
        /** The thesis's own control (Table 5; the thesis-2004 profile), where its rule is not Fanuc's or Haas's. */
        THESIS,
        /** Not a block of the program: the machine profile, a table, the command line, a file or the controller link. */
        SETUP
    }

    /** What the control does with the block. */
    public enum Behaviour {
        /** It stops with an alarm: gcnc reports an error. */
        ALARM,
        /** It runs the block: gcnc warns (or notes) where the result may not be what was meant. */
        RUNS,
        /** Whatever the control does, gcnc cannot follow it yet: a precise "not supported yet" error. */
        UNSUPPORTED
    }

    /** One row: the code, its source, the control's behaviour and what that behaviour is, in both languages. */
    public record Row(Code code, Source source, Behaviour behaviour, String english, String spanish) {
        public String text(ErrorMessages.Lang lang) {
            return lang == ErrorMessages.Lang.ES ? spanish : english;
        }

        /** The severity this behaviour calls for: an alarm (or gcnc's "not supported yet") is an error, a block that runs is not. */
        public boolean agrees(Severity s) {
            return behaviour == Behaviour.RUNS ? s != Severity.ERROR : s == Severity.ERROR;
        }
    }

    public static final String FILE = "error_basis.csv";

    private final Map<Code, Row> rows;

    private ErrorBasis(Map<Code, Row> rows) {
        this.rows = rows;
    }

    public static ErrorBasis load(TableSource source) throws TableException {
        Csv csv = source.csv(FILE);
        Map<Code, Row> rows = new EnumMap<>(Code.class);
        for (Csv.Row r : csv.rows()) {
            Code code = CodeTable.code(r);
            Row row = new Row(code, value(r, "source", Source.class), value(r, "control", Behaviour.class),
                    r.get("en"), r.get("es"));
            rows.put(code, row); // ErrorBasisTest keeps each code to one row
        }
        return new ErrorBasis(rows);
    }

    private static <E extends Enum<E>> E value(Csv.Row r, String column, Class<E> type) throws TableException {
        String s = r.get(column);
        try {
            return Enum.valueOf(type, s.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            StringBuilder names = new StringBuilder();
            for (E v : type.getEnumConstants()) {
                names.append(names.length() > 0 ? ", " : "").append(v.name().toLowerCase(Locale.ROOT));
            }
            throw r.faultAt(column, Phrase.ONE_OF.with(column, names, s));
        }
    }

    /** No rows: a --tables folder with an errors.csv of its own and no error_basis.csv. */
    public static ErrorBasis empty() {
        return new ErrorBasis(new EnumMap<>(Code.class));
    }

    public Optional<Row> find(Code code) {
        return Optional.ofNullable(rows.get(code));
    }

    public Map<Code, Row> rows() {
        return Map.copyOf(rows);
    }
}
