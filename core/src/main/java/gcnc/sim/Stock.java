package gcnc.sim;

import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.operation.overlayng.OverlayNG;
import org.locationtech.jts.operation.overlayng.OverlayNGRobust;

/**
 * The workpiece as an exact half-section: polygons in the (z, r) plane, millimetres of the
 * machine frame, r the radius from the spindle centreline. Every move removes exactly the area its
 * insert sweeps (the convex hull of the insert at both ends of each straight piece; an arc is cut
 * into pieces within half a count of it), with JTS doing the polygon booleans.
 *
 * <p>An overlap counts only when it is real: thicker than {@link #DEPTH} (the overlap, shrunk by
 * half of it, is not empty), never because of how the stock is held. The exact upper envelope of
 * the material ({@link UpperEnvelope}: the largest radius at each z, never below the material)
 * lets the many moves that pass above the material skip the polygon work, and the bore
 * ({@link LowerEnvelope}: the smallest, never above it) those that pass in a drilled or bored hole. A cut is taken from
 * the envelope at once and from the polygons only when they are next asked (a rapid or a holder that may reach into material, the
 * drawing), many cuts in one boolean ({@link #cut}): a program whose rapids stay clear of the
 * material does almost no polygon work.
 */
final class Stock {
    /** How deep a tool must reach into material before it counts: 0.01 mm. */
    static final double DEPTH = 0.01;

    private final GeometryFactory factory = new GeometryFactory();
    private final double back;
    private final double face;
    private final double radius;
    /** The largest radius of material at each z (never below the truth). */
    private final UpperEnvelope envelope;
    /** The exact polygons, in tiles along z ({@link Material}). */
    private final Material material;

    Stock(double back, double face, double radius) {
        this(back, face, 0, radius);
    }

    /** A blank from {@code back} to {@code face}, its material from radius {@code inner} (a bore; 0 for a bar) to {@code radius}. */
    Stock(double back, double face, double inner, double radius) {
        this(back, face, inner, radius, false);
    }

    /**
     * The same; {@code reference} true: the full model, without the shortcuts the envelopes give
     * beyond the blank's own bore (the bore is not raised by cuts from inside, and the drawing's
     * outline always comes from the polygons), for tests to hold the fast path against.
     */
    Stock(double back, double face, double inner, double radius, boolean reference) {
        this.back = back;
        this.face = face;
        this.radius = radius;
        this.reference = reference;
        this.envelope = new UpperEnvelope(back, face, inner, radius, !reference);
        this.material = new Material(factory, back, face, inner, radius);
    }

    /** The full model ({@link #Stock(double, double, double, double, boolean)}). */
    private final boolean reference;

    double back() {
        return back;
    }

    double face() {
        return face;
    }

    double initialRadius() {
        return radius;
    }

    /**
     * Could anything in z [zLo, zHi] no nearer the centreline than rMin reach more than
     * {@link #DEPTH} into material? A contact within the depth (a tool running along a face it
     * has just cut) is not: those moves skip the polygon work.
     */
    boolean mayTouch(double zLo, double zHi, double rMin) {
        return envelope.dips(zLo + DEPTH / 2, zHi - DEPTH / 2, null, rMin + DEPTH / 2);
    }

    /** The hull as a JTS polygon. */
    Geometry polygon(Hull h) {
        Coordinate[] c = new Coordinate[h.z().length + 1];
        for (int i = 0; i < h.z().length; i++) {
            c[i] = new Coordinate(h.z()[i], h.r()[i]);
        }
        c[c.length - 1] = c[0];
        return factory.createPolygon(c);
    }

    /**
     * Whether a region may reach into material, given the region drawn a little smaller (its
     * outline moved in by up to half the {@link #DEPTH}): a move that only runs along a face it
     * has just cut never does. The upper envelope answers without a polygon boolean (where the
     * hull's lower edge stays above the material's largest radius everywhere it spans, it
     * cannot touch); a yes is only a may, which {@link #deepOverlap} and {@link #cut} settle exactly.
     */
    boolean mayBite(Hull smaller) {
        return smaller != null && under(smaller);
    }

