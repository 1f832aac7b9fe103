package gcnc.machine;

import static gcnc.machine.ProfileFile.written;

import gcnc.diag.Phrase;
import gcnc.ir.Point;
import gcnc.tables.Offset;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import gcnc.tables.Utf8;
import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads and validates a machine profile. {@code --machine NAME} finds
 * {@code machines/NAME.machine} among the tables; anything with a '/' or ending in
 * {@code .machine} is a file path. Every key is read and checked here, the simulator's too
 * ({@link MachineModel}), so that every fault names the profile's file, line and column when gcnc
 * starts, and none is left to surface later as a finding at a line of the program
 * (docs/profiles.md, "Checked when loaded").
 */
public final class ProfileLoader {
    public static final String DEFAULT = "generic";

    /** The largest value of a Galil register (positions, VS, VA, VD are 32-bit). */
    private static final double REGISTER_MAX = Integer.MAX_VALUE;
    /**
     * Counts per mm gcnc takes: one count from 1 mm (the thesis machine has 1.5 counts per mm)
     * down to 1 nm; outside that a value is a slip (a zero too many or too few), E402.
     */
    private static final double MIN_COUNTS_PER_MM = 1;
    private static final double MAX_COUNTS_PER_MM = 1_000_000;
    /** Spindle speed (and drive gain per volt) gcnc takes: up to 100,000 r/min, beyond any lathe spindle. */
    private static final double MAX_RPM = 100_000;
    /** feed.per_f: counts/s per unit of F (the thesis machine: 20; by default counts per mm / 60). */
    private static final double MIN_PER_F = 0.001;
    private static final double MAX_PER_F = 1_000_000;

    /** The machine profiles in gcnc's tables (tables/machines), by name. */
    public static final java.util.List<String> SHIPPED = java.util.List.of("fanuc", "generic", "haas", "thesis-2004");

    private ProfileLoader() {
    }

    public static MachineProfile load(String nameOrPath, TableSource tables, Tables data) throws TableException {
        return load(nameOrPath, tables, data, null);
    }

    /** Loads a profile; {@code control}, when not null, replaces the control the profile names. */
    public static MachineProfile load(String nameOrPath, TableSource tables, Tables data, String control)
            throws TableException {
        return load(nameOrPath, tables, data, control, java.util.Optional.empty(), false);
    }

    /**
     * Loads a profile with its wear offsets from {@code offsets} ({@code --offsets FILE}) when given,
     * else from the offsets file the profile names ({@code offsets.file}), if any ({@link WearReader});
     * with {@code newOffsets} an offsets file that does not exist yet reads as empty (else E455).
     */
    public static MachineProfile load(String nameOrPath, TableSource tables, Tables data, String control,
                                      java.util.Optional<Path> offsets, boolean newOffsets) throws TableException {
        ProfileFile f;
        if (isPath(nameOrPath)) {
            Path p = Path.of(nameOrPath);
            f = ProfileFile.parse(p.toString(), readFile(p));
        } else {
            String name = "machines/" + nameOrPath + ".machine";
            String text;
            try {
                text = tables.read(name);
            } catch (TableException e) {
                if (!SHIPPED.contains(nameOrPath)) {
                    // a name gcnc does not ship: say which it does, and the nearest ("hass": haas)
                    String shipped = String.join(", ", SHIPPED);
                    throw ProfileFile.fault(tables.describe(name), 1, 1, Spelling.typo(nameOrPath, SHIPPED)
                            .map(near -> Phrase.NO_MACHINE_TYPO.with(nameOrPath, near, shipped))
                            .orElse(Phrase.NO_MACHINE.with(nameOrPath, shipped)));
                }
                throw e;
            }
            f = ProfileFile.parse(tables.describe(name), text);
        }
        return read(f, data, tables, control, offsets, newOffsets);
    }

    /** Whether {@code --machine} names a file (a '/' in it, or ending in .machine) rather than a profile among the tables. */
    public static boolean isPath(String nameOrPath) {
        return nameOrPath.contains("/") || nameOrPath.endsWith(".machine");
    }

