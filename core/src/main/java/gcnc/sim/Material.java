package gcnc.sim;

import org.locationtech.jts.geom.Coordinate;
import org.locationtech.jts.geom.Envelope;
import org.locationtech.jts.geom.Geometry;
import org.locationtech.jts.geom.GeometryFactory;
import org.locationtech.jts.geom.LineString;
import org.locationtech.jts.geom.Polygon;
import org.locationtech.jts.geom.PrecisionModel;
import org.locationtech.jts.geom.prep.PreparedGeometry;
import org.locationtech.jts.geom.prep.PreparedGeometryFactory;
import org.locationtech.jts.operation.overlayng.OverlayNG;
import org.locationtech.jts.operation.overlayng.OverlayNGRobust;
import org.locationtech.jts.operation.overlayng.UnaryUnionNG;
import org.locationtech.jts.simplify.DouglasPeuckerSimplifier;
import java.util.ArrayList;
import java.util.List;

/**
 * The blank's material as exact polygons of the (z, r) half-section, held in tiles along z
 * ({@link #TILE} mm wide) so that a cut or a test costs what the tiles it spans hold, not what the
 * whole part holds: a program that leaves the stock ragged (thousands of rapids into the blank, a
 * peck of a ten-thousandth) stays linear in its moves instead of redoing an ever larger polygon
 * boolean per move.
 *
 * <p>Every boolean snaps its corners to a grid of {@link #GRID} mm (JTS snap rounding: robust, no
 * fallback to slower noders when two edges nearly meet), and after each cut the corners that lie
 * exactly on a straight line between their neighbours are dropped (a groove deepened peck by peck
 * would otherwise keep two corners per peck on its walls). Both move an edge by at most half the
 * grid, 0.000005 mm: far inside the {@link Stock#DEPTH} an overlap must exceed to count, so a move
 * reaching more than DEPTH + 0.00001 mm into the material is always found and one reaching less
 * than DEPTH − 0.00001 mm never is.
 */
final class Material {
    /** Width of a tile along z, mm (the last one takes the remainder). */
    static final double TILE = 2.0;
    /** The grid every corner is snapped to, mm. */
    static final double GRID = 1e-5;
    private static final PrecisionModel PM = new PrecisionModel(1 / GRID);
    /** Below the distance between two grid points off a line: only corners exactly on a line are dropped. */
    private static final double COLLINEAR = 1e-9;

    private final GeometryFactory factory;
    private final double back;
    private final double width;
    /** Where tile k begins (k = 0 .. n), on the grid. */
    private final double[] bounds;
    private final Geometry[] tiles;
    private final PreparedGeometry[] prepared;
    /** Corners handed to JTS so far (each boolean and each preparation counts its tile's): the cost a test can bound. */
    private long work;

    Material(GeometryFactory factory, double back, double face, double inner, double radius) {
        this.factory = factory;
        this.back = back;
        int n = (int) Math.max(1, Math.ceil((face - back) / TILE));
        this.width = (face - back) / n;
        this.bounds = new double[n + 1];
        this.tiles = new Geometry[n];
        this.prepared = new PreparedGeometry[n];
        for (int k = 0; k <= n; k++) {
            bounds[k] = k == n ? PM.makePrecise(face) : PM.makePrecise(back + k * width);
        }
        for (int k = 0; k < n; k++) {
            tiles[k] = factory.toGeometry(new Envelope(bounds[k], bounds[k + 1], PM.makePrecise(inner),
                    PM.makePrecise(radius)));
        }
    }

    /** The tile that holds z (clamped to the blank). */
    private int tile(double z) {
        return (int) Math.max(0, Math.min(tiles.length - 1, Math.floor((z - back) / width)));
    }

    /** The tiles an envelope spans, {first, last}; a tile's neighbour too when z is on their border. */
    private int[] span(Envelope e) {
        return new int[] {tile(e.getMinX() - GRID), tile(e.getMaxX() + GRID)};
    }

    private PreparedGeometry prepared(int k) {
        if (prepared[k] == null) {
            work += tiles[k].getNumPoints();
            prepared[k] = PreparedGeometryFactory.prepare(tiles[k]);
        }
        return prepared[k];
    }

