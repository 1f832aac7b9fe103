package gcnc.machine;

import java.util.Locale;

/**
 * Tool outlines from a short name, as a machine profile gives them per turret station
 * ({@code sim.tool.3 = T 16}, {@code sim.tool.default = C 12.7}): the ISO insert shapes of a
 * turning tool, a threading insert, grooving and parting blades, a boring bar. Each outline is in
 * millimetres relative to the tip (dz toward the tailstock, dx away from the centreline) and is
 * convex; the holder sits on the insert's back, as wide along Z as the insert, so that a cut
 * deeper than the insert is tall puts the holder into the stock (E315).
 *
 * <ul>
 *   <li>{@code C size}, {@code D size}, {@code V size}: 80°, 55° and 35° rhombic inserts of
 *       inscribed circle {@code size} on a right-hand holder: the major edge rises radially
 *       from the tip, the minor edge trails toward the tailstock.</li>
 *   <li>{@code T size}: a 60° threading insert, edge {@code size}, symmetric about the radial line.</li>
 *   <li>{@code G width [reach]}, {@code P width [reach]}: a grooving or parting blade, the tip at
 *       its chuck-side corner, {@code reach} deep (default 10 × width, at most 25, for G; 32 for P),
 *       held by a clamp block {@link #CLAMP} mm wider on each side: a groove or part-off deeper
 *       than the reach is E315.</li>
 *   <li>{@code B diameter}: a boring bar along +Z below the tip, its insert facing outward.</li>
 * </ul>
 * These are simplified outlines (no clearance angles, no nose radius): what matters for the
 * checks is how tall and wide the cutting part is, where the holder starts, and which edges cut.
 * The two edges that meet at a rhombic insert's tip cut, and so do a boring insert's; the edge
 * behind them, facing the tailstock, does not ({@link MachineModel.ToolOutline#back}), so turning
 * back toward the tailstock deeper than the trailing edge reaches is a cut with the back of the
 * insert. A blade cuts with its end and both sides (grooving inserts turn sideways), and a
 * threading insert with both flanks: they have no back.
 */
final class ToolLibrary {
    /** How far the holder extends beyond the insert, away from the cut (mm). */
    static final double HOLDER = 30;
    /**
     * How much wider than its blade a grooving or parting blade's clamp block is on each side (mm):
     * little, so that parting close to the jaws stays clean, but enough that the block cannot
     * follow the blade down its own slot.
     */
    static final double CLAMP = 1;

    private ToolLibrary() {
    }

    /** The outline for a spec such as "C 12.7", in mm from the tip; null if the spec is not one. */
    static MachineModel.ToolOutline shape(String spec) {
        String[] p = spec.trim().split("\\s+");
        if (p.length < 2 || p.length > 3 || p[0].length() != 1) {
            return null;
        }
        double size;
        double reach = Double.NaN;
        try {
            size = Double.parseDouble(p[1]);
            if (p.length == 3) {
                reach = Double.parseDouble(p[2]);
            }
        } catch (NumberFormatException e) {
            return null;
        }
        if (!(size > 0) || !Double.isFinite(size) || p.length == 3 && !(reach > 0 && Double.isFinite(reach))) {
            return null;
        }
        double[][] insert;
        switch (p[0].toUpperCase(Locale.ROOT)) {
            case "C" -> insert = rhombus(80, size);
            case "D" -> insert = rhombus(55, size);
            case "V" -> insert = rhombus(35, size);
            case "T" -> {
                // both flanks cut; the third edge is under the holder
                double[][] t = {{0, size * cos(60), size * cos(120)}, {0, size * sin(60), size * sin(120)}};
                return new MachineModel.ToolOutline(outline(t), outline(holder(t)));
            }
            case "G", "P" -> {
                double deep = p.length == 3 ? reach : p[0].equalsIgnoreCase("G") ? Math.min(25, 10 * size) : 32;
                double[][] blade = {{0, size, size, 0}, {0, 0, deep, deep}};
                // the clamp block at the blade's reach, wider than the blade on both sides: a plunge
                // deeper than the reach puts it into the groove's walls
                double[][] clamp = {{-CLAMP, size + CLAMP, size + CLAMP, -CLAMP},
                        {deep, deep, deep + HOLDER, deep + HOLDER}};
                return new MachineModel.ToolOutline(outline(blade), outline(clamp));
            }
            case "B" -> {
                // the insert at the bar's end, its corner at the tip; the bar below it, 150 mm along +Z
                double[][] tip = {{0, 0.4 * size, 0.4 * size, 0}, {-0.3 * size, -0.3 * size, 0, 0}};
                double[][] bar = {{0, 150, 150, 0}, {-size, -size, -0.3 * size, -0.3 * size}};
                // the edge facing the tailstock does not cut: boring back toward it is E320
                return new MachineModel.ToolOutline(outline(tip), outline(bar), new int[] {1});
            }
            default -> {
                return null;
            }
        }
        // the rhombus's back edge (corner 2 to corner 3, facing the tailstock) does not cut
        return new MachineModel.ToolOutline(outline(insert), outline(holder(insert)), new int[] {2});
    }