    /** A profile (or the tool table file it names) given as a path, decoded as the tables are ({@link Utf8}). */
    static String readFile(Path p) throws TableException {
        try {
            return Utf8.read(p.toString(), p);
        } catch (NoSuchFileException e) {
            throw ProfileFile.fault(p.toString(), 1, 1, Phrase.PROFILE_NOT_FOUND.arg());
        } catch (IOException e) {
            throw ProfileFile.fault(p.toString(), 1, 1, Phrase.reason(e));
        }
    }

    public static MachineProfile read(ProfileFile f, Tables data) throws TableException {
        return read(f, data, TableSource.builtIn(), null);
    }

    /**
     * Reads a profile. Its control comes from {@code control} when not null, else from its
     * {@code control} key (default thesis-2004, the control gcnc began with), among {@code tables}.
     */
    public static MachineProfile read(ProfileFile f, Tables data, TableSource tables, String control)
            throws TableException {
        return read(f, data, tables, control, java.util.Optional.empty(), false);
    }

    /** {@link #read(ProfileFile, Tables, TableSource, String)} with the offsets file {@code offsets} (else offsets.file). */
    public static MachineProfile read(ProfileFile f, Tables data, TableSource tables, String control,
                                      java.util.Optional<Path> offsets, boolean newOffsets) throws TableException {
        ProfileKeys.check(f);
        Control c = control(f, tables, control);
        String noPoint = f.choice("input.no_point", c.noPointLiteral() ? "literal" : "increment", "literal", "increment");
        boolean literal = noPoint.equals("literal");
        Units units = switch (f.choice("units", "", "mm", "inch")) {
            case "mm" -> Units.MM;
            case "inch" -> Units.INCH;
            default -> c.powerUpUnits().orElse(Units.MM);
        };
        boolean chuckByProgram = f.choice("chuck.driven_by", c.chuckByProgram() ? "program" : "operator",
                "program", "operator").equals("program");
        Blending.read(f, c); // checked here, at the key's line; the planner reads it again (Blending.of)
        Axis x = axis(f, "x");
        Axis z = axis(f, "z");
        if (channel(x.galil()) == channel(z.galil())) {
            throw f.fault(f.required("z.galil"), Phrase.SAME_CHANNEL.arg());
        }
        char spindleAxis = spindleAxis(f, x, z);
        boolean counts = f.choice("offsets.unit", "mm", "mm", "counts").equals("counts");
        Point home = position(f, "home", x, z);
        Point machineZero = f.entry("machine_zero").isPresent() ? position(f, "machine_zero", x, z) : home;
        for (int n = 2; n <= 4; n++) {
            if (f.entry("reference." + n).isPresent()) {
                position(f, "reference." + n, x, z); // G30's reference points, read by MachineProfile.reference
            }
        }
        Map<Integer, Point> tools = toolOffsets(f, data, counts, x, z);
        boolean diameterX = f.choice("x.programming", "diameter", "diameter", "radius").equals("diameter");
        ToolWear wear = WearReader.read(f, f.text("name"), tools, counts, x, offsets, newOffsets);
        lengthsInCounts(f, Math.max(x.countsPerMm(), z.countsPerMm()));
        MachineModel model = MachineModel.read(f);
        if (!c.name().equals("thesis-2004")) {
            // the thesis's 2004 record writes OF S/300 unclamped for its G50 S5000 (Table 5.2): a
            // record to reproduce, not a drive to configure (its galil compiles still get E203)
            spindleReachesTopSpeed(f);
        }
        GalilModel galil = GalilModels.load(tables).forProfile(f);
        MachineProfile p = new MachineProfile(f.text("name"), galil, x, z, diameterX,
                literal ? 1 : 0.001, literal ? 1 : 0.0001, home,
                register(f, "rapid.speed", Phrase.REGISTER_SPEED),
                register(f, "feed.max", Phrase.REGISTER_SPEED),
                register(f, "vector.acceleration", 256000, Phrase.REGISTER_ACCELERATION),
                register(f, "vector.deceleration", 256000, Phrase.REGISTER_DECELERATION),
                f.within("spindle.max_rpm", 1, MAX_RPM), f.within("spindle.rpm_per_volt", 1, MAX_RPM), spindleAxis,
                f.choice("tool_post", "front", "front", "rear").equals("rear"),
                workOffsets(f, counts, x, z, model), tools, toolCount(f, tools), outputs(f), feedPerF(f), f, c, units,
                machineZero, chuckByProgram, model, encoder(f, x, z),
                noses(f, counts, x), threadChamfer(f), wear);
        GalilModels.holds(p, f); // channels, speeds, accelerations and outputs the model has (E421-E424)
        MachineIo.read(f, spindleAxis, p.tools(), p.galilModel()); // the spindle drive, turret, homing (E424, E430-E434)
        return p;
    }

