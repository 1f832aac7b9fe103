package gcnc.machine;

import static gcnc.machine.ProfileFile.written;

import gcnc.diag.Phrase;
import gcnc.tables.TableException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;

/**
 * The tool table a shop writes for its turret, one line per station (docs/profiles.md, "Tool
 * table"): what the tool is and its size, then any of its nose radius and tip direction (for
 * G41/G42, as {@code nose.N} gives them), how deep it reaches, a drill's point angle and the side
 * of the spindle centreline it works on:
 *
 * <pre>
 * station.1 = turn C 12.7, nose 0.8, tip 3     # CNMG 12 on a right-hand holder
 * station.4 = drill 10                          # on the centreline, 118° point
 * station.9 = part 3, reach 32, nose 0.2, tip 3
 * station.2 = turn D 12.7, side -x              # a gang lathe: the tool works on the -X side
 * </pre>
 *
 * Kinds: {@code turn} with an ISO insert letter (C D V W T S) and the inscribed circle,
 * {@code thread} and the edge, {@code groove} and {@code part} and the blade's width,
 * {@code bore} and the bar's diameter, {@code drill}, {@code centre} (centre drill, by its pilot)
 * and {@code tap} and the diameter; {@code puller}, a bar puller, has no size (it cuts nothing). Outlines come from {@link ToolLibrary}. A bad line is a fault at
 * its line (E400) naming what is wrong, never a station silently left at the default.
 */
final class ToolTable {
    /**
     * One station: its outline, and the nose it gives its tool offset (offset N of station N, as
     * T0303 pairs them) when it names one.
     *
     * @param noseRadius the nose radius as written (mm, or counts with offsets.unit = counts), NaN if none
     * @param tip        the tip direction 0-9, or -1 if none
     */
    record Station(int number, MachineModel.ToolOutline outline, double noseRadius, int tip, ProfileFile.Entry entry) {
        boolean hasNose() {
            return !Double.isNaN(noseRadius) || tip >= 0;
        }
    }

    private ToolTable() {
    }

    /**
     * Every {@code station.N} of the profile and of the tool table file it names ({@code tools.file},
     * beside the profile), checked; a fault in the file is at its own line.
     */
    static Map<Integer, Station> read(ProfileFile f) throws TableException {
        Map<Integer, Station> out = new HashMap<>();
        Map<Integer, ProfileFile.Entry> seen = new HashMap<>();
        read(f, out, seen);
        Optional<ProfileFile.Entry> ref = f.entry("tools.file");
        if (ref.isPresent()) {
            read(file(f, ref.get()), out, seen);
        }
        return out;
    }

    /**
     * The tool table file a profile names: a path relative to the profile's folder, holding only
     * {@code station.N} lines (and comments), so that a shop keeps its turret apart from its machine.
     */
    private static ProfileFile file(ProfileFile f, ProfileFile.Entry ref) throws TableException {
        Path p = Path.of(f.path()).resolveSibling(ref.value().trim());
        if (!Files.isRegularFile(p)) {
            throw f.fault(ref, Phrase.TOOLS_FILE_MISSING.with(p.toString()));
        }
        ProfileFile t = ProfileFile.parse(p.toString(), ProfileLoader.readFile(p));
        for (String key : t.keys()) {
            if (!key.startsWith("station.") || !ProfileKeys.known(key)) {
                throw t.faultAtKey(t.required(key), Phrase.TOOLS_FILE_KEYS.with(key));
            }
        }
        return t;
    }

    private static void read(ProfileFile f, Map<Integer, Station> out, Map<Integer, ProfileFile.Entry> seen)
            throws TableException {
        for (ProfileFile.Entry e : f.withPrefix("station.")) {
            String id = e.key().substring("station.".length()); // ProfileKeys: station.<1-2 digits>
            int n = Integer.parseInt(id);
            if (n < 1) {
                throw f.faultAtKey(e, Phrase.STATION_FROM_ONE.with(e.key()));
            }
            ProfileFile.Entry before = seen.putIfAbsent(n, e);
            if (before != null) {
                throw f.faultAtKey(e, Phrase.NUMBER_AGAIN.with(e.key(), n, before.key(), before.line()));
            }
            out.put(n, station(f, e, n));
        }
    }

    private static Station station(ProfileFile f, ProfileFile.Entry e, int n) throws TableException {
        String[] items = e.value().split(",", -1);
        String[] head = items[0].trim().split("\\s+");
        String kind = head[0].toLowerCase(Locale.ROOT);
        boolean turn = kind.equals("turn");
        boolean puller = kind.equals("puller");
        if (head.length != (turn ? 3 : puller ? 1 : 2)) {
            throw form(f, e);
        }
        double size = puller ? 1 : f.number(e, head[head.length - 1]);
        if (!(size > 0)) {
            throw form(f, e);
        }
        double nose = Double.NaN;
        int tip = -1;
        double reach = Double.NaN;
        double angle = 118;
        int side = 1;
        for (int i = 1; i < items.length; i++) {
            String[] kv = items[i].trim().split("\\s+");
            if (kv.length != 2) {
                throw form(f, e);
            }
            String word = kv[0].toLowerCase(Locale.ROOT);
            switch (word) {
                case "side" -> {
                    if (!kv[1].equalsIgnoreCase("-x") && !kv[1].equalsIgnoreCase("+x")) {
                        throw form(f, e);
                    }
                    side = kv[1].startsWith("-") ? -1 : 1;
                }
                case "nose" -> {
                    nose = f.number(e, kv[1]);
                    if (!(nose >= 0) || nose >= 25) {
                        throw f.fault(e, Phrase.NOSE_RADIUS.with(written(nose), e.key()));
                    }
                }
                case "tip" -> {
                    double t = f.number(e, kv[1]);
                    if (t != Math.rint(t) || t < 0 || t > 9) {
                        throw f.fault(e, Phrase.TIP_DIRECTION.with(written(t), e.key()));
                    }
                    tip = (int) t;
                }
                case "reach" -> {
                    reach = f.number(e, kv[1]);
                    if (!(reach > 0)) {
                        throw form(f, e);
                    }
                }
                case "angle" -> {
                    angle = f.number(e, kv[1]);
                    if (!kind.equals("drill") || !(angle >= 60 && angle < 180)) {
                        throw f.fault(e, Phrase.STATION_ANGLE.with(e.key(), written(angle)));
                    }
                }
                default -> throw form(f, e);
            }
        }
        String name = items[0].trim().replaceAll("\\s+", " ");
        MachineModel.ToolOutline outline = switch (kind) {
            case "turn" -> ToolLibrary.turning(head[1].toUpperCase(Locale.ROOT), size, name);
            case "thread" -> ToolLibrary.thread(size, name);
            case "groove" -> ToolLibrary.blade(false, size, reach, name);
            case "part" -> ToolLibrary.blade(true, size, reach, name);
            case "bore" -> ToolLibrary.boringBar(size, name);
            case "drill" -> ToolLibrary.drill(size, angle, reach, name);
            case "centre", "center" -> ToolLibrary.centreDrill(size, name);
            case "tap" -> ToolLibrary.tap(size, reach, name);
            case "puller" -> ToolLibrary.puller(name);
            default -> null;
        };
        if (outline == null) {
            throw form(f, e);
        }
        return new Station(n, outline.with(name, side), nose, tip, e);
    }

    private static TableException form(ProfileFile f, ProfileFile.Entry e) {
        return f.fault(e, Phrase.STATION_FORM.with(e.key(), e.value().trim()));
    }
}