    /**
     * A rhombus with corner angle {@code corner} at the tip, inscribed circle {@code ic} (edges of
     * length ic / sin(corner)), its major edge radial (lead angle 90°): the shoulder it leaves is
     * square, so the usual straight retract at the end of a pass ({@code G00 U2.}) slides along it.
     * A real 93-95° holder leans the edge a few degrees; the few hundredths of a millimetre it then
     * rubs on the retract are not a collision, and this model does not report them.
     */
    private static double[][] rhombus(double corner, double ic) {
        double side = ic / sin(corner);
        double major = 90;
        double minor = major - corner;
        double mz = side * cos(major);
        double mr = side * sin(major);
        double nz = side * cos(minor);
        double nr = side * sin(minor);
        return new double[][] {{0, mz, mz + nz, nz}, {0, mr, mr + nr, nr}};
    }

    /**
     * The holder: the body above the insert, as wide along Z as the insert, its underside the
     * insert's upper edges (so no gap is left between them for a sweep to miss) and its top
     * {@link #HOLDER} mm above the insert's highest point.
     */
    private static double[][] holder(double[][] insert) {
        int[] chain = MonotoneChain.upper(insert[0], insert[1]);
        // the chain starts with the insert's radial edge when that edge is vertical: the holder's
        // underside begins at its top, not at the tip
        int first = 0;
        while (first + 1 < chain.length && insert[0][chain[first + 1]] == insert[0][chain[first]]) {
            first++;
        }
        int[] upper = java.util.Arrays.copyOfRange(chain, first, chain.length);
        double top = -Double.MAX_VALUE;
        for (int i : upper) {
            top = Math.max(top, insert[1][i]);
        }
        int n = upper.length;
        double[][] out = new double[2][n + 2];
        for (int k = 0; k < n; k++) {
            out[0][k] = insert[0][upper[k]];
            out[1][k] = insert[1][upper[k]];
        }
        out[0][n] = out[0][n - 1];
        out[1][n] = top + HOLDER;
        out[0][n + 1] = out[0][0];
        out[1][n + 1] = top + HOLDER;
        return out;
    }

    private static MachineModel.Outline outline(double[][] mm) {
        return new MachineModel.Outline(mm[0], mm[1]);
    }

    /** cos and sin in degrees, exact at multiples of 90° (Math.cos(Math.toRadians(90)) is 6e-17, not 0). */
    private static double cos(double deg) {
        return deg % 90 == 0 ? Math.rint(Math.cos(Math.toRadians(deg))) : Math.cos(Math.toRadians(deg));
    }

    private static double sin(double deg) {
        return deg % 90 == 0 ? Math.rint(Math.sin(Math.toRadians(deg))) : Math.sin(Math.toRadians(deg));
    }
}
