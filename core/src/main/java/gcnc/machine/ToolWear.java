package gcnc.machine;

import gcnc.ir.Point;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;

/**
 * The wear offsets of a machine's tool offsets, kept apart from their geometry ({@code tool.N}) as
 * a Fanuc or Haas control keeps its wear page apart from its geometry page: the control moves the
 * tool by geometry + wear (docs/semantics.md, "Wear offsets"). A positive X wear moves the tool away
 * from the spindle centreline (an OD comes out larger by the wear on the diameter, a bore larger
 * too), a positive Z wear moves it toward +Z.
 *
 * @param byOffset    tool offset number (1..99) to its wear, as written: X as the program writes X (a
 *                    diameter where {@code x.programming = diameter}), Z; in the offsets unit
 * @param counts      the offsets unit is counts ({@code offsets.unit = counts}), else mm
 * @param maxStep     the largest change one test cut may make on either axis ({@code wear.max_step}), offsets unit
 * @param maxTotal    the largest wear an offset may hold on either axis ({@code wear.max_total}), offsets unit
 * @param offsetsFile the offsets file read ({@code --offsets FILE} or the profile's {@code offsets.file}), if any
 */
public record ToolWear(Map<Integer, Wear> byOffset, boolean counts, double maxStep, double maxTotal,
                       Optional<String> offsetsFile) {
    /**
     * One offset's wear as written.
     *
     * @param x    X wear as programmed (a diameter on a diameter-programmed machine), offsets unit
     * @param z    Z wear, offsets unit
     * @param file the file its {@code wear.N} line is in (the profile or the offsets file)
     * @param line that line
     */
    public record Wear(double x, double z, String file, int line) {
    }

    /** Wear limits by default: 0.5 mm a step, 1 mm in all (in counts: those mm in X's counts per mm). */
    public static final double DEFAULT_STEP_MM = 0.5;
    public static final double DEFAULT_TOTAL_MM = 1.0;

    public ToolWear {
        byOffset = java.util.Collections.unmodifiableMap(new TreeMap<>(byOffset));
    }

    /** No wear at all, with the default limits in mm (a profile built by hand, a test's). */
    public static ToolWear none() {
        return new ToolWear(Map.of(), false, DEFAULT_STEP_MM, DEFAULT_TOTAL_MM, Optional.empty());
    }

    /** Offset {@code n}'s wear, when a {@code wear.N} line gives one. */
    public Optional<Wear> of(int n) {
        return Optional.ofNullable(byOffset.get(n));
    }

    /** The same table with offset {@code n}'s wear set to {@code x, z} (from {@code file}, at {@code line}). */
    public ToolWear with(int n, double x, double z, String file, int line) {
        Map<Integer, Wear> m = new TreeMap<>(byOffset);
        m.put(n, new Wear(x, z, file, line));
        return new ToolWear(m, counts, maxStep, maxTotal, offsetsFile);
    }

    /**
     * Offset {@code n}'s wear as the pre-flight and the test cut show it: {@code T01 X+0.030 Z0.000
     * (diameter, mm)} (X as the program writes it: a diameter or a radius).
     */
    public String describe(int n, boolean diameterX) {
        Wear w = byOffset.get(n);
        return describe(n, w == null ? 0 : w.x(), w == null ? 0 : w.z(), diameterX, unit());
    }

    /** {@link #describe(int, boolean)} of offset {@code n}'s wear {@code x, z} in {@code unit}. */
    public static String describe(int n, double x, double z, boolean diameterX, String unit) {
        return "T" + (n < 10 ? "0" + n : Integer.toString(n)) + " X" + signed(x) + " Z" + signed(z) + " ("
                + (diameterX ? "diameter" : "radius") + ", " + unit + ")";
    }

    /** A wear value with its sign: "+0.030", "-0.0762", "0.000" (at least 3 decimals, at most 6). */
    public static String signed(double v) {
        java.math.BigDecimal d = java.math.BigDecimal.valueOf(v).setScale(6, java.math.RoundingMode.HALF_EVEN)
                .stripTrailingZeros();
        if (d.scale() < 3) {
            d = d.setScale(3);
        }
        return (d.signum() > 0 ? "+" : "") + d.toPlainString();
    }

    /** The unit of the values as a person reads it: "mm" or "counts". */
    public String unit() {
        return counts ? "counts" : "mm";
    }

    /**
     * Offset {@code n}'s wear in machine counts (X a radius, as the machine frame measures it), to
     * add to its geometry: X as written halved on a diameter machine, each axis times its counts
     * per mm unless the unit is counts.
     */
    public Point inCounts(int n, Axis x, Axis z, boolean diameterX) {
        Wear w = byOffset.get(n);
        if (w == null) {
            return Point.ORIGIN;
        }
        double wx = (counts ? w.x() : w.x() * x.countsPerMm()) / (diameterX ? 2 : 1);
        double wz = counts ? w.z() : w.z() * z.countsPerMm();
        return new Point(wx, wz);
    }
}
