package gcnc.machine;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Phrase;
import gcnc.diag.Span;
import gcnc.tables.Decimal;
import gcnc.tables.TableException;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalDouble;

/**
 * The text of a machine profile: {@code key = value} lines, {@code #} comments (whole-line or
 * trailing), keys in any order, each at most once. Every value remembers its line and column so
 * that a bad value is reported where the user typed it. Typed readers are below. A machine
 * profile's keys are all read when it is loaded (ProfileLoader, MachineModel), so no part of gcnc
 * reads one later; control.cfg has the same form (ControlLoader).
 */
public final class ProfileFile {
    /**
     * A value as written, with its place: {@code keyColumn} where the key starts (for a fault in
     * the key itself, e.g. an unknown one), {@code column} where the value starts.
     */
    public record Entry(String key, String value, int line, int keyColumn, int column) {
    }

    private final String path;
    private final Map<String, Entry> entries;

    private ProfileFile(String path, Map<String, Entry> entries) {
        this.path = path;
        this.entries = Collections.unmodifiableMap(entries);
    }

    public static ProfileFile parse(String path, String text) throws TableException {
        Map<String, Entry> map = new LinkedHashMap<>();
        String[] lines = text.split("\r?\n", -1);
        for (int n = 0; n < lines.length; n++) {
            String raw = lines[n];
            int hash = raw.indexOf('#');
            String l = hash >= 0 ? raw.substring(0, hash) : raw;
            if (l.isBlank()) {
                continue;
            }
            int eq = l.indexOf('=');
            int indent = l.length() - l.stripLeading().length();
            if (eq < 0) {
                throw fault(path, n + 1, indent + 1, Phrase.EXPECTED_KEY_VALUE.arg());
            }
            String key = l.substring(0, eq).trim();
            String value = l.substring(eq + 1).trim();
            int valueCol = eq + 2 + (l.substring(eq + 1).length() - l.substring(eq + 1).stripLeading().length());
            if (key.isEmpty()) {
                throw fault(path, n + 1, indent + 1, Phrase.MISSING_KEY_BEFORE_EQUALS.arg());
            }
            if (map.containsKey(key)) {
                throw fault(path, n + 1, indent + 1, Phrase.KEY_GIVEN_TWICE.with(key, map.get(key).line()));
            }
            map.put(key, new Entry(key, value, n + 1, indent + 1, valueCol));
        }
        return new ProfileFile(path, map);
    }

    public String path() {
        return path;
    }

    public Optional<Entry> entry(String key) {
        return Optional.ofNullable(entries.get(key));
    }

    /** All keys that start with a prefix, in file order (e.g. "tool." for the tool table). */
    public List<Entry> withPrefix(String prefix) {
        List<Entry> out = new ArrayList<>();
        for (Entry e : entries.values()) {
            if (e.key().startsWith(prefix)) {
                out.add(e);
            }
        }
        return out;
    }

    public List<String> keys() {
        return List.copyOf(entries.keySet());
    }

    public Entry required(String key) throws TableException {
        Entry e = entries.get(key);
        if (e == null) {
            throw fault(path, 1, 1, Phrase.MISSING_REQUIRED_KEY.with(key));
        }
        return e;
    }

    public String text(String key) throws TableException {
        return required(key).value();
    }

    public String text(String key, String otherwise) {
        Entry e = entries.get(key);
        return e == null ? otherwise : e.value();
    }

    public double number(String key) throws TableException {
        return number(required(key));
    }

    public double number(String key, double otherwise) throws TableException {
        Entry e = entries.get(key);
        return e == null ? otherwise : number(e);
    }

    public double positive(String key) throws TableException {
        Entry e = required(key);
        double v = number(e);
        if (!(v > 0)) {
            throw fault(e, Phrase.GREATER_THAN_ZERO.with(key));
        }
        return v;
    }

    /** An optional value that must be greater than 0 when given. */
    public double positive(String key, double otherwise) throws TableException {
        return entries.containsKey(key) ? positive(key) : otherwise;
    }

    /** A finite decimal number ({@link Decimal}): NaN, infinities and hexadecimal are faults. */
    public double number(Entry e) throws TableException {
        return number(e, e.value());
    }

