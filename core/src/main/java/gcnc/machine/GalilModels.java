package gcnc.machine;

import gcnc.diag.Code;
import gcnc.diag.Phrase;
import gcnc.machine.GalilModel.Limit;
import gcnc.machine.GalilModel.Range;
import gcnc.tables.Csv;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * tables/galil_models.csv, read and checked like the other tables (a bad cell is a fault at its
 * line and column), and the machine profile's side of it: {@code galil.model} picks a row (E420 with
 * the nearest name when none matches), {@code galil.firmware} says whether the 1.2a program memory
 * applies, and a profile whose numbers the model cannot take is refused at their line (E421-E424)
 * instead of every program failing later at one of its own lines.
 */
public final class GalilModels {
    public static final String FILE = "galil_models.csv";
    /**
     * The model of a profile without {@code galil.model}: a DMC-40x0 with the four channels a lathe
     * uses (Z, X, the spindle's output, a spare).
     */
    public static final String DEFAULT = "DMC-4040";

    private final Map<String, GalilModel> byName;

    private GalilModels(Map<String, GalilModel> byName) {
        this.byName = byName;
    }

    public static GalilModels load(TableSource source) throws TableException {
        Csv csv = source.csv(FILE);
        Map<String, GalilModel> models = new LinkedHashMap<>();
        Map<String, Integer> lines = new LinkedHashMap<>();
        for (Csv.Row r : csv.rows()) {
            String name = r.get("model");
            if (!name.matches("DMC-[0-9]{4,5}")) {
                throw r.faultAt("model", Phrase.GALIL_MODEL_NAME.with(name));
            }
            Integer first = lines.putIfAbsent(name, r.line());
            if (first != null) {
                throw r.faultAt("model", Phrase.GALIL_MODEL_TWICE.with(name, first));
            }
            int axes = whole(r, "axes", 1, 8);
            Map<Limit, Range> limits = new EnumMap<>(Limit.class);
            for (Limit l : Limit.values()) {
                limits.put(l, range(r, l, l.maxColumn()));
            }
            Map<Limit, Range> newer = new EnumMap<>(Limit.class);
            newer(r, limits, Limit.PROGRAM_LINES, "program_lines_12a", newer);
            newer(r, limits, Limit.ARRAY_ELEMENTS, "array_elements_12a", newer);
            String analog = r.get("analog_outputs");
            GalilModel.HostLink link = hostLink(r);
            String echo = r.get("serial_echo");
            if (!(echo.equals("1") || echo.equals("0") || echo.isEmpty() && link == GalilModel.HostLink.BUS)) {
                throw r.faultAt("serial_echo", Phrase.GALIL_MODEL_CHOICE.with("serial_echo", echo,
                        "1 or 0 (blank for a bus card)"));
            }
            models.put(name, new GalilModel(name, r.get("family"), axes, whole(r, "digital_outputs", 0, 64),
                    analog.isEmpty() ? -1 : whole(r, "analog_outputs", 0, 64), whole(r, "sample_us", 1, 100_000),
                    limits, newer, false, link, echo.equals("1"), List.of(), r.line()));
        }
        return new GalilModels(models);
    }

    /** The host_link cell: serial-ethernet or bus. */
    private static GalilModel.HostLink hostLink(Csv.Row r) throws TableException {
        String v = r.get("host_link");
        for (GalilModel.HostLink l : GalilModel.HostLink.values()) {
            if (l.spelling().equals(v)) {
                return l;
            }
        }
        throw r.faultAt("host_link", Phrase.GALIL_MODEL_CHOICE.with("host_link", v, "serial-ethernet or bus"));
    }

    /** The built-in table; a broken one is a bug in gcnc.jar, not a user's fault. */
    public static GalilModels builtIn() {
        try {
            return load(TableSource.builtIn());
        } catch (TableException e) {
            throw new IllegalStateException("the tables built into gcnc.jar are broken: " + e.getMessage(), e);
        }
    }

    public Optional<GalilModel> find(String name) {
        return Optional.ofNullable(byName.get(name));
    }