    /** The most volts the OF output gives (Galil's +-10 V analog output; the backend clamps 9.998..10 with E204). */
    private static final double OF_VOLTS = 10.0;

    /** The most the backend writes on OF (Galil's 9.998 V); above it, up to 10 V, it clamps with E204. */
    private static final double OF_VOLTS_CLAMP = 9.998;

    /**
     * A profile whose own top speed its spindle drive could not be given: {@code spindle.max_rpm}
     * over {@code spindle.rpm_per_volt} is more than the OF output's 10 V, so every program that
     * runs the spindle at the machine's top speed would be E203 at compile, after passing check
     * (E410 at rpm_per_volt's line).
     */
    private static void spindleReachesTopSpeed(ProfileFile f) throws TableException {
        double max = f.positive("spindle.max_rpm");
        double gain = f.positive("spindle.rpm_per_volt");
        if (max / gain > OF_VOLTS_CLAMP && max / gain <= OF_VOLTS) {
            // 9.998..10 V: the backend clamps it with E204 at every S that asks for the top speed, a
            // warning of the profile's own making in every program (issue 22): the profile is wrong
            ProfileFile.Entry e = f.required("spindle.rpm_per_volt");
            throw new TableException(f.path(), gcnc.diag.Diagnostic.error(gcnc.diag.Code.E405_SPINDLE_TOP_SPEED_CLAMPED,
                    gcnc.diag.Span.of(e.line(), e.column()), ProfileFile.written(max),
                    ProfileFile.written(Math.rint(max / gain * 10000) / 10000), ProfileFile.written(gain),
                    ProfileFile.written(Math.ceil(max / OF_VOLTS_CLAMP * 1000) / 1000)));
        }
        if (max / gain > OF_VOLTS) {
            ProfileFile.Entry e = f.required("spindle.rpm_per_volt");
            throw new TableException(f.path(), gcnc.diag.Diagnostic.error(gcnc.diag.Code.E410_SPINDLE_TOP_SPEED_VOLTS,
                    gcnc.diag.Span.of(e.line(), e.column()), ProfileFile.written(max),
                    ProfileFile.written(Math.rint(max / gain * 1000) / 1000), ProfileFile.written(gain),
                    ProfileFile.written(Math.ceil(max / OF_VOLTS * 1000) / 1000)));
        }
    }

    /**
     * {@code thread.chamfer_leads} (0 to 100 leads; 0 = a straight pull-out even under M23) and
     * {@code thread.chamfer_angle} (degrees from the Z axis, more than 0 and less than 90): the
     * chamfered pull-out of a G76/G92 pass under Haas M23 (Settings 95 and 96); Haas's shipped
     * values when absent.
     */
    private static ThreadChamfer threadChamfer(ProfileFile f) throws TableException {
        double leads = ThreadChamfer.HAAS.leads();
        double angle = ThreadChamfer.HAAS.angle();
        if (f.entry("thread.chamfer_leads").isPresent()) {
            ProfileFile.Entry e = f.required("thread.chamfer_leads");
            leads = f.number(e);
            if (!(leads >= 0 && leads <= ThreadChamfer.MAX_LEADS)) {
                throw f.fault(e, Phrase.THREAD_CHAMFER_LEADS.with(written(leads), written(ThreadChamfer.MAX_LEADS)));
            }
        }
        if (f.entry("thread.chamfer_angle").isPresent()) {
            ProfileFile.Entry e = f.required("thread.chamfer_angle");
            angle = f.number(e);
            if (!(angle > 0 && angle < 90)) {
                throw f.fault(e, Phrase.THREAD_CHAMFER_ANGLE.with(written(angle)));
            }
        }
        return new ThreadChamfer(leads, angle);
    }

