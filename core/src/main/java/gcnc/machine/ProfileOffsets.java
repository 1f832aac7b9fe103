package gcnc.machine;

import static gcnc.machine.ProfileFile.written;

import gcnc.diag.Phrase;
import gcnc.ir.Point;
import gcnc.tables.Offset;
import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The profile's offsets, as {@link ProfileLoader} reads them: the work offsets (G54-G59), the tool
 * offsets and their noses, the turret's station count; each must fit a 32-bit position register in counts.
 */
final class ProfileOffsets {
    private ProfileOffsets() {
    }

    /**
     * {@code work.G54 = x, z}, or {@code x, face} ({@code face} alone: X 0): Z on the face of the blank (chuck.face_z + the
     * stick-out, in mm whatever offsets.unit says), which a run's own blank moves
     * ({@link MachineProfile#withStickout}); {@link MachineModel#workZero} checked it has a chuck and a blank.
     */
    static Map<Integer, Point> workOffsets(ProfileFile f, boolean counts, Axis x, Axis z, MachineModel model)
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

    static Map<Integer, Point> toolOffsets(ProfileFile f, Tables data, boolean counts, Axis x, Axis z)
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
    static Map<Integer, Nose> noses(ProfileFile f, boolean counts, Axis x) throws TableException {
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
    static int toolCount(ProfileFile f, Map<Integer, Point> tools) throws TableException {
        if (f.entry("tools.count").isEmpty()) {
            return tools.keySet().stream().mapToInt(i -> i).max().orElse(1);
        }
        return whole(f, "tools.count", Phrase.TOOLS_COUNT_RANGE);
    }

    /** A count of tools or offsets, which T's two-digit fields bound to 1..99. */
    static int whole(ProfileFile f, String key, Phrase rule) throws TableException {
        ProfileFile.Entry e = f.required(key);
        double n = f.number(e);
        if (n != Math.rint(n) || n < 1 || n > 99) {
            throw f.fault(e, rule.with(written(n)));
        }
        return (int) n;
    }

    /**
     * The number that ends a numbered key ({@code tool.3}, {@code m.03}; ProfileKeys has checked
     * that it is digits). Two keys for one number are a fault rather than one silently winning.
     */
    static int numberOf(ProfileFile f, ProfileFile.Entry e, String prefix, Map<Integer, ProfileFile.Entry> seen)
            throws TableException {
        int n = Integer.parseInt(e.key().substring(prefix.length()));
        ProfileFile.Entry before = seen.putIfAbsent(n, e);
        if (before != null) {
            throw f.faultAtKey(e, Phrase.NUMBER_AGAIN.with(e.key(), n, before.key(), before.line()));
        }
        return n;
    }

    static Point offset(double[] v, boolean counts, Axis x, Axis z) {
        return counts ? new Point(v[0], v[1]) : new Point(v[0] * x.countsPerMm(), v[1] * z.countsPerMm());
    }

    /**
     * An offset as {@link #offset}, which must fit a 32-bit position register in counts (E403 at
     * its value): an offset past it would overflow every position it is added to.
     */
    static Point offset(ProfileFile f, ProfileFile.Entry e, boolean counts, Axis x, Axis z)
            throws TableException {
        double[] v = f.pair(e);
        Point p = offset(v, counts, x, z);
        double[] inCounts = {p.x(), p.z()};
        for (int k = 0; k < 2; k++) {
            if (Math.abs(inCounts[k]) > ProfileLoader.REGISTER_MAX) {
                throw f.fault(e, gcnc.diag.Code.E403_PROFILE_COUNTS_OVERFLOW, e.key(), written(v[k]),
                        written(Math.rint(inCounts[k])), written(ProfileLoader.REGISTER_MAX));
            }
        }
        return p;
    }
}
