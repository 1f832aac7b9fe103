package gcnc.sim;

import gcnc.diag.Code;
import java.util.ArrayList;
import java.util.List;

/**
 * A segment that may come near the chuck, the tailstock or the stock, followed piece by piece with
 * the tool's outline ({@link ToolInUse}): the collisions with the chuck and the tailstock (E303,
 * E304), the insert's back edges meeting material (E320, E323), the stock it cuts, a rapid into it
 * (E305) and a holder in it (E315); one finding per check per block of a sequence. It remembers
 * the segments that came near and took nothing (quiet: the same again takes nothing either). The
 * findings are placed by the {@link Marker} (the {@link MotionChecks}, which knows the program's
 * coordinates).
 */
final class CloseUp {
    /** Places a finding at machine position {@code p} (counts), the tool's tip then at {@code tip}. */
    interface Marker {
        void mark(Code code, gcnc.dmc.Source place, double[] p, double[] tip, Object... lead);
    }

    private final SimMachine machine;
    /** The blank being cut, null when none. */
    private final Stock stock;
    private final double tol;
    private final double kx;
    private final double kz;
    private final Marker marker;
    private int tool;
    private ToolInUse outline;
    /** Where the tool tip was (machine counts {x, z}) when the last finding was made: its outline is drawn there. */
    private double[] tip;
    /** What this sequence has already reported: one finding per check per sequence, so one bad move is one finding. */
    private boolean chuckHit;
    private boolean tailHit;
    private boolean stockHit;
    private boolean holderHit;
    private boolean backHit;

    /** Whether the sequence being replayed really took material away (asked for with {@code judgeCut}). */
    private boolean judgeCut;
    private boolean removed;

    CloseUp(SimMachine machine, Stock stock, double tol, double kx, double kz, Marker marker) {
        this.machine = machine;
        this.stock = stock;
        this.tol = tol;
        this.kx = kx;
        this.kz = kz;
        this.marker = marker;
    }

    /** The tool in use from now on: its number (a finding names it) and its outline. */
    void tool(int n, ToolInUse outline) {
        this.tool = n;
        this.outline = outline;
    }

    /** A sequence begins: nothing reported yet, nothing removed; {@code judgeCut}: see {@link MotionChecks#sequence}. */
    void sequence(boolean judgeCut) {
        this.judgeCut = judgeCut;
        removed = false;
        block();
    }

    /** The sequence's segments of another block begin: one finding per check per motion's block. */
    void block() {
        chuckHit = tailHit = stockHit = holderHit = backHit = false;
    }

    /** Whether the sequence really took material away (asked for with {@code judgeCut}). */
    boolean removed() {
        return removed;
    }

    /**
     * A segment that may come near the chuck, the tailstock or the stock (or whose path is kept for
     * the drawing), followed piece by piece. Kept out of {@link MotionChecks#sequence}, whose loop runs
     * for every segment: the JIT compiles that loop small and this once, on its own.
     */
    void segment(Segment s, boolean rapid, gcnc.dmc.Source place, List<double[]> poly, boolean nearChuck,
                 boolean nearTail, boolean nearStock) {
        Quiet key = poly == null && !nearChuck && !nearTail ? new Quiet(tool, s.fromX(), s.fromZ(), s.toX(), s.toZ(),
                s.arc() ? s.centreX() : 0, s.arc() ? s.centreZ() : 0, s.arc() ? s.sweepDeg() : 0) : null;
        if (key != null && quiet.contains(key)) {
            return;
        }
        int n = nearStock && poly == null && !nearChuck && !nearTail ? stockPieces(s) : s.pieces();
        List<Stock.Sweep> cuts = nearStock ? new ArrayList<>(n) : List.of();
        List<Stock.Sweep> holders = nearStock ? new ArrayList<>(n) : List.of();
        List<BackEdges.Band> backs = nearStock && !rapid && outline.back.any() ? new ArrayList<>(1) : null;
        double[] a = s.at(0);
        if (poly != null) {
            poly.add(a);
        }
        for (int i = 1; i <= n; i++) {
            double[] b = i == n ? new double[] {s.toX(), s.toZ()} : s.at((double) i / n);
            if (poly != null) {
                poly.add(b);
            }
            double ar = outline.side * (a[0] - machine.centreX());
            double br = outline.side * (b[0] - machine.centreX());
            tip = b;
            if (nearChuck && !chuckHit && hits(machine.chuck(), a[1], ar, b[1], br)) {
                chuckHit = true;
                marker.mark(Code.E303_SIM_CHUCK_COLLISION, place, b, tip, toolName());
            }
            if (nearTail && !tailHit && hits(machine.tailstock(), a[1], ar, b[1], br)) {
                tailHit = true;
                marker.mark(Code.E304_SIM_TAILSTOCK_COLLISION, place, b, tip, toolName());
            }
            if (nearStock) {
                outline.sweeps(stock, a[1], ar, b[1], br, cuts, holders, backs);
            }
            a = b;
        }
        tip = new double[] {s.toX(), s.toZ()};
        if (backs != null && !backs.isEmpty() && !backHit) {
            double[] at = BackEdges.met(stock, backs, cuts);
            if (at != null) {
                backHit = true;
                Code code = outline.shape.kind().axial() ? Code.E323_SIM_AXIAL_TOOL_SIDEWAYS : Code.E320_SIM_BACK_OF_INSERT;
                marker.mark(code, place, machinePoint(at), tip, toolName());
            }
        }
        boolean touched = (!cuts.isEmpty() || !holders.isEmpty()) && stockMove(cuts, holders, rapid, place);
        if (!touched && key != null) {
            if (quiet.size() >= QUIET_MAX) {
                quiet.clear();
            }
            quiet.add(key);
        }
    }

