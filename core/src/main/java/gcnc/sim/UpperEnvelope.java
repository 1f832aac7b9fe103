package gcnc.sim;

import java.util.ArrayList;
import java.util.List;

/**
 * The largest radius of material at each z of the blank, held exactly as a piecewise-linear
 * function over [back, face]: pieces that join end to end, each a straight line (a face of the part
 * is a jump between two pieces). It lets the many moves that pass above the material skip the
 * polygon work ({@link Stock}).
 *
 * <p>It is never below the material: a cut lowers it only where the sweep covers everything from
 * its lower edge up to the envelope, and then to that lower edge; the polygons, when they catch
 * up, rebuild it from their own edges ({@link EdgeEnvelope}, {@link #replace}). Because it is
 * exact, a turning pass costs the few pieces it spans, not one step per slice of its length.
 * (Before this, the envelope was a value per 0.0025 mm slice: a 40 mm pass was 16,000 steps.)
 *
 * <p>The pieces sit in chunks of at most {@link #CHUNK}, each knowing its largest radius, so a move
 * over a detailed envelope skips whole chunks it stays above, and a cut rewrites only the chunks
 * it spans. A program that leaves a ragged outline is bounded: past {@link #MAX_PIECES} the
 * envelope is coarsened to level steps at their largest radius, which only makes it higher.
 */
final class UpperEnvelope {
    /** One straight stretch from (z0, a) to (z1, b), z0 < z1, mm. */
    record Piece(double z0, double z1, double a, double b) implements Pieces.Stretch {
        double at(double z) {
            if (z <= z0) {
                return a;
            }
            if (z >= z1) {
                return b;
            }
            return a + (b - a) * (z - z0) / (z1 - z0);
        }

        double max() {
            return Math.max(a, b);
        }

        /** The same line over [s, t] (inside [z0, z1]). */
        Piece cut(double s, double t) {
            return new Piece(s, t, at(s), at(t));
        }
    }

    /** Pieces in order, and the largest radius among them. */
    private static final class Chunk implements Pieces.Stretch {
        final List<Piece> pieces;
        final double max;

        Chunk(List<Piece> pieces) {
            this.pieces = pieces;
            double m = 0;
            for (Piece p : pieces) {
                m = Math.max(m, p.max());
            }
            this.max = m;
        }

        @Override
        public double z0() {
            return pieces.get(0).z0();
        }

        double z1() {
            return pieces.get(pieces.size() - 1).z1();
        }
    }

    static final int CHUNK = 32;
    /** Pieces kept at most (about 3 MiB); past it the envelope is coarsened ({@link #coarsen}). */
    static final int MAX_PIECES = 1 << 16;

    private final double back;
    private final double face;
    private final List<Chunk> chunks = new ArrayList<>();
    private int pieces;
    /** The bore: the smallest radius of material at each z, never above it ({@link LowerEnvelope}). */
    private final LowerEnvelope bore;
    /**
     * The floor of the top run: from it to this envelope each z's material is one run (below it,
     * down to the bore, there may be what a cut passed above: the pip a drill's point leaves off
     * the centreline, the floor of an undercut).
     */
    private final LowerEnvelope floor;
    /** Whether every cut from above ended in the top run or took everything: the envelope is the outline. */
    private boolean exact = true;
    /** Whether cuts raise the bore (false: the bore stays the blank's, the reference model's way). */
    private final boolean raiseBore;

    /** A blank of {@code radius} from {@code back} to {@code face}, bored to {@code inner} (0 for a bar). */
    UpperEnvelope(double back, double face, double inner, double radius) {
        this(back, face, inner, radius, true);
    }

    /** The same; {@code raiseBore} false keeps the bore at {@code inner} whatever is cut from inside. */
    UpperEnvelope(double back, double face, double inner, double radius, boolean raiseBore) {
        this.back = back;
        this.face = face;
        this.bore = new LowerEnvelope(back, face, inner);
        this.floor = new LowerEnvelope(back, face, inner);
        this.raiseBore = raiseBore;
        chunks.add(new Chunk(List.of(new Piece(back, face, radius, radius))));
        pieces = 1;
    }

    /**
     * Whether the envelope is the material's outline exactly: every cut from above so far ended in
     * the top run (the material from the floor up to the envelope, one run at each z) or took
     * everything at its z (its lower edge at or below the bore). Cuts from inside (a drill, a
     * boring bar) and cuts under the envelope (an undercut, the pip a drill's point leaves) raise
     * the floor and leave it so. A cut from above whose lower edge ends under the floor (a groove
     * under a shoulder deepened from outside, a turned diameter down into an internal groove) cannot
     * tell what is left below it. While it holds, a drawing needs no polygons. Coarsening ends it.
     */
    boolean solid() {
        return exact && bore.exact() && floor.exact();
    }