    /**
     * Takes what a sweep covers away from the material: at once from the upper envelope, from the
     * polygons when they are next needed (a rapid or a holder that may reach into the material, the
     * drawing), many cuts in one boolean. A program whose rapids stay clear of the material never
     * needs the polygons at all.
     */
    void cut(Hull full) {
        if (full == null || !under(full)) {
            return;
        }
        pending.add(full);
        envelope.lower(full);
        recent[recentNext] = full;
        recentNext = (recentNext + 1) % recent.length;
        if (pending.size() >= PENDING_MAX) {
            settle();
        }
    }

    /** A piece's sweep at full size, and drawn a little smaller ({@link Hull#smaller}) to tell a real bite from a touch. */
    record Sweep(Hull full, Hull smaller) {
    }

    /**
     * The sweeps whose smaller outline really reaches into material (the polygons' answer, with
     * the pending cuts taken first): what a rapid or a holder is checked with.
     */
    java.util.List<Sweep> biting(java.util.List<Sweep> sweeps) {
        if (sweeps.isEmpty()) {
            return sweeps;
        }
        settle();
        java.util.List<Sweep> out = new java.util.ArrayList<>(sweeps.size());
        for (Sweep s : sweeps) {
            if (s.full() != null && s.smaller() != null && touches(polygon(s.smaller()))) {
                out.add(s);
            }
        }
        return out;
    }

    /** Cuts taken from the envelope but not yet from the polygons ({@link #cut}). */
    private final java.util.List<Hull> pending = new java.util.ArrayList<>();
    /**
     * At most this many cuts wait for the polygons (a hull is a dozen corners: about a MiB), so
     * memory stays flat; a program whose rapids never come near the material settles them in one
     * boolean every this many cuts.
     */
    private static final int PENDING_MAX = 4096;

    /** Takes the pending cuts from the polygons (per tile: one union, one difference). */
    private void settle() {
        if (pending.isEmpty()) {
            return;
        }
        java.util.List<Geometry> cuts = new java.util.ArrayList<>(pending.size());
        for (Hull h : pending) {
            cuts.add(polygon(h));
        }
        pending.clear();
        remove(cuts);
    }

    /**
     * Whether the hull dips below the upper envelope somewhere and is not in the bore (the
     * envelope is never below the material, the bore never above it: a no is certain).
     */
    private boolean under(Hull h) {
        return envelope.dips(h.zMin(), h.zMax(), h, 0) && (reference || !envelope.inBore(h) && !cutAlready(h));
    }

    /**
     * The last few cuts: a sweep inside one of them meets no material (material is never added),
     * such as a drill's retract along the hole it has just drilled, whose hull is the feed's.
     */
    private final Hull[] recent = new Hull[4];
    private int recentNext;

    private boolean cutAlready(Hull h) {
        for (Hull c : recent) {
            if (c != null && Hull.inside(h, c)) {
                return true;
            }
        }
        return false;
    }

    /** A point where the sweeps reach more than {@link #DEPTH} into material, {z, r}; null if nowhere. */
    double[] deepOverlap(java.util.List<Sweep> sweeps) {
        java.util.List<Geometry> parts = new java.util.ArrayList<>(sweeps.size());
        for (Sweep s : sweeps) {
            if (s.full() != null) {
                parts.add(polygon(s.full()));
            }
        }
        return parts.isEmpty() ? null : deepIn(parts.size() == 1 ? parts.get(0) : OverlayNGRobust.union(parts));
    }