    /**
     * A segment of a tool that came near the stock and did not reach into it. Material is only ever
     * taken away, so the same segment again (a pass retraced, a roughing cycle run twice, a
     * finishing pass over the finished part) cannot reach into it either: {@link #segment} skips it.
     */
    private record Quiet(int tool, double fromX, double fromZ, double toX, double toZ, double centreX, double centreZ,
                         double sweepDeg) {
        // written out: a record's own equals and hashCode are bootstrapped on first use (ObjectMethods),
        // 20 ms of every simulated run's start-up
        @Override
        public boolean equals(Object o) {
            return o instanceof Quiet q && tool == q.tool && same(fromX, q.fromX) && same(fromZ, q.fromZ)
                    && same(toX, q.toX) && same(toZ, q.toZ) && same(centreX, q.centreX) && same(centreZ, q.centreZ)
                    && same(sweepDeg, q.sweepDeg);
        }

        @Override
        public int hashCode() {
            int h = 31 * tool + Double.hashCode(fromX);
            h = 31 * h + Double.hashCode(fromZ);
            h = 31 * h + Double.hashCode(toX);
            h = 31 * h + Double.hashCode(toZ);
            h = 31 * h + Double.hashCode(centreX);
            h = 31 * h + Double.hashCode(centreZ);
            return 31 * h + Double.hashCode(sweepDeg);
        }

        private static boolean same(double a, double b) {
            return Double.compare(a, b) == 0;
        }
    }

    private static final int QUIET_MAX = 1 << 16;
    private final java.util.Set<Quiet> quiet = new java.util.HashSet<>();

    /**
     * One segment's effect on the stock, from the sweeps of its pieces that may reach into
     * material. A cut takes away what its insert sweeps (lazily: {@link Stock#cut}); a rapid that
     * really reaches into material is E305, and a holder that reaches into what is left after the
     * cut is E315 (both settled on the polygons). A crash is reported once, and what it went
     * through is gone: no echo in the next moves. Returns whether the segment reached into
     * material at all (a rapid or holder that only came near did not: the segment is quiet).
     */
    private boolean stockMove(List<Stock.Sweep> cuts, List<Stock.Sweep> holders, boolean rapid, gcnc.dmc.Source place) {
        if (rapid || judgeCut) {
            cuts = stock.biting(cuts);
            removed |= !rapid && !cuts.isEmpty();
        }
        holders = stock.biting(holders);
        if (cuts.isEmpty() && holders.isEmpty()) {
            return false;
        }
        boolean crashed = false;
        if (rapid && !stockHit) {
            double[] at = cuts.isEmpty() ? null : stock.deepOverlap(cuts);
            at = at != null || holders.isEmpty() ? at : stock.deepOverlap(holders);
            if (at != null) {
                stockHit = crashed = true;
                marker.mark(Code.E305_SIM_RAPID_INTO_STOCK, place, machinePoint(at), tip);
            }
        }
        for (Stock.Sweep s : cuts) {
            stock.cut(s.full());
        }
        if (!rapid && !holders.isEmpty() && !holderHit) {
            double[] at = stock.deepOverlap(holders);
            if (at != null) {
                holderHit = crashed = true;
                marker.mark(Code.E315_SIM_HOLDER_IN_STOCK, place, machinePoint(at), tip, toolName());
            }
        }
        if (crashed) {
            for (Stock.Sweep s : holders) {
                stock.cut(s.full());
            }
        }
        return true;
    }

    /** Pieces of a segment for the stock: chords within half the stock's depth of an arc (a finer cut leaves no deeper scallop). */
    private int stockPieces(Segment s) {
        if (!s.arc()) {
            return 1;
        }
        double r = s.radius() / Math.min(kx, kz);
        double sag = Stock.DEPTH / 2;
        double step = r <= sag ? 180 : Math.toDegrees(2 * Math.acos(1 - sag / r));
        return (int) Math.max(1, Math.min(256, Math.ceil(Math.abs(s.sweepDeg()) / step)));
    }

    /** A point {z, r} of the stock's frame (mm) as machine counts {x, z}. */
    private double[] machinePoint(double[] zr) {
        return new double[] {outline.side * zr[1] * kx + machine.centreX(), zr[0] * kz};
    }

    private boolean hits(Shape[] obstacles, double az, double ar, double bz, double br) {
        for (Shape o : obstacles) {
            for (Shape part : outline.shape.parts()) {
                if (Geometry.sweptHits(part, az, ar, bz, br, o, tol)) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * The tool as a finding names it: its number, and when the profile does not describe its
     * station, that the finding rests on the default outline ({@code 3 (assumed: the default C 12.7;
     * station 3 is not described)}), in the user's language.
     */
    private String toolName() {
        if (tool == 0 || machine.described(tool)) {
            return String.valueOf(tool);
        }
        return gcnc.diag.Phrase.TOOL_ASSUMED.with(tool, machine.defaultTool().name());
    }
}
