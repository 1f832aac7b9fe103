package gcnc.machine;

import static gcnc.machine.ProfileFile.written;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Phrase;
import gcnc.diag.Span;
import gcnc.ir.Point;
import gcnc.tables.TableException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;

/**
 * Reads the wear offsets of a profile ({@link ToolWear}): its own {@code wear.N = X, Z} lines, its
 * limits {@code wear.max_step} and {@code wear.max_total}, and the offsets file, named by
 * {@code --offsets FILE} or else by the profile's {@code offsets.file} (a path relative to the
 * profile). An offsets file is {@code wear.N} lines in the profile's own syntax ({@link ProfileFile});
 * a {@code wear.N} in it replaces the profile's for that N. Every value is checked here, at its
 * file, line and column (docs/profiles.md, "Wear offsets").
 */
public final class WearReader {
    private WearReader() {
    }

    /**
     * The wear of a profile being loaded: {@code f} the profile, {@code tools} its tool offsets (a
     * wear needs a tool offset of its number), {@code offsets} the file {@code --offsets} names;
     * with {@code mayBeAbsent} an offsets file that does not exist yet reads as empty (the test cut creates it).
     */
    static ToolWear read(ProfileFile f, String profileName, Map<Integer, Point> tools, boolean counts, Axis x,
                         Optional<Path> offsets, boolean mayBeAbsent) throws TableException {
        double perMm = counts ? x.countsPerMm() : 1;
        double step = f.entry("wear.max_step").isPresent() ? f.positive("wear.max_step") : ToolWear.DEFAULT_STEP_MM * perMm;
        double total = f.entry("wear.max_total").isPresent() ? f.positive("wear.max_total")
                : ToolWear.DEFAULT_TOTAL_MM * perMm;
        if (step > total) {
            ProfileFile.Entry e = f.entry("wear.max_step").or(() -> f.entry("wear.max_total")).orElseThrow();
            throw f.fault(e, Code.E454_WEAR_STEP_ABOVE_TOTAL, written(step), written(total));
        }
        Map<Integer, ToolWear.Wear> wear = new HashMap<>();
        entries(f, profileName, tools, total, counts ? "counts" : "mm", wear);
        Optional<Path> file = offsets.isPresent() ? offsets : named(f);
        if (file.isPresent() && !(mayBeAbsent && !Files.exists(file.get()))) {
            ProfileFile o = offsetsFile(file.get(), offsets.isPresent() ? null : f.required("offsets.file"), f);
            for (ProfileFile.Entry e : o.keys().stream().map(k -> o.entry(k).orElseThrow()).toList()) {
                if (!e.key().matches("wear\\.[0-9]{1,2}")) {
                    throw new TableException(o.path(), Diagnostic.error(Code.E450_OFFSETS_FILE_KEY,
                            Span.of(e.line(), e.keyColumn()), e.key()));
                }
            }
            Map<Integer, ToolWear.Wear> fromFile = new HashMap<>();
            entries(o, profileName, tools, total, counts ? "counts" : "mm", fromFile);
            wear.putAll(fromFile);
        }
        return new ToolWear(wear, counts, step, total, file.map(Path::toString));
    }

    /** The profile's {@code offsets.file}, resolved against the profile's folder. */
    private static Optional<Path> named(ProfileFile f) {
        return f.entry("offsets.file").map(e -> {
            Path p = Path.of(e.value());
            Path folder = Path.of(f.path()).toAbsolutePath().getParent();
            return p.isAbsolute() || folder == null ? p : folder.resolve(p).normalize();
        });
    }

    /** Where the offsets file of a profile is: {@code --offsets} when given, else its {@code offsets.file}. */
    public static Optional<Path> file(ProfileFile f, Optional<Path> offsets) {
        return offsets.isPresent() ? offsets : named(f);
    }

    /**
     * The offsets file parsed; missing, E455 at the profile's {@code offsets.file} value ({@code at}),
     * or at the file itself when {@code --offsets} named it.
     */
    private static ProfileFile offsetsFile(Path p, ProfileFile.Entry at, ProfileFile profile) throws TableException {
        if (!Files.exists(p)) {
            if (at != null) {
                throw profile.fault(at, Code.E455_OFFSETS_FILE_MISSING, p.toString());
            }
            throw new TableException(p.toString(), Diagnostic.error(Code.E455_OFFSETS_FILE_MISSING, Span.of(1, 1),
                    p.toString()));
        }
        return ProfileFile.parse(p.toString(), ProfileLoader.readFile(p));
    }

    /** Every {@code wear.N} of {@code f} into {@code out}, each checked (number, values, offset, limit). */
    private static void entries(ProfileFile f, String profileName, Map<Integer, Point> tools, double total,
                                String unit, Map<Integer, ToolWear.Wear> out) throws TableException {
        Map<Integer, ProfileFile.Entry> seen = new HashMap<>();
        for (ProfileFile.Entry e : f.withPrefix("wear.")) {
            if (!e.key().matches("wear\\.[0-9]{1,2}")) {
                continue; // wear.max_step, wear.max_total: the limits
            }
            int n = Integer.parseInt(e.key().substring("wear.".length()));
            ProfileFile.Entry before = seen.putIfAbsent(n, e);
            if (before != null) {
                throw f.faultAtKey(e, Phrase.NUMBER_AGAIN.with(e.key(), n, before.key(), before.line()));
            }
            if (n < 1) {
                throw f.faultAtKey(e, Phrase.WEAR_FROM_ONE.with(e.key()));
            }
            String[] parts = e.value().split(",", -1);
            if (parts.length == 3) {
                throw f.fault(e, Code.E451_WEAR_NOSE_NOT_SUPPORTED_YET, e.key(), e.value());
            }
            double[] v = f.pair(e);
            if (!tools.containsKey(n)) {
                throw new TableException(f.path(), Diagnostic.error(Code.E452_WEAR_NO_TOOL_OFFSET,
                        Span.of(e.line(), e.keyColumn()), e.key(), profileName, n));
            }
            for (int k = 0; k < 2; k++) {
                if (Math.abs(v[k]) > total) {
                    throw f.fault(e, Code.E453_WEAR_BEYOND_TOTAL, e.key(), k == 0 ? "X" : "Z", written(v[k]),
                            unit, written(total));
                }
            }
            out.put(n, new ToolWear.Wear(v[0], v[1], f.path(), e.line()));
        }
    }
}