    /**
     * The largest size of any number in a profile or control: 10^12. No length (mm), speed, rate or
     * count of a lathe comes near it, and a product of two such numbers (mm times counts per mm)
     * stays a finite number, so that the checks in counts that follow can speak; past it a value is
     * a slip of the keyboard (1e306) that would overflow every sum it enters (E401).
     */
    public static final double MAX_SIZE = 1e12;

    /** One number written inside the value of {@code e} (a pair, a list of points). */
    public double number(Entry e, String text) throws TableException {
        OptionalDouble v = Decimal.parse(text.trim());
        if (v.isEmpty()) {
            throw fault(e, Phrase.NOT_A_NUMBER.with(text.trim(), e.key()));
        }
        if (Math.abs(v.getAsDouble()) > MAX_SIZE) {
            throw fault(e, Code.E401_PROFILE_NUMBER_TOO_LARGE, e.key(), text.trim(), written(MAX_SIZE));
        }
        return v.getAsDouble();
    }

    /**
     * A number that must lie in {@code [min, max]} (E402 at its value): a rate, a count or a speed
     * past which no lathe goes (docs/profiles.md, "Checked when loaded").
     */
    public double within(String key, double min, double max) throws TableException {
        return within(required(key), min, max);
    }

    public double within(Entry e, double min, double max) throws TableException {
        double v = min > 0 ? positive(e.key()) : number(e);
        if (!(v >= min && v <= max)) {
            throw fault(e, Code.E402_PROFILE_VALUE_RANGE, e.key(), written(v), written(min), written(max));
        }
        return v;
    }

    /** A fault with a code of its own (not E400's phrase) at the value of {@code e}. */
    public TableException fault(Entry e, Code code, Object... args) {
        return new TableException(path, Diagnostic.error(code, Span.of(e.line(), e.column()), args));
    }

    /** A value written as {@code a, b} (two numbers). */
    public double[] pair(Entry e) throws TableException {
        String[] parts = e.value().split(",", -1);
        if (parts.length != 2) {
            throw fault(e, Phrase.TWO_NUMBERS.with(e.key(), "a, b"));
        }
        return new double[] {number(e, parts[0]), number(e, parts[1])};
    }

    public double[] pair(String key) throws TableException {
        return pair(required(key));
    }

    /** One of a closed set of words; the fault lists the choices. */
    public String choice(String key, String otherwise, String... choices) throws TableException {
        Entry e = entries.get(key);
        if (e == null) {
            return otherwise;
        }
        for (String c : choices) {
            if (c.equalsIgnoreCase(e.value())) {
                return c;
            }
        }
        throw fault(e, Phrase.ONE_OF.with(key, String.join(", ", choices), e.value()));
    }

    /** A number for a message as a person would write it in a profile (no 1.0E7, no trailing zeros). */
    public static String written(double v) {
        if (!Double.isFinite(v)) {
            return Double.isNaN(v) ? "NaN" : v > 0 ? "+inf" : "-inf";
        }
        java.math.BigDecimal d = java.math.BigDecimal.valueOf(v).stripTrailingZeros();
        // past 15 digits a plain number is a wall of zeros: 1E+306 says it
        return Math.abs(v) >= 1e15 || v != 0 && Math.abs(v) < 1e-9 ? d.round(new java.math.MathContext(6)).toString()
                : d.toPlainString();
    }

    /**
     * A fault in the value of {@code e}, at the value's column. {@code message} is a
     * {@link Phrase} argument ({@code Phrase.X.with(...)}), so that it reads in the user's language.
     */
    public TableException fault(Entry e, String message) {
        return fault(path, e.line(), e.column(), message);
    }

    /** A fault in the key of {@code e} (unknown, misplaced), at the key's column. */
    public TableException faultAtKey(Entry e, String message) {
        return fault(path, e.line(), e.keyColumn(), message);
    }

    public static TableException fault(String path, int line, int column, String message) {
        return new TableException(path, Diagnostic.error(Code.E400_TABLE, Span.of(line, column), message));
    }
}
