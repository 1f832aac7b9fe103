package gcnc.sim;

import java.util.List;

/**
 * The tool in use as the stock and obstacle checks see it, worked out once per tool change: its
 * shape, the outlines of its insert and holder in mm from the tip (and the same drawn a little
 * smaller, {@link Hull#smaller}, to tell a real bite from a touch), how far each part and the
 * whole tool reach from the tip, the insert's edges that do not cut, and the side of the
 * centreline it works on; and what its parts sweep over one straight piece of a move
 * ({@link #sweeps}).
 */
final class ToolInUse {
    final SimMachine.ToolShape shape;
    /** The insert and holder relative to the tip, mm ({z[], r[]}; holder null if none). */
    final double[][] insertMm;
    final double[][] holderMm;
    /** The same outlines drawn a little smaller ({@link Hull#smaller}), to tell a real bite from a touch. */
    final double[][] insertIn;
    final double[][] holderIn;
    /** How far each part reaches from the tip, mm: {dr-, dz-, dz+} of the insert and of the holder. */
    final double[] insertReach;
    final double[] holderReach;
    /** The insert's edges that do not cut (E320, E323 for a drill, centre drill or tap). */
    final BackEdges back;
    /** The side of the centreline the tool works on: 1 (+X) or -1 (-X, a gang lathe's tools). */
    final int side;
    /** How far the tool outline reaches from its tip: {dr-, dr+, dz-, dz+}, counts. */
    final double[] reach;
    private final double kx;
    private final double kz;

    /** {@code kx}, {@code kz}: the axes' counts per mm. */
    ToolInUse(SimMachine.ToolShape shape, double kx, double kz) {
        this.shape = shape;
        this.kx = kx;
        this.kz = kz;
        this.reach = reach(shape);
        insertMm = shape == null ? null : mm(shape.insert());
        holderMm = shape == null || shape.holder() == null ? null : mm(shape.holder());
        insertIn = insertMm == null ? null : Hull.smaller(insertMm[0], insertMm[1]);
        holderIn = holderMm == null ? null : Hull.smaller(holderMm[0], holderMm[1]);
        insertReach = insertMm == null ? null : partReach(insertMm);
        holderReach = holderMm == null ? null : partReach(holderMm);
        back = insertMm == null ? BackEdges.NONE : BackEdges.of(insertMm, shape.back());
        side = shape == null ? 1 : shape.side();
    }

    private static double[] partReach(double[][] outline) {
        double[] r = {Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = 0; i < outline[0].length; i++) {
            r[0] = Math.min(r[0], outline[1][i]);
            r[1] = Math.min(r[1], outline[0][i]);
            r[2] = Math.max(r[2], outline[0][i]);
        }
        return r;
    }

    private double[][] mm(Shape s) {
        double[] z = new double[s.size()];
        double[] r = new double[s.size()];
        for (int i = 0; i < z.length; i++) {
            z[i] = s.z()[i] / kz;
            r[i] = s.r()[i] / kx;
        }
        return new double[][] {z, r};
    }

    /** {rMin, rMax, zMin, zMax} of the shapes (counts, radius), null when there are none. */
    static double[] box(Shape[] shapes) {
        if (shapes.length == 0) {
            return null;
        }
        double[] b = {Double.MAX_VALUE, -Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE};
        for (Shape s : shapes) {
            for (int i = 0; i < s.size(); i++) {
                b[0] = Math.min(b[0], s.r()[i]);
                b[1] = Math.max(b[1], s.r()[i]);
                b[2] = Math.min(b[2], s.z()[i]);
                b[3] = Math.max(b[3], s.z()[i]);
            }
        }
        return b;
    }

    private static double[] reach(SimMachine.ToolShape t) {
        double[] b = box(t.parts());
        return new double[] {Math.min(0, b[0]), Math.max(0, b[1]), Math.min(0, b[2]), Math.max(0, b[3])};
    }

    /** The insert's outline (mm from the tip, on the tool's side) with its tip at (z, r) of the drawing; null if none. */
    Shape placedInsert(double z, double r) {
        return placed(insertMm, z, r);
    }

    /** The holder's outline placed so ({@link #placedInsert}); null if none. */
    Shape placedHolder(double z, double r) {
        return placed(holderMm, z, r);
    }

    private Shape placed(double[][] outline, double z, double r) {
        if (outline == null) {
            return null;
        }
        double[] zs = new double[outline[0].length];
        double[] rs = new double[zs.length];
        for (int i = 0; i < zs.length; i++) {
            zs[i] = z + outline[0][i];
            rs[i] = r + side * outline[1][i];
        }
        return new Shape(zs, rs);
    }

    /**
     * One straight piece near the stock (tip from z a, radius ar to z b, radius br; counts): the
     * sweeps of the insert ({@code cuts}) and the holder ({@code holders}) that may reach into
     * material, and the insert's back edges' ({@code backs}, null when not asked for).
     */
    void sweeps(Stock stock, double a, double ar, double b, double br, List<Stock.Sweep> cuts,
                List<Stock.Sweep> holders, List<BackEdges.Band> backs) {
        double az = a / kz;
        double bz = b / kz;
        double lo = Math.min(az, bz);
        double hi = Math.max(az, bz);
        double r = Math.min(ar, br) / kx;
        // each part against the material with its own box: the holder sits above the insert, so it
        // rarely comes near, and most pieces along a surface just cut need neither test
        if (stock.mayTouch(lo + insertReach[1], hi + insertReach[2], r + insertReach[0])) {
            int earlier = cuts.size();
            Hull smaller = Hull.sweep(insertIn[0], insertIn[1], az, ar / kx, bz, br / kx);
            if (stock.mayBite(smaller)) {
                cuts.add(new Stock.Sweep(Hull.sweep(insertMm[0], insertMm[1], az, ar / kx, bz, br / kx), smaller));
            }
            if (backs != null) {
                back.piece(stock, az, ar / kx, bz, br / kx, backs, earlier);
            }
        }
        if (holderMm != null && stock.mayTouch(lo + holderReach[1], hi + holderReach[2], r + holderReach[0])) {
            Hull smaller = Hull.sweep(holderIn[0], holderIn[1], az, ar / kx, bz, br / kx);
            if (stock.mayBite(smaller)) {
                holders.add(new Stock.Sweep(Hull.sweep(holderMm[0], holderMm[1], az, ar / kx, bz, br / kx), smaller));
            }
        }
    }
}