    /** The largest encoder resolution gcnc accepts: 2^20 counts per revolution. */
    private static final int MAX_ENCODER_COUNTS = 1 << 20;

    /**
     * {@code spindle.encoder} (counts per revolution, a whole number 4 to 2^20) and
     * {@code spindle.encoder_axis} (the channel whose main encoder reads it, by default
     * {@code spindle.axis}; not a channel that moves the tool); null when the profile has none.
     */
    private static SpindleEncoder encoder(ProfileFile f, Axis x, Axis z) throws TableException {
        if (f.entry("spindle.encoder").isEmpty()) {
            if (f.entry("spindle.encoder_axis").isPresent()) {
                throw f.fault(f.required("spindle.encoder_axis"),
                        Phrase.ENCODER_AXIS_NEEDS_ENCODER.arg());
            }
            return null;
        }
        ProfileFile.Entry e = f.required("spindle.encoder");
        double counts = f.number(e);
        if (counts != Math.rint(counts) || counts < 4 || counts > MAX_ENCODER_COUNTS) {
            throw f.fault(e, Phrase.ENCODER_COUNTS.with(MAX_ENCODER_COUNTS));
        }
        char channel = channelLetter(f, "spindle.encoder_axis", f.text("spindle.axis", "C"));
        for (Axis a : new Axis[] {x, z}) {
            if (channel(channel) == channel(a.galil())) {
                throw f.fault(f.entry("spindle.encoder_axis").orElse(e), Phrase.ENCODER_ON_TOOL_AXIS.with(channel,
                        a == x ? "X" : "Z", a == x ? "x" : "z", a.galil()));
            }
        }
        return new SpindleEncoder((int) counts, channel);
    }

    /** The control the profile names (or {@code override}); a fault in it is also shown at the profile's key. */
    private static Control control(ProfileFile f, TableSource tables, String override) throws TableException {
        String name = override != null ? override : f.text("control", "thesis-2004");
        try {
            return ControlLoader.load(name, tables);
        } catch (TableException e) {
            // a fault of its own code (a file too large, E404) is shown as it is, at the control's file
            if (override == null && f.entry("control").isPresent() && e.diagnostic().code() == gcnc.diag.Code.E400_TABLE) {
                throw f.fault(f.required("control"), Phrase.CONTROL_FAULT.with(name,
                        e.path() + ":" + e.diagnostic().span().line() + ":" + e.diagnostic().span().column(),
                        e.diagnostic().args().isEmpty() ? "" : e.diagnostic().args().get(0)));
            }
            throw e;
        }
    }

    private static double feedPerF(ProfileFile f) throws TableException {
        if (f.entry("feed.per_f").isEmpty()) {
            return 0;
        }
        return f.within("feed.per_f", MIN_PER_F, MAX_PER_F);
    }

    private static Axis axis(ProfileFile f, String a) throws TableException {
        char letter = channelLetter(f, a + ".galil", null);
        double perMm = f.within(a + ".counts_per_mm", MIN_COUNTS_PER_MM, MAX_COUNTS_PER_MM);
        double perInch = f.entry(a + ".counts_per_inch").isPresent()
                ? f.within(a + ".counts_per_inch", MIN_COUNTS_PER_MM * 25.4, MAX_COUNTS_PER_MM * 25.4) : perMm * 25.4;
        double sign = f.number(a + ".sign", 1);
        if (sign != 1 && sign != -1) {
            throw f.fault(f.required(a + ".sign"), Phrase.SIGN.with(a));
        }
        ProfileFile.Entry te = f.required(a + ".travel");
        double[] travel = f.pair(te);
        if (travel[0] >= travel[1]) {
            throw f.fault(te, Phrase.TRAVEL_ORDER.with(a, "min, max"));
        }
        for (double end : travel) {
            if (Math.abs(end * perMm) > REGISTER_MAX) {
                throw f.fault(te, Phrase.TRAVEL_REGISTER.with(a, written(end),
                        written(Math.rint(end * perMm))));
            }
        }
        return new Axis(letter, perMm, perInch, (int) sign, travel[0] * perMm, travel[1] * perMm);
    }

