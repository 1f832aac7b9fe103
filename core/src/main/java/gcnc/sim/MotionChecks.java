package gcnc.sim;

import gcnc.diag.Code;
import gcnc.ir.ArcGeometry;
import gcnc.ir.Motion;
import gcnc.machine.MachineModel;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;

/**
 * The geometric checks on each replayed sequence (travel, chuck, tailstock, rapid into stock,
 * path conformance), the stock removal, and what the report measures (envelope, cycle time,
 * drawing). One finding per check per sequence, so one bad move is one finding.
 */
final class MotionChecks {
    interface Reporter {
        void report(Code code, int line, Object... args);
    }

    private final MachineProfile profile;
    private final SimMachine machine;
    private final Reporter out;
    private final double tol;
    private final Stock stock;
    /** The blank simulated, null when none. */
    private final StockSize blank;
    /** The envelope in the program's terms, the tools' use: what a person reads ({@link SimReport#program()}). */
    private final ProgramTerms terms;
    private final double kx;
    private final double kz;
    /** The current tool's insert and holder relative to its tip, mm ({z[], r[]}; holder null if none). */
    private double[][] insertMm;
    private double[][] holderMm;
    /** The same outlines drawn a little smaller ({@link Stock#smaller}), to tell a real bite from a touch. */
    private double[][] insertIn;
    private double[][] holderIn;
    /** How far each part reaches from the tip, mm: {dr-, dz-, dz+} of the insert and of the holder. */
    private double[] insertReach;
    private double[] holderReach;
    /** The insert's edges that do not cut (E320, E323 for a drill, centre drill or tap). */
    private BackEdges back = BackEdges.NONE;
    /** The side of the centreline the tool works on: 1 (+X) or -1 (-X, a gang lathe's tools). */
    private int side = 1;
    private final PathRecorder path;
    private final Conformance conformance;
    private int tool;
    /** {rMin, rMax, zMin, zMax} of the chuck and tailstock (counts, radius), empty = none. */
    private final double[] chuckBox;
    private final double[] tailBox;
    /** How far the tool outline reaches from its tip: {dr-, dr+, dz-, dz+}. */
    private double[] reach = new double[4];
    private SimMachine.ToolShape toolShape;
    private int sequences;
    private int segments;
    private double seconds;
    /** What the cycle would take if every motion stopped at its end: what blending gains is the difference. */
    private double exactStopSeconds;
    private double xMin = Double.POSITIVE_INFINITY;
    private double xMax = Double.NEGATIVE_INFINITY;
    private double zMin = Double.POSITIVE_INFINITY;
    private double zMax = Double.NEGATIVE_INFINITY;

    MotionChecks(MachineProfile profile, SimMachine machine, SimOptions options, Reporter out) {
        this.profile = profile;
        this.machine = machine;
        this.out = out;
        this.tol = options.tolerance();
        this.kx = profile.x().countsPerMm();
        this.kz = profile.z().countsPerMm();
        StockSize s = options.noBlank() ? null : options.stock().orElse(machine.stock().orElse(null));
        java.util.Optional<StockSize.Beyond> beyond = s == null ? java.util.Optional.empty() : s.beyond(profile);
        if (beyond.isPresent()) {
            // a stock header's or NO STOCK's size the machine cannot hold: said at the program's first
            // line (where the header is), and the run goes on without a blank rather than model it
            out.report(beyond.get().code(), 1, StockSize.shown(beyond.get().value()), mm(beyond.get().limit()), profile.name());
            s = null;
        }
        if (s != null && !Double.isNaN(machine.chuckFace())) {
            double face = machine.chuckFace() / kz + s.stickout();
            stock = new Stock(face - s.length(), face, s.bore() / 2, s.diameter() / 2, options.referenceStock());
            blank = s;
        } else {
            stock = null;
            blank = null;
        }
        terms = new ProgramTerms(profile);
        path = options.keepPath() ? new PathRecorder(profile, machine.centreX(), options.scrubLine() == 0) : null;
        scrub = path == null || options.scrubLine() == 0 ? null : new StockScrub(options.scrubLine(), stock);
        conformance = new Conformance(out, path, tol, Simulator.threadTolerance(profile, options));
        toolShape = machine.defaultTool();
        chuckBox = box(machine.chuck());
        tailBox = box(machine.tailstock());
        reach = reach(toolShape);
        outlines();
    }

