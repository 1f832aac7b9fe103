package gcnc.sim;

import java.util.List;

/**
 * The edges of a tool's insert that do not cut (its back, {@link gcnc.machine.MachineModel.ToolOutline#back}),
 * and what they meet: material met first by a back edge is a cut with the back of the insert
 * (E320, docs/simulator.md "The back of the insert").
 *
 * <p>Of the area a convex insert sweeps along a straight piece beyond where it started, each point
 * is met first by exactly one of its leading edges: the band that edge sweeps. So the material in a
 * leading back edge's band, before the move's own cut takes it, is what the back meets. The bands
 * of all the pieces of a segment (an arc's chords) are judged together, more than {@link
 * Stock#DEPTH} thick, so that the verdict does not depend on how finely an arc is cut.
 */
final class BackEdges {
    /** No back edges: a tool whose back is not known, or that has none (a blade, a threading insert). */
    static final BackEdges NONE = new BackEdges(new double[0][]);

    /** Each edge in mm from the tip: {z0, r0, z1, r1, nz, nr}, (nz, nr) its outward unit normal. */
    private final double[][] edges;

    private BackEdges(double[][] edges) {
        this.edges = edges;
    }

    /** The edges {@code back} (edge i from corner i to corner i + 1) of a convex outline {z[], r[]} in mm. */
    static BackEdges of(double[][] outline, int[] back) {
        double[] z = outline[0];
        double[] r = outline[1];
        int n = z.length;
        double cz = 0;
        double cr = 0;
        for (int i = 0; i < n; i++) {
            cz += z[i] / n;
            cr += r[i] / n;
        }
        double[][] edges = new double[back.length][];
        for (int k = 0; k < back.length; k++) {
            int i = back[k];
            int j = (i + 1) % n;
            double len = Math.hypot(z[j] - z[i], r[j] - r[i]);
            double nz = (r[j] - r[i]) / len;
            double nr = -(z[j] - z[i]) / len;
            if (nz * ((z[i] + z[j]) / 2 - cz) + nr * ((r[i] + r[j]) / 2 - cr) < 0) {
                nz = -nz;
                nr = -nr;
            }
            edges[k] = new double[] {z[i], r[i], z[j], r[j], nz, nr};
        }
        return new BackEdges(edges);
    }

    boolean any() {
        return edges.length > 0;
    }

    /**
     * A back edge's band on one piece of a segment, and how many of the segment's cuts come from
     * the pieces before it: an arc's earlier pieces take their material before this one meets it.
     */
    record Band(Hull band, int earlierCuts) {
    }

    /**
     * Adds to {@code bands} the bands of the back edges that lead the piece (tip from (az, ar) to
     * (bz, br), mm) and may reach into the stock's material; {@code earlier} cuts of the segment
     * come from its earlier pieces.
     */
    void piece(Stock stock, double az, double ar, double bz, double br, List<Band> bands, int earlier) {
        for (double[] e : edges) {
            double advance = (bz - az) * e[4] + (br - ar) * e[5];
            if (advance <= 0) {
                continue; // trailing, or running along itself: it meets nothing first
            }
            Hull band = Hull.sweep(new double[] {e[0], e[2]}, new double[] {e[1], e[3]}, az, ar, bz, br);
            if (band != null && stock.mayBite(band)) {
                bands.add(new Band(band, earlier));
            }
        }
    }

    /**
     * Where material more than {@link Stock#DEPTH} thick lies in the bands of a segment's pieces,
     * before the segment's own cuts (the insert's sweeps, which cover the bands) take it away: {z, r}
     * in mm, or null.
     */
    static double[] met(Stock stock, List<Band> bands, List<Stock.Sweep> cuts) {
        List<Hull> regions = new java.util.ArrayList<>(bands.size());
        int[] before = new int[bands.size()];
        for (int i = 0; i < bands.size(); i++) {
            regions.add(bands.get(i).band());
            before[i] = bands.get(i).earlierCuts();
        }
        return stock.deepOverlap(regions, before, cuts);
    }
}