    /** One Galil channel letter; {@code otherwise} when the key is absent (null: required). */
    private static char channelLetter(ProfileFile f, String key, String otherwise) throws TableException {
        String letter = otherwise == null ? f.text(key) : f.text(key, otherwise);
        if (!letter.matches("[A-HXYZW]")) {
            throw f.fault(f.required(key), Phrase.CHANNEL_LETTER.with(key, "A-H, X, Y, Z, W"));
        }
        return letter.charAt(0);
    }

    /** The spindle's OF channel, which cannot be one of the two that move the tool. */
    private static char spindleAxis(ProfileFile f, Axis x, Axis z) throws TableException {
        char s = channelLetter(f, "spindle.axis", "C");
        for (Axis a : new Axis[] {x, z}) {
            if (channel(s) == channel(a.galil())) {
                throw f.fault(f.required("spindle.axis"), Phrase.SPINDLE_ON_TOOL_AXIS.with(s,
                        a == x ? "X" : "Z", a == x ? "x" : "z", a.galil()));
            }
        }
        return s;
    }

    /** A Galil channel's number: X, Y, Z, W are the first four channels, A, B, C, D. */
    private static int channel(char letter) {
        int xyzw = "XYZW".indexOf(letter);
        return xyzw >= 0 ? xyzw : letter - 'A';
    }

    /**
     * A machine position {@code x, z} in mm (home, machine_zero), in counts. It must be inside the
     * travel: the machine cannot start at, or return to, a place its axes cannot reach.
     */
    private static Point position(ProfileFile f, String key, Axis x, Axis z) throws TableException {
        ProfileFile.Entry e = f.required(key);
        double[] v = f.pair(e);
        inTravel(f, e, "x", v[0]);
        inTravel(f, e, "z", v[1]);
        return new Point(v[0] * x.countsPerMm(), v[1] * z.countsPerMm());
    }

    private static void inTravel(ProfileFile f, ProfileFile.Entry e, String axis, double mm) throws TableException {
        double[] travel = f.pair(axis + ".travel");
        if (mm < travel[0] || mm > travel[1]) {
            throw f.fault(e, Phrase.OUTSIDE_TRAVEL.with(e.key(), axis.toUpperCase(), written(mm), axis,
                    written(travel[0]), written(travel[1])));
        }
    }

    /**
     * A value the backend writes into a 32-bit Galil register (VS, VA, VD): below 1 it rounds to
     * 0, which the controller refuses, above 2^31 - 1 it does not fit. Either way every move, or
     * the program's header, would fail at a line of the program.
     */
    private static double register(ProfileFile f, String key, Phrase what) throws TableException {
        ProfileFile.Entry e = f.required(key);
        double v = f.positive(key);
        if (v < 1 || v > REGISTER_MAX) {
            throw f.fault(e, what.with(key, written(REGISTER_MAX), written(v)));
        }
        return v;
    }

    private static double register(ProfileFile f, String key, double otherwise, Phrase what) throws TableException {
        return f.entry(key).isPresent() ? register(f, key, what) : otherwise;
    }