    public List<GalilModel> all() {
        return List.copyOf(byName.values());
    }

    /** The series the table knows, each with its first and last model: "DMC-40x0 (DMC-4010 to DMC-4080)". */
    String families() {
        Map<String, List<String>> fam = new LinkedHashMap<>();
        for (GalilModel m : byName.values()) {
            fam.computeIfAbsent(m.family(), k -> new ArrayList<>()).add(m.name());
        }
        List<String> out = new ArrayList<>();
        fam.forEach((f, names) -> out.add(names.size() == 1 ? names.get(0)
                : names.get(0) + ".." + names.get(names.size() - 1)));
        return String.join(", ", out);
    }

    /**
     * The model a profile names ({@link #DEFAULT} without the key), at the firmware it names:
     * E420 at {@code galil.model}'s value when the table has no such model, with the nearest name.
     */
    GalilModel forProfile(ProfileFile f) throws TableException {
        Optional<ProfileFile.Entry> e = f.entry("galil.model");
        String name = e.map(ProfileFile.Entry::value).orElse(DEFAULT);
        Optional<GalilModel> m = find(name);
        if (m.isEmpty()) {
            // a model is typed as the controller's label reads ("DMC4040", "dmc-4040"): compare without the dash and case
            String near = Spelling.typo(name, List.copyOf(byName.keySet()))
                    .or(() -> byName.keySet().stream().filter(k -> squeeze(k).equals(squeeze(name))).findFirst())
                    .map(Phrase.DID_YOU_MEAN::with).orElse("");
            throw f.fault(e.orElseThrow(), Code.E420_UNKNOWN_GALIL_MODEL, name, near, families());
        }
        GalilModel model = firmware(f) ? m.get().withFirmware12a() : m.get();
        // galil.deviations: probe rows the shop's unit contradicts, checked against ProbeRow by gcnc run
        List<String> deviations = new ArrayList<>();
        for (String d : f.entry("galil.deviations").map(ProfileFile.Entry::value).orElse("").split(",")) {
            if (!d.isBlank()) {
                deviations.add(d.strip());
            }
        }
        return model.withDeviations(deviations);
    }

    private static String squeeze(String s) {
        return s.replace("-", "").toUpperCase(java.util.Locale.ROOT);
    }

    /** A firmware revision as ^R^V reports it: 1.2a, 1.0c, 1.3e; optionally with "Rev". */
    private static final Pattern REVISION = Pattern.compile("(?i)(?:rev\\s*)?([0-9]+)\\.([0-9]+)([a-z]?)");

    /** Whether {@code galil.firmware} is 1.2a or later (absent: no, the smaller program memory holds). */
    private static boolean firmware(ProfileFile f) throws TableException {
        Optional<ProfileFile.Entry> e = f.entry("galil.firmware");
        if (e.isEmpty()) {
            return false;
        }
        Matcher m = REVISION.matcher(e.get().value());
        if (!m.matches()) {
            throw f.fault(e.get(), Code.E425_FIRMWARE_REVISION, e.get().value());
        }
        int major = Integer.parseInt(m.group(1));
        int minor = Integer.parseInt(m.group(2));
        char letter = m.group(3).isEmpty() ? 'a' : Character.toLowerCase(m.group(3).charAt(0));
        return major > 1 || (major == 1 && (minor > 2 || (minor == 2 && letter >= 'a')));
    }