    /** Whether the run has a blank to cut (from --stock, the program's stock header or the profile). */
    boolean hasStock() {
        return stock != null;
    }

    private void outlines() {
        insertMm = toolShape == null ? null : mm(toolShape.insert());
        holderMm = toolShape == null || toolShape.holder() == null ? null : mm(toolShape.holder());
        insertIn = insertMm == null ? null : Stock.smaller(insertMm[0], insertMm[1]);
        holderIn = holderMm == null ? null : Stock.smaller(holderMm[0], holderMm[1]);
        insertReach = insertMm == null ? null : partReach(insertMm);
        holderReach = holderMm == null ? null : partReach(holderMm);
        back = insertMm == null ? BackEdges.NONE : BackEdges.of(insertMm, toolShape.back());
        side = toolShape == null ? 1 : toolShape.side();
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

    private static double[] box(Shape[] shapes) {
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

    /** Can the tool, its tip anywhere in the segment box {xMin, xMax, zMin, zMax}, reach the obstacle box? */
    private boolean near(double[] obstacle, double[] seg) {
        if (obstacle == null) {
            return false;
        }
        double rLo = radius(seg[0], seg[1]);
        double rHi = side > 0 ? seg[1] - centre() : centre() - seg[0];
        return rLo + reach[0] < obstacle[1] + tol && rHi + reach[1] > obstacle[0] - tol
                && seg[2] + reach[2] < obstacle[3] + tol && seg[3] + reach[3] > obstacle[2] - tol;
    }

    int tool() {
        return tool;
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

    /** The program coordinates of the block being replayed (null for a bare DMC replay). */
    private gcnc.ir.ProgramFrame frame;

    void frame(gcnc.ir.ProgramFrame f) {
        frame = f;
        terms.frame(f);
        frames = null;
    }

    /** The program frame of each segment of the next sequence, when it carries several blocks (null: one frame). */
    private gcnc.ir.ProgramFrame[] frames;

    void frames(gcnc.ir.ProgramFrame[] perSegment) {
        frames = perSegment;
    }

    /** The spindle was set to {@code rpm} (for the setup sheet's highest speed). */
    void spindle(double rpm) {
        terms.spindle(rpm);
    }

    /** Where the tool tip was (machine counts {x, z}) when the last finding was made: its outline is drawn there. */
    private double[] tip;

    /** The number of the DMC line being replayed (a finding without a program frame is placed by it). */
    private int dmcLine;

    void dmcLine(int n) {
        dmcLine = n;
    }

    void selectTool(int n) {
        tool = n;
        toolShape = machine.tool(n);
        reach = reach(toolShape);
        outlines();
    }

    /** A program stop: counted, no time (the operator's wait is not the machine's). */
    void programStop() {
        programStops++;
    }

    private int programStops;

    /** The cycle clock so far: what {@link SimReport#cycleSeconds} will say of the lines replayed up to now. */
    double seconds() {
        return seconds;
    }

    void dwell(double s) {
        seconds += s;
        terms.time(tool, s);
        exactStopSeconds += s;
    }

    /** What this sequence has already reported: one finding per check per sequence, so one bad move is one finding. */
    private boolean chuckHit;
    private boolean tailHit;
    private boolean stockHit;
    private boolean holderHit;
    private boolean backHit;

    /** Whether the sequence being replayed really took material away (asked for with {@code judgeCut}). */
    private boolean judgeCut;
    private boolean removed;

    /**
     * Replays one sequence. With {@code judgeCut} the stock is asked exactly whether the move takes
     * more than {@link Stock#DEPTH} of material (a feed with the spindle stopped or the chuck open:
     * a bar puller's pull in the air is no cut, E306/E307 are for a real one); returns that answer,
     * false without {@code judgeCut}.
     */
    boolean sequence(List<Segment> segs, double speed, boolean rapid, int line, double acc, double dec,
                     boolean judgeCut) {
        if (scrub != null) {
            scrub.before(line, sequences);
        }
        this.judgeCut = judgeCut;
        removed = false;
        sequences++;
        segments += segs.size();
        double length = 0;
        boolean travelX = false;
        boolean travelZ = false;
        chuckHit = tailHit = stockHit = holderHit = backHit = false;
        List<double[]> poly = path == null ? null : new ArrayList<>();
        int polyLine = line;
        boolean blended = false;
        for (Segment s : segs) {
            blended = blended || !Double.isNaN(s.speed()) || !Double.isNaN(s.end());
        }
        double entry = 0;
        double secondsBefore = seconds;
        long lastBlock = -1;
        for (int k = 0; k < segs.size(); k++) {
            Segment s = segs.get(k);
            // a sequence may carry several blocks: each segment's findings go to its own block's line
            int at = s.source() != null && s.source().line() > 0 ? s.source().line() : line;
            long block = s.source() == null ? -1 : s.source().block();
            if (k > 0 && (at != polyLine || block != lastBlock)) {
                // one finding per check per motion's block: a sequence of several blocks reports each one's
                chuckHit = tailHit = stockHit = holderHit = backHit = false;
            }
            lastBlock = block;
            if (frames != null && frames[k] != null && frames[k] != frame) {
                frame = frames[k];
                terms.frame(frame);
            }
            if (poly != null && at != polyLine && !poly.isEmpty()) {
                path.move(rapid, poly, polyLine, frame == null ? null : frame.file(), tool);
                poly = new ArrayList<>();
            }
            polyLine = at;
            length += s.length();
            double[] box = bounds(s);
            xMin = Math.min(xMin, box[0]);
            xMax = Math.max(xMax, box[1]);
            zMin = Math.min(zMin, box[2]);
            zMax = Math.max(zMax, box[3]);
            terms.box(box, rapid);
            travelX = travelX || travel(at, "X", box[0], box[1], profile.x().min(), profile.x().max(),
                    profile.x().countsPerMm());
            travelZ = travelZ || travel(at, "Z", box[2], box[3], profile.z().min(), profile.z().max(),
                    profile.z().countsPerMm());
            double rMin = radius(box[0], box[1]);
            boolean nearChuck = near(chuckBox, box);
            boolean nearTail = near(tailBox, box);
            // a bar puller grips the bar: it neither cuts nor crashes into it
            boolean nearStock = stock != null && insertMm != null && toolShape.kind() != MachineModel.ToolKind.PULLER
                    && stock.mayTouch((box[2] + reach[2]) / kz,
                    (box[3] + reach[3]) / kz, (rMin + reach[0]) / kx);
            if (poly != null || nearChuck || nearTail || nearStock) {
                closeUp(s, rapid, at, poly, nearChuck, nearTail, nearStock);
            }
            if (blended) {
                // the segment at its own speed, from the corner before it to the corner after it
                double v = Double.isNaN(s.speed()) ? speed : s.speed();
                double exit = k == segs.size() - 1 ? 0 : Double.isNaN(s.end()) ? v : s.end();
                seconds += Profiles.time(s.length(), entry, v, exit, acc, dec);
                exactStopSeconds += time(s.length(), v, acc, dec);
                entry = exit;
            }
        }
        if (!blended) {
            double t = time(length, speed, acc, dec);
            seconds += t;
            exactStopSeconds += t;
        }
        terms.move(tool, line, seconds - secondsBefore);
        if (poly != null) {
            path.move(rapid, poly, polyLine, frame == null ? null : frame.file(), tool);
            path.frame(frame, rapid);
        }
        if (scrub != null && scrub.inRun() && !segs.isEmpty()) {
            Segment last = segs.get(segs.size() - 1);
            double tipZ = last.toZ() / kz;
            double tipR = (last.toX() - centre()) / kx;
            scrub.after(sequences - 1, tool, placed(insertMm, tipZ, tipR), placed(holderMm, tipZ, tipR));
        }
        return removed;
    }

    /** The studio's scrub ({@link SimOptions#withScrub}), null when none was asked for. */
    private final StockScrub scrub;

    /** A tool part's outline (mm from the tip, on the tool's side) with its tip at (z, r) of the drawing. */
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
     * A segment that may come near the chuck, the tailstock or the stock (or whose path is kept for
     * the drawing), followed piece by piece. Kept out of {@link #sequence}, whose loop runs for
     * every segment: the JIT compiles that loop small and this once, on its own.
     */
    private void closeUp(Segment s, boolean rapid, int line, List<double[]> poly, boolean nearChuck,
                         boolean nearTail, boolean nearStock) {
        Quiet key = poly == null && !nearChuck && !nearTail ? new Quiet(tool, s.fromX(), s.fromZ(), s.toX(), s.toZ(),
                s.arc() ? s.centreX() : 0, s.arc() ? s.centreZ() : 0, s.arc() ? s.sweepDeg() : 0) : null;
        if (key != null && quiet.contains(key)) {
            return;
        }
        int n = nearStock && poly == null && !nearChuck && !nearTail ? stockPieces(s) : s.pieces();
        List<Stock.Sweep> cuts = nearStock ? new ArrayList<>(n) : List.of();
        List<Stock.Sweep> holders = nearStock ? new ArrayList<>(n) : List.of();
        List<BackEdges.Band> backs = nearStock && !rapid && back.any() ? new ArrayList<>(1) : null;
        double[] a = s.at(0);
        if (poly != null) {
            poly.add(a);
        }
        for (int i = 1; i <= n; i++) {
            double[] b = i == n ? new double[] {s.toX(), s.toZ()} : s.at((double) i / n);
            if (poly != null) {
                poly.add(b);
            }
            double ar = side * (a[0] - machine.centreX());
            double br = side * (b[0] - machine.centreX());
            tip = b;
            if (nearChuck && !chuckHit && hits(machine.chuck(), a[1], ar, b[1], br)) {
                chuckHit = true;
                mark(Code.E303_SIM_CHUCK_COLLISION, line, b, toolName());
            }
            if (nearTail && !tailHit && hits(machine.tailstock(), a[1], ar, b[1], br)) {
                tailHit = true;
                mark(Code.E304_SIM_TAILSTOCK_COLLISION, line, b, toolName());
            }
            if (nearStock) {
                stockPiece(a[1], ar, b[1], br, cuts, holders, backs);
            }
            a = b;
        }
        tip = new double[] {s.toX(), s.toZ()};
        if (backs != null && !backs.isEmpty() && !backHit) {
            double[] at = BackEdges.met(stock, backs, cuts);
            if (at != null) {
                backHit = true;
                mark(toolShape.kind().axial() ? Code.E323_SIM_AXIAL_TOOL_SIDEWAYS : Code.E320_SIM_BACK_OF_INSERT, line,
                        machinePoint(at), toolName());
            }
        }
        boolean touched = (!cuts.isEmpty() || !holders.isEmpty()) && stockMove(cuts, holders, rapid, line);
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
     * finishing pass over the finished part) cannot reach into it either: {@link #closeUp} skips it.
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
     * One straight piece near the stock (tip from z a, radius ar to z b, radius br; counts): the
     * sweeps of the insert and the holder that may reach into material, for {@link #stockMove}.
     */
    private void stockPiece(double a, double ar, double b, double br, List<Stock.Sweep> cuts,
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
            Stock.Hull smaller = Stock.sweep(insertIn[0], insertIn[1], az, ar / kx, bz, br / kx);
            if (stock.mayBite(smaller)) {
                cuts.add(new Stock.Sweep(Stock.sweep(insertMm[0], insertMm[1], az, ar / kx, bz, br / kx), smaller));
            }
            if (backs != null) {
                back.piece(stock, az, ar / kx, bz, br / kx, backs, earlier);
            }
        }
        if (holderMm != null && stock.mayTouch(lo + holderReach[1], hi + holderReach[2], r + holderReach[0])) {
            Stock.Hull smaller = Stock.sweep(holderIn[0], holderIn[1], az, ar / kx, bz, br / kx);
            if (stock.mayBite(smaller)) {
                holders.add(new Stock.Sweep(Stock.sweep(holderMm[0], holderMm[1], az, ar / kx, bz, br / kx), smaller));
            }
        }
    }

    /**
     * One segment's effect on the stock, from the sweeps of its pieces that may reach into
     * material. A cut takes away what its insert sweeps (lazily: {@link Stock#cut}); a rapid that
     * really reaches into material is E305, and a holder that reaches into what is left after the
     * cut is E315 (both settled on the polygons). A crash is reported once, and what it went
     * through is gone: no echo in the next moves. Returns whether the segment reached into
     * material at all (a rapid or holder that only came near did not: the segment is quiet).
     */
    private boolean stockMove(List<Stock.Sweep> cuts, List<Stock.Sweep> holders, boolean rapid, int line) {
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
                mark(Code.E305_SIM_RAPID_INTO_STOCK, line, machinePoint(at));
            }
        }
        for (Stock.Sweep s : cuts) {
            stock.cut(s.full());
        }
        if (!rapid && !holders.isEmpty() && !holderHit) {
            double[] at = stock.deepOverlap(holders);
            if (at != null) {
                holderHit = crashed = true;
                mark(Code.E315_SIM_HOLDER_IN_STOCK, line, machinePoint(at), toolName());
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
        return new double[] {side * zr[1] * kx + centre(), zr[0] * kz};
    }

    /** See {@link Conformance#check}. */
    double[] conformance(Motion m, List<Segment> segs, int line) {
        return conformance.check(m, segs, line);
    }

    private double centre() {
        return machine.centreX();
    }

    /**
     * The smallest radius (counts from the centreline, on the tool's side) of a tip anywhere from
     * machine X {@code xLo} to {@code xHi}: a tool on the -X side (a gang lathe's) sees the part
     * mirrored through the axis, so the half-section and the tool's outline stay as they are.
     */
    private double radius(double xLo, double xHi) {
        return side > 0 ? xLo - centre() : centre() - xHi;
    }

    private boolean hits(Shape[] obstacles, double az, double ar, double bz, double br) {
        for (Shape o : obstacles) {
            for (Shape part : toolShape.parts()) {
                if (Geometry.sweptHits(part, az, ar, bz, br, o, tol)) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * The finding, at machine position p = {x, z} (counts), with its place kept for the SVG: after
     * the lead arguments, where it is as the program writes it (X as a diameter, Z from work zero,
     * the DMC's line when the program frame is not known), the block's N word ("N110; " or ""), and the
     * machine position in mm. Without the program frame (a DMC replayed by itself: the work offsets
     * are not in it) the place is the DMC's line, "DMC line 57", whatever line the finding is
     * reported at (a source map's G-code line).
     */
    private void mark(Code code, int line, double[] p, Object... lead) {
        Object[] args = new Object[lead.length + 4];
        System.arraycopy(lead, 0, args, 0, lead.length);
        if (frame == null) {
            args[lead.length] = gcnc.diag.Phrase.DMC_LINE.with(dmcLine);
            args[lead.length + 1] = "";
        } else {
            args[lead.length] = "X" + programmed((p[0] - frame.origin().x()) / frame.perX())
                    + " Z" + programmed((p[1] - frame.origin().z()) / frame.perZ());
            args[lead.length + 1] = frame.sequence().isEmpty() ? "" : frame.sequence() + "; ";
        }
        args[lead.length + 2] = mm(p[0] / profile.x().countsPerMm());
        args[lead.length + 3] = mm(p[1] / profile.z().countsPerMm());
        out.report(code, line, args);
        if (path != null) {
            String block = frame != null && !frame.sequence().isEmpty() ? frame.sequence() : "line " + line;
            path.mark(code.id(), block, line, p[0], p[1], toolShape, side, tip);
        }
    }

    /** A program coordinate as a program writes it, always with its decimal point: 42., -20.5. */
    private static String programmed(double v) {
        String t = mm(v);
        return t.contains(".") ? t : t + ".";
    }

    /**
     * E302: where the axis went as the program writes it first ("X460.", the block's N word), then
     * in the machine frame against the travel; without the program frame (a DMC replayed by itself)
     * the place is the DMC's line.
     */
    private boolean travel(int line, String axis, double lo, double hi, double min, double max, double perMm) {
        if (lo >= min - tol && hi <= max + tol) {
            return false;
        }
        double bad = lo < min - tol ? lo : hi;
        Object where;
        String block = "";
        if (frame == null) {
            where = gcnc.diag.Phrase.DMC_LINE.with(dmcLine);
        } else {
            boolean x = axis.equals("X");
            where = axis + programmed((bad - (x ? frame.origin().x() : frame.origin().z())) / (x ? frame.perX() : frame.perZ()));
            block = frame.sequence().isEmpty() ? "" : frame.sequence() + "; ";
        }
        out.report(Code.E302_SIM_TRAVEL, line, axis, where, block, mm(bad / perMm), mm(min / perMm), mm(max / perMm));
        return true;
    }

    /** {xMin, xMax, zMin, zMax} of a segment: an arc's extremes where it crosses 0/90/180/270 degrees. */
    static double[] bounds(Segment s) {
        if (!s.arc()) {
            return new double[] {Math.min(s.fromX(), s.toX()), Math.max(s.fromX(), s.toX()),
                Math.min(s.fromZ(), s.toZ()), Math.max(s.fromZ(), s.toZ())};
        }
        return ArcGeometry.bounds(s.fromX(), s.fromZ(), s.toX(), s.toZ(), s.centreX(), s.centreZ(), s.radius(),
                s.startDeg(), s.sweepDeg());
    }

    /** Trapezoidal speed profile from rest to rest; a triangle when the move is too short to reach v. */
    static double time(double length, double v, double acc, double dec) {
        if (length <= 0 || v <= 0) {
            return 0;
        }
        double ramps = v * v / (2 * acc) + v * v / (2 * dec);
        if (length >= ramps) {
            return length / v + v / (2 * acc) + v / (2 * dec);
        }
        double peak = Math.sqrt(2 * length * acc * dec / (acc + dec));
        return peak / acc + peak / dec;
    }

    /** Up to 3 decimals, no trailing zeros: 12.5, -3, 0.001. */
    static String mm(double v) {
        double r = Math.rint(v * 1000) / 1000;
        if (r == Math.rint(r) && Math.abs(r) < 1e15) {
            return Long.toString((long) r);
        }
        return java.math.BigDecimal.valueOf(r).stripTrailingZeros().toPlainString();
    }

    SimReport report(int findings) {
        Drawing d = path == null ? null : path.drawing(machine, stock, scrub == null ? null : scrub.result());
        boolean moved = sequences > 0;
        return new SimReport(sequences, segments, findings,
                moved ? xMin / profile.x().countsPerMm() : Double.NaN, moved ? xMax / profile.x().countsPerMm() : Double.NaN,
                moved ? zMin / profile.z().countsPerMm() : Double.NaN, moved ? zMax / profile.z().countsPerMm() : Double.NaN,
                seconds, exactStopSeconds, d, terms.envelope(), terms.feedEnvelope(), terms.facts(machine, blank)).withProgramStops(programStops);
    }
}