    /** How many pieces the envelope has (tests bound it). */
    int size() {
        return pieces;
    }

    /** The chunk that holds z (the later one where two meet). */
    private int chunkAt(double z) {
        return Pieces.holding(chunks, z);
    }

    /** The first chunk with a piece over z: where two chunks meet, the earlier (at a face both sides' radii hold). */
    private int firstChunk(double z) {
        int c = chunkAt(z);
        return c > 0 && chunks.get(c).z0() == z ? c - 1 : c;
    }

    /**
     * Whether a region over z [zLo, zHi] comes below the envelope anywhere: the region is a hull
     * (its lower edge is what counts), or with a null hull everything at or above {@code floor}.
     * The envelope is never below the material, so a no is certain.
     */
    boolean dips(double zLo, double zHi, Hull region, double floor) {
        if (zHi < back || zLo > face || zHi < zLo) {
            return false;
        }
        if (region != null) {
            zLo = Math.max(zLo, region.zMin());
            zHi = Math.min(zHi, region.zMax());
            if (zHi < zLo) {
                return false;
            }
        }
        for (int c = firstChunk(zLo); c < chunks.size() && chunks.get(c).z0() <= zHi; c++) {
            Chunk k = chunks.get(c);
            double p = Math.max(zLo, k.z0());
            double q = Math.min(zHi, k.z1());
            if (p > q || lowest(region, floor, p, q) >= k.max) {
                continue;
            }
            for (Piece piece : k.pieces) {
                double s = Math.max(p, piece.z0());
                double t = Math.min(q, piece.z1());
                if (s <= t && below(region, floor, piece, s, t)) {
                    return true;
                }
            }
        }
        return false;
    }

    private static double lowest(Hull region, double floor, double a, double b) {
        return region == null ? floor : region.lowest(a, b);
    }

    /**
     * Whether the region comes below one piece over [s, t]: the lower edge is convex and the piece
     * straight, so their difference is least at an end or at one of the edge's corners.
     */
    private static boolean below(Hull region, double floor, Piece piece, double s, double t) {
        double us = piece.at(s);
        double ut = piece.at(t);
        if (region == null) {
            return floor < Math.max(us, ut);
        }
        if (region.lowest(s, t) >= Math.max(us, ut)) {
            return false;
        }
        if (region.lowest(s, s) < us || region.lowest(t, t) < ut) {
            return true;
        }
        double[] z = region.z();
        double[] r = region.r();
        for (int i = 1, end = region.lowerEnd(); i <= end; i++) {
            if (z[i] > s && z[i] < t && r[i] < piece.at(z[i])) {
                return true;
            }
        }
        return false;
    }

    /**
     * Takes a sweep from the envelopes ({@link EnvelopeCut#stretch}): lowers this one wherever the
     * hull covers from its lower edge to the envelope or above (nothing is left above the lower
     * edge, and nothing at all where the lower edge is at or below the bore), raises the bore where
     * the sweep cuts from inside, and the top run's floor where it passes under the envelope.
     * Returns whether this envelope changed.
     */
    boolean lower(Hull h) {
        double lo = Math.max(back, h.zMin());
        double hi = Math.min(face, h.zMax());
        if (!(lo < hi)) {
            return false;
        }
        HullSide bottom = HullSide.bottom(h);
        HullSide top = HullSide.top(h);
        // between these both of the hull's edges, the bore and the floor are straight, as each piece is
        double[] corners = EnvelopeCut.breaks(h, lo, hi, both(bore.breaks(lo, hi), floor.breaks(lo, hi)));
        List<Piece> out = new ArrayList<>();
        List<Piece> inner = new ArrayList<>();
        List<Piece> under = new ArrayList<>();
        int changed = 0;
        for (int c = chunkAt(lo); c < chunks.size() && chunks.get(c).z0() < hi; c++) {
            for (Piece piece : chunks.get(c).pieces) {
                double s0 = Math.max(piece.z0(), lo);
                double s1 = Math.min(piece.z1(), hi);
                if (!(s0 < s1)) {
                    continue;
                }
                double s = s0;
                for (double corner : corners) {
                    if (corner > s && corner < s1) {
                        changed |= stretch(piece, bottom, top, s, corner, out, inner, under);
                        s = corner;
                    }
                }
                changed |= stretch(piece, bottom, top, s, s1, out, inner, under);
            }
        }
        exact &= (changed & EnvelopeCut.INEXACT) == 0;
        if ((changed & EnvelopeCut.UPPER) != 0) {
            replace(lo, hi, out);
        }
        if (raiseBore && (changed & EnvelopeCut.BORE) != 0) {
            bore.replace(lo, hi, inner);
        }
        if ((changed & EnvelopeCut.RUN) != 0) {
            floor.replace(lo, hi, under);
        }
        return (changed & EnvelopeCut.UPPER) != 0;
    }

