package gcnc.machine;

import gcnc.ir.Point;
import gcnc.tables.Offset;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Reads and validates a machine profile. {@code --machine NAME} finds
 * {@code machines/NAME.machine} among the tables; anything with a '/' or ending in
 * {@code .machine} is a file path. Every fault names the file, line and column.
 */
public final class ProfileLoader {
    public static final String DEFAULT = "generic";

    private ProfileLoader() {
    }

    public static MachineProfile load(String nameOrPath, TableSource tables, Tables data) throws TableException {
        return load(nameOrPath, tables, data, null);
    }

    /** Loads a profile; {@code control}, when not null, replaces the control the profile names. */
    public static MachineProfile load(String nameOrPath, TableSource tables, Tables data, String control)
            throws TableException {
        ProfileFile f;
        if (nameOrPath.contains("/") || nameOrPath.endsWith(".machine")) {
            Path p = Path.of(nameOrPath);
            try {
                f = ProfileFile.parse(p.toString(), Files.readString(p, StandardCharsets.UTF_8));
            } catch (NoSuchFileException e) {
                throw ProfileFile.fault(p.toString(), 1, 1, "machine profile not found");
            } catch (IOException e) {
                throw ProfileFile.fault(p.toString(), 1, 1, e.getMessage());
            }
        } else {
            String name = "machines/" + nameOrPath + ".machine";
            f = ProfileFile.parse(tables.describe(name), tables.read(name));
        }
        return read(f, data, tables, control);
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
        String controlName = control != null ? control : f.text("control", "thesis-2004");
        Control c;
        try {
            c = ControlLoader.load(controlName, tables);
        } catch (TableException e) {
            if (control == null && f.entry("control").isPresent()) {
                throw f.fault(f.required("control"), "control '" + controlName + "': " + e.getMessage());
            }
            throw e;
        }
        String noPoint = f.choice("input.no_point", c.noPointLiteral() ? "literal" : "increment", "literal", "increment");
        boolean literal = noPoint.equals("literal");
        Units units = switch (f.choice("units", "", "mm", "inch")) {
            case "mm" -> Units.MM;
            case "inch" -> Units.INCH;
            default -> c.powerUpUnits().orElse(Units.MM);
        };
        boolean chuckByProgram = f.choice("chuck.driven_by", c.chuckByProgram() ? "program" : "operator",
                "program", "operator").equals("program");
        Axis x = axis(f, "x");
        Axis z = axis(f, "z");
        boolean counts = f.choice("offsets.unit", "mm", "mm", "counts").equals("counts");
        double[] home = f.pair("home");
        Point homeCounts = new Point(home[0] * x.countsPerMm(), home[1] * z.countsPerMm());

        Map<Integer, Point> work = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("work.")) {
            String g = e.key().substring(5);
            int n = switch (g) {
                case "G54" -> 54; case "G55" -> 55; case "G56" -> 56;
                case "G57" -> 57; case "G58" -> 58; case "G59" -> 59;
                default -> throw f.fault(e, "work offsets are work.G54 .. work.G59, not '" + e.key() + "'");
            };
            work.put(n, offset(f.pair(e), counts, x, z));
        }
        for (int g = 54; g <= 59; g++) {
            work.putIfAbsent(g, Point.ORIGIN);
        }

        Map<Integer, Point> tools = new HashMap<>();
        String toolTable = f.choice("tools.table", "none", "none", "thesis");
        if (toolTable.equals("thesis")) {
            List<Offset> t8 = data.toolOffsets();
            for (int i = 0; i < t8.size(); i++) {
                tools.put(i + 1, offset(new double[] {t8.get(i).x(), t8.get(i).z()}, counts, x, z));
            }
        }
        for (ProfileFile.Entry e : f.withPrefix("tool.")) {
            int n = positiveInt(f, e, e.key().substring(5));
            tools.put(n, offset(f.pair(e), counts, x, z));
        }
        if (f.entry("tools.offsets").isPresent()) {
            double n = f.positive("tools.offsets");
            if (n != Math.rint(n) || n > 99) {
                throw f.fault(f.required("tools.offsets"), "tools.offsets is a whole number of offsets, 1 to 99");
            }
            for (int i = 1; i <= n; i++) {
                tools.putIfAbsent(i, Point.ORIGIN);
            }
        }
        int toolCount = (int) f.number("tools.count", tools.keySet().stream().mapToInt(i -> i).max().orElse(1));
        Point machineZero = homeCounts;
        if (f.entry("machine_zero").isPresent()) {
            double[] mz = f.pair("machine_zero");
            machineZero = new Point(mz[0] * x.countsPerMm(), mz[1] * z.countsPerMm());
        }