    /**
     * {@code work.G54 = x, z}, or {@code x, face} ({@code face} alone: X 0): Z on the face of the blank (chuck.face_z + the
     * stick-out, in mm whatever offsets.unit says), which a run's own blank moves
     * ({@link MachineProfile#withStickout}); {@link MachineModel#workZero} checked it has a chuck and a blank.
     */
    private static Map<Integer, Point> workOffsets(ProfileFile f, boolean counts, Axis x, Axis z, MachineModel model)
            throws TableException {
        Map<Integer, Point> work = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("work.")) {
            int g = Integer.parseInt(e.key().substring("work.G".length())); // ProfileKeys: work.G54 .. work.G59
            if (model.workZero().atFace().contains(g)) {
                String[] xz = e.value().split(",", -1);
                double xValue = xz.length == 1 ? 0 : f.number(e, xz[0]);
                double faceMm = model.chuck().orElseThrow().faceZ() + model.workZero().stickout();
                work.put(g, new Point(counts ? xValue : xValue * x.countsPerMm(), faceMm * z.countsPerMm()));
            } else {
                work.put(g, offset(f, e, counts, x, z));
            }
        }
        for (int g = 54; g <= 59; g++) {
            work.putIfAbsent(g, Point.ORIGIN);
        }
        return work;
    }

    private static Map<Integer, Point> toolOffsets(ProfileFile f, Tables data, boolean counts, Axis x, Axis z)
            throws TableException {
        Map<Integer, Point> tools = new HashMap<>();
        String toolTable = f.choice("tools.table", "none", "none", "thesis");
        if (toolTable.equals("thesis")) {
            List<Offset> t8 = data.toolOffsets();
            for (int i = 0; i < t8.size(); i++) {
                tools.put(i + 1, offset(new double[] {t8.get(i).x(), t8.get(i).z()}, counts, x, z));
            }
        }
        Map<Integer, ProfileFile.Entry> seen = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("tool.")) {
            int n = numberOf(f, e, "tool.", seen);
            if (n < 1) {
                throw f.faultAtKey(e, Phrase.TOOL_OFFSET_FROM_ONE.with(e.key()));
            }
            tools.put(n, offset(f, e, counts, x, z));
        }
        if (f.entry("tools.offsets").isPresent()) {
            int n = whole(f, "tools.offsets", Phrase.TOOLS_OFFSETS_RANGE);
            for (int i = 1; i <= n; i++) {
                tools.putIfAbsent(i, Point.ORIGIN);
            }
        }
        return tools;
    }

    /**
     * {@code nose.N = RADIUS, TIP}: the nose radius (mm, or counts with offsets.unit = counts; at
     * least 0, below 25 mm) and the tip direction (a whole number 0 to 9) of tool offset N
     * (docs/nose-compensation.md). The radius is turned into counts along X, as arcs are.
     */
    private static Map<Integer, Nose> noses(ProfileFile f, boolean counts, Axis x) throws TableException {
        Map<Integer, Nose> noses = new HashMap<>();
        Map<Integer, ProfileFile.Entry> seen = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("nose.")) {
            int n = numberOf(f, e, "nose.", seen);
            if (n < 1) {
                throw f.faultAtKey(e, Phrase.NOSE_FROM_ONE.with(e.key()));
            }
            double[] v = f.pair(e);
            double mm = counts ? v[0] / x.countsPerMm() : v[0];
            if (!(mm >= 0) || mm >= 25) {
                throw f.fault(e, Phrase.NOSE_RADIUS.with(written(v[0]), e.key()));
            }
            if (v[1] != Math.rint(v[1]) || v[1] < 0 || v[1] > 9) {
                throw f.fault(e, Phrase.TIP_DIRECTION.with(written(v[1]), e.key()));
            }
            noses.put(n, new Nose(mm * x.countsPerMm(), (int) v[1]));
        }
        // a station of the tool table that names its nose gives it to the offset of its number (T0303)
        for (ToolTable.Station s : ToolTable.read(f).values()) {
            if (!s.hasNose()) {
                continue;
            }
            if (seen.containsKey(s.number())) {
                throw f.faultAtKey(s.entry(), Phrase.NOSE_TWICE.with(s.number()));
            }
            double radius = Double.isNaN(s.noseRadius()) ? 0 : s.noseRadius();
            double mm = counts ? radius / x.countsPerMm() : radius;
            noses.put(s.number(), new Nose(mm * x.countsPerMm(), Math.max(0, s.tip())));
        }
        return noses;
    }

    /** Turret stations: T numbers 1..count; by default the highest tool offset number. */
    private static int toolCount(ProfileFile f, Map<Integer, Point> tools) throws TableException {
        if (f.entry("tools.count").isEmpty()) {
            return tools.keySet().stream().mapToInt(i -> i).max().orElse(1);
        }
        return whole(f, "tools.count", Phrase.TOOLS_COUNT_RANGE);
    }

    /** A count of tools or offsets, which T's two-digit fields bound to 1..99. */
    private static int whole(ProfileFile f, String key, Phrase rule) throws TableException {
        ProfileFile.Entry e = f.required(key);
        double n = f.number(e);
        if (n != Math.rint(n) || n < 1 || n > 99) {
            throw f.fault(e, rule.with(written(n)));
        }
        return (int) n;
    }

    private static Map<Integer, List<String>> outputs(ProfileFile f) throws TableException {
        Map<Integer, List<String>> outputs = new HashMap<>();
        Map<Integer, ProfileFile.Entry> seen = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("m.")) {
            int m = numberOf(f, e, "m.", seen);
            List<String> dirs = new ArrayList<>();
            for (String d : e.value().split(",")) {
                String t = d.trim();
                if (!t.matches("(SB|CB) ?[0-9]{1,3}")) {
                    throw f.fault(e, Phrase.OUTPUT_DIRECTIVES.with(t));
                }
                dirs.add(t);
            }
            outputs.put(m, List.copyOf(dirs));
        }
        return outputs;
    }

    /**
     * The number that ends a numbered key ({@code tool.3}, {@code m.03}; ProfileKeys has checked
     * that it is digits). Two keys for one number are a fault rather than one silently winning.
     */
    private static int numberOf(ProfileFile f, ProfileFile.Entry e, String prefix, Map<Integer, ProfileFile.Entry> seen)
            throws TableException {
        int n = Integer.parseInt(e.key().substring(prefix.length()));
        ProfileFile.Entry before = seen.putIfAbsent(n, e);
        if (before != null) {
            throw f.faultAtKey(e, Phrase.NUMBER_AGAIN.with(e.key(), n, before.key(), before.line()));
        }
        return n;
    }

    private static Point offset(double[] v, boolean counts, Axis x, Axis z) {
        return counts ? new Point(v[0], v[1]) : new Point(v[0] * x.countsPerMm(), v[1] * z.countsPerMm());
    }

    /** The simulator's lengths in mm (chuck, tailstock, blank, spindle centre), each of which becomes counts. */
    private static final String[] LENGTHS = {"sim.centre_x", "chuck.face_z", "chuck.jaw_diameter", "chuck.jaw_length",
        "chuck.diameter", "tailstock.centre_z", "tailstock.quill_diameter", "stock.diameter", "stock.length",
        "stock.stickout"};

    /** Each of {@link #LENGTHS} given must fit a 32-bit register in counts (E403 at its value), as positions do. */
    private static void lengthsInCounts(ProfileFile f, double perMm) throws TableException {
        for (String key : LENGTHS) {
            if (f.entry(key).isPresent()) {
                ProfileFile.Entry e = f.required(key);
                double mm = f.number(e);
                if (Math.abs(mm * perMm) > REGISTER_MAX) {
                    throw f.fault(e, gcnc.diag.Code.E403_PROFILE_COUNTS_OVERFLOW, key, written(mm),
                            written(Math.rint(mm * perMm)), written(REGISTER_MAX));
                }
            }
        }
    }

    /**
     * An offset as {@link #offset}, which must fit a 32-bit position register in counts (E403 at
     * its value): an offset past it would overflow every position it is added to.
     */
    private static Point offset(ProfileFile f, ProfileFile.Entry e, boolean counts, Axis x, Axis z)
            throws TableException {
        double[] v = f.pair(e);
        Point p = offset(v, counts, x, z);
        double[] inCounts = {p.x(), p.z()};
        for (int k = 0; k < 2; k++) {
            if (Math.abs(inCounts[k]) > REGISTER_MAX) {
                throw f.fault(e, gcnc.diag.Code.E403_PROFILE_COUNTS_OVERFLOW, e.key(), written(v[k]),
                        written(Math.rint(inCounts[k])), written(REGISTER_MAX));
            }
        }
        return p;
    }
}
