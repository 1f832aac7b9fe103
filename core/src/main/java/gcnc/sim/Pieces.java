package gcnc.sim;

import java.util.ArrayList;
import java.util.List;

/** Tidies a run of envelope pieces end to end ({@link UpperEnvelope}, {@link LowerEnvelope}). */
final class Pieces {
    /**
     * A joint this close to the line through its neighbours' ends is dropped, mm: the polygons'
     * own rounding (their corners sit on a 0.00001 mm grid) is ten thousand times coarser.
     */
    static final double STRAIGHT = 1e-9;
    /**
     * A piece narrower than this is a rounding between two cuts' ends (a face at z 149.5 and one
     * at 149.50000000000003), not material: its neighbour goes on over it. The polygons' grid is
     * ten thousand times coarser, and no overlap of {@link Stock#DEPTH} fits in it.
     */
    static final double SLIVER = 1e-9;

    private Pieces() {
    }

    /** A stretch of an envelope along z, from {@code z0}: a piece, or a chunk of pieces. */
    interface Stretch {
        double z0();
    }

    /** The index of the stretch that holds z among {@code stretches} (end to end, in order): the later one where two meet. */
    static int holding(List<? extends Stretch> stretches, double z) {
        int lo = 0;
        int hi = stretches.size() - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (stretches.get(mid).z0() <= z) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        return lo;
    }

    /**
     * What an envelope holds once {@code fresh} (pieces covering [lo, hi] end to end) takes the place
     * of what {@code covered} (consecutive pieces reaching over [lo, hi]) had there: the parts of
     * {@code covered} before lo, {@code fresh}, the parts after hi, in order and not yet joined.
     */
    static List<UpperEnvelope.Piece> spliced(Iterable<UpperEnvelope.Piece> covered, double lo, double hi,
            List<UpperEnvelope.Piece> fresh) {
        List<UpperEnvelope.Piece> all = new java.util.ArrayList<>();
        List<UpperEnvelope.Piece> after = new java.util.ArrayList<>();
        for (UpperEnvelope.Piece p : covered) {
            if (p.z1() <= lo) {
                all.add(p);
            } else if (p.z0() >= hi) {
                after.add(p);
            } else {
                if (p.z0() < lo) {
                    all.add(p.cut(p.z0(), lo));
                }
                if (p.z1() > hi) {
                    after.add(p.cut(hi, p.z1()));
                }
            }
        }
        all.addAll(fresh);
        all.addAll(after);
        return all;
    }

    /**
     * Drops empty pieces and slivers, and the joints that lie on the line through their neighbours
     * (within {@link #STRAIGHT}); a corner whose two sides are a rounding apart becomes one point,
     * the higher ({@code higher}: an upper envelope, never below the material) or the lower.
     */
    static List<UpperEnvelope.Piece> join(List<UpperEnvelope.Piece> in, boolean higher) {
        List<UpperEnvelope.Piece> out = new ArrayList<>(in.size());
        for (UpperEnvelope.Piece p : in) {
            if (!(p.z0() < p.z1())) {
                continue;
            }
            if (p.z1() - p.z0() < SLIVER && !out.isEmpty()) { // a rounding's width: its neighbour goes on over it
                UpperEnvelope.Piece last = out.get(out.size() - 1);
                out.set(out.size() - 1, new UpperEnvelope.Piece(last.z0(), p.z1(), last.a(), last.b()));
                continue;
            }
            if (!out.isEmpty()) {
                UpperEnvelope.Piece last = out.get(out.size() - 1);
                if (Math.abs(last.b() - p.a()) <= STRAIGHT) {
                    double m = higher ? Math.max(last.b(), p.a()) : Math.min(last.b(), p.a());
                    UpperEnvelope.Piece line = new UpperEnvelope.Piece(last.z0(), p.z1(), last.a(), p.b());
                    if (Math.abs(line.at(p.z0()) - m) <= STRAIGHT) {
                        out.set(out.size() - 1, line);
                        continue;
                    }
                    out.set(out.size() - 1, new UpperEnvelope.Piece(last.z0(), last.z1(), last.a(), m));
                    p = new UpperEnvelope.Piece(p.z0(), p.z1(), m, p.b());
                }
            }
            out.add(p);
        }
        return out;
    }
}
