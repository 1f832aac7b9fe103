package gcnc.machine;

import static gcnc.machine.ProfileFile.written;

import gcnc.diag.Phrase;
import gcnc.ir.Point;
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
    static final double REGISTER_MAX = Integer.MAX_VALUE;
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
        Axis x = ProfileAxes.axis(f, "x");
        Axis z = ProfileAxes.axis(f, "z");
        if (Plane.channel(x.galil()) == Plane.channel(z.galil())) {
            throw f.fault(f.required("z.galil"), Phrase.SAME_CHANNEL.arg());
        }
        char spindleAxis = ProfileAxes.spindleAxis(f, x, z);
        boolean counts = f.choice("offsets.unit", "mm", "mm", "counts").equals("counts");
        Point home = ProfileAxes.position(f, "home", x, z);
        Point machineZero = f.entry("machine_zero").isPresent() ? ProfileAxes.position(f, "machine_zero", x, z) : home;
        for (int n = 2; n <= 4; n++) {
            if (f.entry("reference." + n).isPresent()) {
                ProfileAxes.position(f, "reference." + n, x, z); // G30's reference points, read by MachineProfile.reference
            }
        }
        Map<Integer, Point> tools = ProfileOffsets.toolOffsets(f, data, counts, x, z);
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
                ProfileOffsets.workOffsets(f, counts, x, z, model), tools, ProfileOffsets.toolCount(f, tools), outputs(f), feedPerF(f), f, c, units,
                machineZero, chuckByProgram, model, ProfileAxes.encoder(f, x, z),
                ProfileOffsets.noses(f, counts, x), threadChamfer(f), wear);
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

    private static Map<Integer, List<String>> outputs(ProfileFile f) throws TableException {
        Map<Integer, List<String>> outputs = new HashMap<>();
        Map<Integer, ProfileFile.Entry> seen = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("m.")) {
            int m = ProfileOffsets.numberOf(f, e, "m.", seen);
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

}
