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
        String name = spec.trim().replaceAll("\\s+", " ");
        String letter = p[0].toUpperCase(Locale.ROOT);
        return switch (letter) {
            case "C", "D", "V" -> turning(letter, size, name);
            case "T" -> thread(size, name);
            case "G", "P" -> blade(letter.equals("P"), size, reach, name);
            case "B" -> boringBar(size, name);
            default -> null;
        };
    }

    /**
     * A turning insert by its ISO shape letter and inscribed circle: C (80° rhombus), D (55°), V
     * (35°), S (90° square), T (60° triangle) and W (80° trigon, modelled by the 80° corner of a C
     * of the same inscribed circle: what the checks see is the corner, the edges at it and how tall
     * it stands); null for another letter.
     */
    static MachineModel.ToolOutline turning(String letter, double ic, String name) {
        double[][] insert;
        int[] back;
        switch (letter) {
            case "C", "W" -> insert = rhombus(80, ic);
            case "D" -> insert = rhombus(55, ic);
            case "V" -> insert = rhombus(35, ic);
            case "S" -> insert = rhombus(90, ic);
            case "T" -> {
                // an equilateral triangle, edge ic * sqrt(3): the major edge radial, the minor trailing at 30°
                double side = ic * Math.sqrt(3);
                insert = new double[][] {{0, 0, side * cos(30)}, {0, side, side * sin(30)}};
                // its third edge faces the tailstock and the holder: its back
                return new MachineModel.ToolOutline(outline(insert), outline(head(holder(insert))), new int[] {1},
                        MachineModel.ToolKind.TURN, name, 1);
            }
            default -> {
                return null;
            }
        }
        // the rhombus's back edge (corner 2 to corner 3, facing the tailstock) does not cut
        back = new int[] {2};
        return new MachineModel.ToolOutline(outline(insert), outline(head(holder(insert))), back,
                MachineModel.ToolKind.TURN, name, 1);
    }

    /** A 60° threading insert, edge {@code size}: both flanks cut; the third edge is under the holder. */
    static MachineModel.ToolOutline thread(double size, String name) {
        double[][] t = {{0, size * cos(60), size * cos(120)}, {0, size * sin(60), size * sin(120)}};
        return new MachineModel.ToolOutline(outline(t), outline(holder(t)), new int[0], MachineModel.ToolKind.THREAD,
                name, 1);
    }

    /** A grooving or parting blade of {@code width}, {@code reach} deep (NaN: 10 × width up to 25, or 32 for parting). */
    static MachineModel.ToolOutline blade(boolean parting, double width, double reach, String name) {
        double deep = !Double.isNaN(reach) ? reach : parting ? 32 : Math.min(25, 10 * width);
        double[][] blade = {{0, width, width, 0}, {0, 0, deep, deep}};
        // the clamp block at the blade's reach, wider than the blade on both sides: a plunge
        // deeper than the reach puts it into the groove's walls
        double[][] clamp = {{-CLAMP, width + CLAMP, width + CLAMP, -CLAMP},
                {deep, deep, deep + HOLDER, deep + HOLDER}};
        return new MachineModel.ToolOutline(outline(blade), outline(clamp), new int[0],
                parting ? MachineModel.ToolKind.PART : MachineModel.ToolKind.GROOVE, name, 1);
    }

    /** A boring bar of {@code diameter}: the insert at the bar's end, its corner at the tip; the bar below it, 150 mm along +Z. */
    static MachineModel.ToolOutline boringBar(double diameter, String name) {
        double[][] tip = {{0, 0.4 * diameter, 0.4 * diameter, 0}, {-0.3 * diameter, -0.3 * diameter, 0, 0}};
        double[][] bar = {{0, 150, 150, 0}, {-diameter, -diameter, -0.3 * diameter, -0.3 * diameter}};
        // the edge facing the tailstock does not cut: boring back toward it is E320
        return new MachineModel.ToolOutline(outline(tip), outline(bar), new int[] {1}, MachineModel.ToolKind.BORE,
                name, 1);
    }

    /** How far a drill's or tap's holder (a collet chuck) reaches beyond the tool's diameter on each side, mm. */
    static final double COLLET = 5;

    /**
     * A twist drill of {@code diameter} on the centreline: its point of {@code pointAngle} degrees
     * (118 for a jobber drill) at the tip, the fluted body {@code reach} long (NaN: 5 × the
     * diameter, a stub drill), then its holder, {@link #COLLET} mm wider on each side: a hole deeper
     * than the flutes puts the holder into the part (E315). Only the point cuts: its sides (the
     * margins) and its back are back edges, so a drill moved sideways in material is E323.
     */
    static MachineModel.ToolOutline drill(double diameter, double pointAngle, double reach, String name) {
        double r = diameter / 2;
        double point = r / Math.tan(Math.toRadians(pointAngle / 2));
        double flutes = Double.isNaN(reach) ? Math.max(5 * diameter, point + diameter) : Math.max(reach, point);
        // counter-clockwise in (z, r): tip, upper point corner, upper flute end, lower flute end, lower point corner
        double[][] body = {{0, point, flutes, flutes, point}, {0, r, r, -r, -r}};
        return new MachineModel.ToolOutline(outline(body), outline(collet(flutes, r)), new int[] {1, 3},
                MachineModel.ToolKind.DRILL, name, 1);
    }

    /**
     * A centre drill of pilot diameter {@code pilot} (A type, DIN 333): a 118° point, the pilot 1.2 ×
     * its diameter long, then the 60° countersink up to the body of 2.5 × the pilot. The insert is
     * the convex hull of point, pilot and countersink (a little more than the tool itself, where the
     * pilot meets the countersink); the body behind the countersink is the holder, so drilling deeper
     * than the countersink (the usual broken centre drill) is E315.
     */
    static MachineModel.ToolOutline centreDrill(double pilot, String name) {
        double r = pilot / 2;
        double body = 2.5 * pilot / 2;
        double point = r / Math.tan(Math.toRadians(59));
        double sink = point + 1.2 * pilot + (body - r) / Math.tan(Math.toRadians(30));
        double[][] cutting = {{0, point, sink, sink, point}, {0, r, body, -body, -r}};
        double[][] holder = {{sink, sink + 4 * body, sink + 4 * body, sink}, {-body, -body, body, body}};
        return new MachineModel.ToolOutline(outline(cutting), outline(holder), new int[0],
                MachineModel.ToolKind.CENTRE_DRILL, name, 1);
    }

    /**
     * A tap of nominal {@code diameter}: its end (the chamfered lead, 0.8 × the diameter across)
     * at the tip, the chamfer to the full diameter over 0.3 × it, the thread {@code reach} long
     * (NaN: 2 × the diameter), then its holder. A tap cuts only with its chamfer and thread, into a
     * hole drilled for it: its end and its sides are back edges, so tapping into solid material, or
     * moving a tap sideways, is E323.
     */
    static MachineModel.ToolOutline tap(double diameter, double reach, String name) {
        double r = diameter / 2;
        double lead = 0.4 * diameter;
        double chamfer = 0.3 * diameter;
        double end = Double.isNaN(reach) ? 2 * diameter + chamfer : Math.max(reach, chamfer + 0.1 * diameter);
        // counter-clockwise: lower end corner, upper end corner, upper chamfer end, upper thread end, lower ...
        double[][] body = {{0, 0, chamfer, end, end, chamfer}, {-lead, lead, r, r, -r, -r}};
        // edge 0 is the end (no hole: it meets solid material), 2 and 4 the sides
        return new MachineModel.ToolOutline(outline(body), outline(collet(end, r)), new int[] {0, 2, 4},
                MachineModel.ToolKind.TAP, name, 1);
    }

    /** A bar puller: its tip only, for the chuck and tailstock; it grips the bar and cuts nothing. */
    static MachineModel.ToolOutline puller(String name) {
        return new MachineModel.ToolOutline(outline(new double[][] {{0}, {0}}), null, new int[0],
                MachineModel.ToolKind.PULLER, name, 1);
    }

    /** A drill's or tap's holder from {@code z} on, {@link #COLLET} mm wider than the tool's radius {@code r}. */
    private static double[][] collet(double z, double r) {
        double w = r + COLLET;
        return new double[][] {{z, z + HOLDER, z + HOLDER, z}, {-w, -w, w, w}};
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

    /** How far a turning holder's head reaches past its insert toward the tailstock, mm. */
    static final double HEAD = 3;

    /**
     * A turning insert's holder with its head: it reaches {@link #HEAD} mm past the insert toward
     * the tailstock, its underside going on along the insert's last upper edge (so the outline
     * stays convex and leaves no gap). A real holder is wider than its insert: plunged straight in
     * deeper than the insert stands, its head meets the wall the insert did not cut (E315), where a
     * holder exactly as wide as the insert would follow it down its own slot unchallenged.
     */
    private static double[][] head(double[][] holder) {
        // holder(): the underside corners first (left to right), then the two top corners
        int n = holder[0].length - 2;
        double z1 = holder[0][n - 1];
        double r1 = holder[1][n - 1];
        double slope = n >= 2 ? (r1 - holder[1][n - 2]) / (z1 - holder[0][n - 2]) : 0;
        double[][] out = new double[2][n + 3];
        for (int k = 0; k < n; k++) {
            out[0][k] = holder[0][k];
            out[1][k] = holder[1][k];
        }
        double top = holder[1][n];
        out[0][n] = z1 + HEAD;
        out[1][n] = Math.min(r1 + slope * HEAD, top);
        out[0][n + 1] = z1 + HEAD;
        out[1][n + 1] = top;
        out[0][n + 2] = holder[0][n + 1];
        out[1][n + 2] = top;
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