    /** Whether the region shares a point with the material. */
    boolean intersects(Geometry region) {
        int[] s = span(region.getEnvelopeInternal());
        for (int k = s[0]; k <= s[1]; k++) {
            if (!tiles[k].isEmpty() && prepared(k).intersects(region)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Takes the cuts away from the material: the cuts that reach into some tile are unioned once,
     * and each tile they reach takes the difference (JTS clips the union to the tile's box first).
     * Returns the z range that changed, {zLo, zHi}, or null if none did.
     *
     * <p>One union for all the tiles, not one per tile: a turning pass 40 mm long spans 20 tiles,
     * and a union per tile redid the same union of every pass over each of them (the drawing of a
     * 2,000-block roughing program waited 0.7 s for it).
     */
    double[] remove(List<Geometry> cuts) {
        boolean[] reached = new boolean[tiles.length];
        List<Geometry> hit = new ArrayList<>(cuts.size());
        for (Geometry c : cuts) {
            int[] s = span(c.getEnvelopeInternal());
            boolean any = false;
            for (int k = s[0]; k <= s[1]; k++) {
                if (!tiles[k].isEmpty() && prepared(k).intersects(c)) {
                    reached[k] = true;
                    any = true;
                }
            }
            if (any) {
                hit.add(c);
            }
        }
        if (hit.isEmpty()) {
            return null;
        }
        Geometry region = hit.size() == 1 ? hit.get(0) : UnaryUnionNG.union(factory.buildGeometry(hit), PM);
        int first = -1;
        int last = -1;
        for (int k = 0; k < tiles.length; k++) {
            if (!reached[k]) {
                continue;
            }
            work += tiles[k].getNumPoints();
            tiles[k] = straighten(OverlayNG.overlay(tiles[k], region, OverlayNG.DIFFERENCE, PM));
            prepared[k] = null;
            first = first < 0 ? k : first;
            last = k;
        }
        return new double[] {bounds[first], bounds[last + 1]};
    }

    /** The material inside the region, its pieces in neighbouring tiles joined; empty if none. */
    Geometry intersection(Geometry region) {
        int[] s = span(region.getEnvelopeInternal());
        List<Geometry> pieces = new ArrayList<>();
        for (int k = s[0]; k <= s[1]; k++) {
            if (!tiles[k].isEmpty() && prepared(k).intersects(region)) {
                work += tiles[k].getNumPoints();
                Geometry piece = OverlayNG.overlay(tiles[k], region, OverlayNG.INTERSECTION, PM);
                if (!piece.isEmpty()) {
                    pieces.add(piece);
                }
            }
        }
        if (pieces.isEmpty()) {
            return factory.createPolygon();
        }
        // joined across the tiles' borders, so that an overlap thicker than the depth is one piece
        return pieces.size() == 1 ? pieces.get(0) : OverlayNGRobust.union(pieces);
    }

    /** Drops the corners that lie exactly on a line between their neighbours (see the class comment). */
    private static Geometry straighten(Geometry g) {
        if (g.isEmpty()) {
            return g;
        }
        DouglasPeuckerSimplifier s = new DouglasPeuckerSimplifier(g);
        s.setDistanceTolerance(COLLINEAR);
        s.setEnsureValid(false); // only corners on a line go: the outline does not move
        return s.getResultGeometry();
    }

    /** Calls back with every edge of the material's outlines over z [zLo, zHi] (tiles' borders included). */
    void edges(double zLo, double zHi, EdgeVisitor v) {
        for (int k = tile(zLo - GRID); k <= tile(zHi + GRID); k++) {
            Geometry t = tiles[k];
            for (int n = 0; n < t.getNumGeometries(); n++) {
                if (!(t.getGeometryN(n) instanceof Polygon p)) {
                    continue; // a difference leaves polygons; anything else has no area
                }
                ring(p.getExteriorRing(), v);
                for (int h = 0; h < p.getNumInteriorRing(); h++) {
                    ring(p.getInteriorRingN(h), v);
                }
            }
        }
    }

    private static void ring(LineString ring, EdgeVisitor v) {
        Coordinate[] c = ring.getCoordinates();
        for (int k = 1; k < c.length; k++) {
            v.edge(c[k - 1], c[k]);
        }
    }

    interface EdgeVisitor {
        void edge(Coordinate a, Coordinate b);
    }

    /** Corners handed to JTS so far (see {@link #work}). */
    long work() {
        return work;
    }

    /** How many corners the material has (for tests: a ragged stock stays bounded). */
    int corners() {
        int n = 0;
        for (Geometry t : tiles) {
            n += t.getNumPoints();
        }
        return n;
    }
}