    private static double[] both(double[] a, double[] b) {
        if (b.length == 0) {
            return a;
        }
        double[] c = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return c;
    }

    /** One stretch [s, t] where the piece, the bore, the floor and both of the hull's edges are straight. */
    private int stretch(Piece piece, HullSide bottom, HullSide top, double s, double t, List<Piece> out,
                        List<Piece> inner, List<Piece> under) {
        Piece in = bore.over(s, t);
        Piece run = floor.over(s, t);
        return EnvelopeCut.stretch(s, t, piece.at(s), piece.at(t), in.at(s), in.at(t), run.at(s), run.at(t),
                bottom.at(s, t, true), bottom.at(s, t, false), top.at(s, t, true), top.at(s, t, false), out, inner, under);
    }

    /** Whether the hull is in the bore, touching no material ({@link LowerEnvelope#holds}). */
    boolean inBore(Hull h) {
        return bore.holds(h);
    }

    /** The bore (tests read it). */
    LowerEnvelope bore() {
        return bore;
    }

    /**
     * Puts {@code fresh} (pieces covering [lo, hi] end to end) in place of what the envelope had
     * there, joining pieces that continue each other, and coarsens past {@link #MAX_PIECES}.
     */
    void replace(double lo, double hi, List<Piece> fresh) {
        int c0 = firstChunk(lo); // the piece ending at lo may join the first fresh one
        int c1 = chunkAt(hi);
        List<Piece> covered = new ArrayList<>();
        for (int c = c0; c <= c1; c++) {
            covered.addAll(chunks.get(c).pieces);
        }
        int removed = covered.size();
        List<Piece> all = Pieces.spliced(covered, lo, hi, fresh);
        List<Piece> joined = Pieces.join(all, true);
        List<Chunk> made = new ArrayList<>();
        for (int i = 0; i < joined.size(); i += CHUNK) {
            made.add(new Chunk(new ArrayList<>(joined.subList(i, Math.min(joined.size(), i + CHUNK)))));
        }
        chunks.subList(c0, c1 + 1).clear();
        chunks.addAll(c0, made);
        pieces += joined.size() - removed;
        if (pieces > MAX_PIECES) {
            coarsen();
        }
    }

    /** Level steps at the largest radius of each, MAX_PIECES / 2 of them over the blank: higher, never lower. */
    private void coarsen() {
        exact = false;
        int n = MAX_PIECES / 2;
        double w = (face - back) / n;
        List<Piece> steps = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            double s = back + i * w;
            double t = i == n - 1 ? face : back + (i + 1) * w;
            double m = max(s, t);
            steps.add(new Piece(s, t, m, m));
        }
        List<Piece> joined = Pieces.join(steps, true);
        chunks.clear();
        for (int i = 0; i < joined.size(); i += CHUNK) {
            chunks.add(new Chunk(new ArrayList<>(joined.subList(i, Math.min(joined.size(), i + CHUNK)))));
        }
        pieces = joined.size();
    }

    /** The largest radius over [s, t]. */
    double max(double s, double t) {
        double m = 0;
        for (int c = firstChunk(s); c < chunks.size() && chunks.get(c).z0() <= t; c++) {
            for (Piece p : chunks.get(c).pieces) {
                double a = Math.max(s, p.z0());
                double b = Math.min(t, p.z1());
                if (a <= b) {
                    m = Math.max(m, Math.max(p.at(a), p.at(b)));
                }
            }
        }
        return m;
    }

    /**
     * The outline as points (z, r), back to face: each piece's ends, a face as two points at one
     * z. With more than {@code most} points, the largest radius of each of {@code most} equal
     * stretches at its middle instead (a drawing needs no finer outline).
     */
    double[][] outline(int most) {
        if (2 * pieces > most) {
            double[] z = new double[most];
            double[] r = new double[most];
            double w = (face - back) / most;
            for (int i = 0; i < most; i++) {
                z[i] = back + (i + 0.5) * w;
                r[i] = max(back + i * w, i == most - 1 ? face : back + (i + 1) * w);
            }
            return new double[][] {z, r};
        }
        double[] z = new double[2 * pieces];
        double[] r = new double[2 * pieces];
        int n = 0;
        for (Chunk c : chunks) {
            for (Piece p : c.pieces) {
                if (n == 0 || z[n - 1] != p.z0() || r[n - 1] != p.a()) {
                    z[n] = p.z0();
                    r[n++] = p.a();
                }
                z[n] = p.z1();
                r[n++] = p.b();
            }
        }
        return new double[][] {java.util.Arrays.copyOf(z, n), java.util.Arrays.copyOf(r, n)};
    }
}