    /**
     * The profile's numbers against its model: every channel it names exists on the model (E421),
     * its accelerations are what VA and VD take (E422), its speeds what VS takes (E423), and its
     * outputs are outputs the model has (E424). Each at the line that says it.
     */
    static void holds(MachineProfile p, ProfileFile f) throws TableException {
        GalilModel m = p.galilModel();
        Optional<ProfileFile.Entry> model = f.entry("galil.model");
        channel(f, m, "x.galil", p.x().galil(), model);
        channel(f, m, "z.galil", p.z().galil(), model);
        channel(f, m, "spindle.axis", p.spindleAxis(), model);
        if (p.spindleEncoder() != null) {
            channel(f, m, f.entry("spindle.encoder_axis").isPresent() ? "spindle.encoder_axis" : "spindle.axis",
                    p.spindleEncoder().channel(), model);
        }
        Range accel = m.range(Limit.ACCELERATION);
        within(f, m, "vector.acceleration", p.acceleration(), accel, Code.E422_ACCELERATION_BEYOND_MODEL);
        within(f, m, "vector.deceleration", p.deceleration(), accel, Code.E422_ACCELERATION_BEYOND_MODEL);
        Range speed = m.range(Limit.VECTOR_SPEED);
        within(f, m, "rapid.speed", p.rapidSpeed(), speed, Code.E423_SPEED_BEYOND_MODEL);
        within(f, m, "feed.max", p.maxFeed(), speed, Code.E423_SPEED_BEYOND_MODEL);
        for (ProfileFile.Entry e : f.withPrefix("m.")) {
            for (String d : e.value().split(",")) {
                int bit = Integer.parseInt(d.trim().substring(2).trim()); // ProfileLoader checked (SB|CB) n
                if (bit < 1 || bit > m.digitalOutputs()) {
                    throw f.fault(e, Code.E424_OUTPUT_BEYOND_MODEL, e.key(), d.trim(), m.name(), m.digitalOutputs());
                }
            }
        }
    }

    /**
     * A channel the model must have: the fault is at the key's line, or at galil.model's when the
     * key is absent and its default (spindle.axis C) is what the model lacks.
     */
    private static void channel(ProfileFile f, GalilModel m, String key, char letter,
                                Optional<ProfileFile.Entry> model) throws TableException {
        if (m.hasChannel(letter)) {
            return;
        }
        ProfileFile.Entry at = f.entry(key).or(() -> model).orElseThrow();
        throw f.fault(at, Code.E421_CHANNEL_BEYOND_MODEL, key, letter, m.name(), m.channels());
    }

    /** A profile value (given or its default) the model's command takes; a default outside it is shown at galil.model. */
    private static void within(ProfileFile f, GalilModel m, String key, double v, Range r, Code code)
            throws TableException {
        if (r.holds(v, false)) {
            return;
        }
        Optional<ProfileFile.Entry> e = f.entry(key).or(() -> f.entry("galil.model"));
        if (e.isEmpty()) {
            return; // a default of gcnc's own is inside every model's range
        }
        throw f.fault(e.get(), code, key, ProfileFile.written(v), m.name(), r.min(), r.max());
    }

    private static Range range(Csv.Row r, Limit l, String maxColumn) throws TableException {
        long min = l.minColumn() == null ? 0 : whole(r, l.minColumn(), 0, Integer.MAX_VALUE);
        long max = whole(r, maxColumn, 1, Integer.MAX_VALUE);
        long step = l.stepColumn() == null ? 1 : whole(r, l.stepColumn(), 1, Integer.MAX_VALUE);
        if (min > max) {
            throw r.faultAt(l.minColumn(), Phrase.LOWER_ABOVE_UPPER.arg());
        }
        return new Range(min, max, step);
    }

    /** A firmware-1.2a column: blank (the model has no such figure), else at least the older one. */
    private static void newer(Csv.Row r, Map<Limit, Range> limits, Limit l, String column, Map<Limit, Range> out)
            throws TableException {
        if (r.get(column).isEmpty()) {
            return;
        }
        Range old = limits.get(l);
        Range range = range(r, l, column);
        if (range.max() < old.max()) {
            throw r.faultAt(column, Phrase.GALIL_FIRMWARE_SMALLER.with(column, l.maxColumn()));
        }
        out.put(l, range);
    }

    private static int whole(Csv.Row r, String column, int min, int max) throws TableException {
        int v = r.integer(column);
        if (v < min || v > max) {
            throw r.faultAt(column, Phrase.GALIL_MODEL_RANGE.with(column, v, min, max));
        }
        return v;
    }
}