    /**
     * A point where the union of {@code regions} reaches more than {@link #DEPTH} into material,
     * each region without what the first {@code before[i]} of {@code cuts} cover (cuts of the same
     * move that are not yet taken from the stock: they take their material first); null if nowhere.
     * The regions are judged together, so that a move cut into many short pieces (an arc) is judged
     * as the whole move.
     */
    double[] deepOverlap(java.util.List<Hull> regions, int[] before, java.util.List<Sweep> cuts) {
        java.util.List<Geometry> parts = new java.util.ArrayList<>(regions.size());
        for (int i = 0; i < regions.size(); i++) {
            Geometry g = polygon(regions.get(i));
            if (before[i] > 0) {
                java.util.List<Geometry> taken = new java.util.ArrayList<>(before[i]);
                for (Sweep c : cuts.subList(0, before[i])) {
                    taken.add(polygon(c.full()));
                }
                g = OverlayNGRobust.overlay(g, OverlayNGRobust.union(taken), OverlayNG.DIFFERENCE);
            }
            parts.add(g);
        }
        return parts.isEmpty() ? null : deepIn(parts.size() == 1 ? parts.get(0) : OverlayNGRobust.union(parts));
    }

    /** A point where {@code region} reaches more than {@link #DEPTH} into material (the pending cuts taken first), or null. */
    private double[] deepIn(Geometry region) {
        settle();
        if (region.isEmpty() || !touches(region)) {
            return null;
        }
        // only the tiles the region spans: the finding is derived from the material near the move
        Geometry overlap = material.intersection(region);
        if (overlap.isEmpty() || overlap.getArea() == 0) {
            return null;
        }
        Geometry core = overlap.buffer(-DEPTH / 2);
        if (core.isEmpty()) {
            return null;
        }
        Coordinate p = core.getInteriorPoint().getCoordinate();
        return new double[] {p.x, p.y};
    }

    /** Removes the cuts from the polygons (what the insert cuts away). Material is never added. */
    private void remove(java.util.List<Geometry> cuts) {
        // not the envelope's answer: it was lowered under these cuts already ({@link #lower})
        double[] changed = material.remove(cuts);
        if (changed != null) {
            refresh(Math.max(back, changed[0]), Math.min(face, changed[1]));
        }
    }

    private boolean touches(Geometry region) {
        Envelope e = region.getEnvelopeInternal();
        if (!mayTouch(e.getMinX(), e.getMaxX(), e.getMinY())) {
            return false;
        }
        return material.intersects(region);
    }

    /** Rebuilds the envelope over z [lo, hi] from the material's edges (only the tiles over them). */
    private void refresh(double lo, double hi) {
        if (!(lo < hi)) {
            return;
        }
        EdgeEnvelope r = new EdgeEnvelope(lo, hi);
        material.edges(lo, hi, r::edge);
        envelope.replace(lo, hi, r.pieces());
    }

    /** Corners handed to the polygon booleans so far: what a ragged stock costs, for tests to bound. */
    long work() {
        return material.work();
    }

    /** How many corners the material's polygons have (the pending cuts taken first). */
    int corners() {
        settle();
        return material.corners();
    }

    /**
     * The finished part's outline, back to face: the largest radius of material left at each z
     * (mm), as points, a face as two points at one z; at most 4096 of them (a drawing needs no more).
     * While every cut took all above its lower edge the envelope is that outline already; else the
     * pending cuts go into the polygons first and the envelope is rebuilt from them.
     */
    double[][] profile() {
        if (reference || !envelope.solid()) {
            settle(); // the polygons know what a cut under material took
        }
        return envelope.outline(4096);
    }

    /** Whether the envelope is the material's outline without the polygons ({@link UpperEnvelope#solid}). */
    boolean envelopeSolid() {
        return envelope.solid();
    }

    /** The bore's radius at z ({@link LowerEnvelope}; tests read it). */
    double boreAt(double z) {
        return envelope.bore().at(z);
    }

    /** How many straight pieces the envelope holds (tests bound it). */
    int envelopePieces() {
        return envelope.size();
    }
}