        Map<Integer, List<String>> outputs = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("m.")) {
            int m = positiveIntOrZero(f, e, e.key().substring(2));
            List<String> dirs = new ArrayList<>();
            for (String d : e.value().split(",")) {
                String t = d.trim();
                if (!t.matches("(SB|CB) ?[0-9]{1,3}")) {
                    throw f.fault(e, "output directives are SBn or CBn, not '" + t + "'");
                }
                dirs.add(t);
            }
            outputs.put(m, List.copyOf(dirs));
        }
        String spindleAxis = f.text("spindle.axis", "C");
        if (!spindleAxis.matches("[A-HXYZW]")) {
            throw f.fault(f.required("spindle.axis"), "spindle.axis is one Galil channel letter (A-H, X, Y, Z, W)");
        }
        return new MachineProfile(f.text("name"), f.text("galil.model", "DMC-4020"), x, z,
                f.choice("x.programming", "diameter", "diameter", "radius").equals("diameter"),
                literal ? 1 : 0.001, literal ? 1 : 0.0001, homeCounts,
                f.positive("rapid.speed"), f.positive("feed.max"),
                f.number("vector.acceleration", 256000), f.number("vector.deceleration", 256000),
                f.positive("spindle.max_rpm"), f.positive("spindle.rpm_per_volt"), spindleAxis.charAt(0),
                f.choice("tool_post", "front", "front", "rear").equals("rear"),
                work, tools, toolCount, outputs, feedPerF(f), f, c, units, machineZero, chuckByProgram);
    }

    private static double feedPerF(ProfileFile f) throws TableException {
        if (f.entry("feed.per_f").isEmpty()) {
            return 0;
        }
        return f.positive("feed.per_f");
    }

    private static Axis axis(ProfileFile f, String a) throws TableException {
        String letter = f.text(a + ".galil");
        if (!letter.matches("[A-HXYZW]")) {
            throw f.fault(f.required(a + ".galil"), a + ".galil is one Galil channel letter (A-H, X, Y, Z, W)");
        }
        double perMm = f.positive(a + ".counts_per_mm");
        double perInch = f.number(a + ".counts_per_inch", perMm * 25.4);
        double sign = f.number(a + ".sign", 1);
        if (sign != 1 && sign != -1) {
            throw f.fault(f.required(a + ".sign"), a + ".sign is 1 or -1");
        }
        double[] travel = f.pair(a + ".travel");
        if (travel[0] >= travel[1]) {
            throw f.fault(f.required(a + ".travel"), a + ".travel is 'min, max' with min < max");
        }
        return new Axis(letter.charAt(0), perMm, perInch, (int) sign, travel[0] * perMm, travel[1] * perMm);
    }

    private static Point offset(double[] v, boolean counts, Axis x, Axis z) {
        return counts ? new Point(v[0], v[1]) : new Point(v[0] * x.countsPerMm(), v[1] * z.countsPerMm());
    }

    private static int positiveInt(ProfileFile f, ProfileFile.Entry e, String s) throws TableException {
        int n = positiveIntOrZero(f, e, s);
        if (n < 1) {
            throw f.fault(e, "numbers in '" + e.key() + "' start at 1");
        }
        return n;
    }

    private static int positiveIntOrZero(ProfileFile f, ProfileFile.Entry e, String s) throws TableException {
        try {
            return Integer.parseInt(s);
        } catch (NumberFormatException x) {
            throw f.fault(e, "'" + e.key() + "' must end in a number");
        }
    }
}
