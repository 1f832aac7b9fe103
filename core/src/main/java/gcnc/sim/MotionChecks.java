package gcnc.sim;

import gcnc.diag.Code;
import gcnc.dmc.Source;
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
    /** Where the findings go, each with the source of the DMC line, segment or block it is about. */
    interface Reporter {
        void report(Code code, Source at, Object... args);
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
    private final PathRecorder path;
    private final Conformance conformance;
    private int tool;
    /** {rMin, rMax, zMin, zMax} of the chuck and tailstock (counts, radius), empty = none. */
    private final double[] chuckBox;
    private final double[] tailBox;
    /** The current tool's outline as the checks see it. */
    private ToolInUse outline;
    /** The segments near an obstacle or the stock, followed piece by piece. */
    private final CloseUp closeUp;
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
            out.report(beyond.get().code(), Source.line(1), StockSize.shown(beyond.get().value()),
                    mm(beyond.get().limit()), profile.name());
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
        chuckBox = ToolInUse.box(machine.chuck());
        tailBox = ToolInUse.box(machine.tailstock());
        outline = new ToolInUse(machine.defaultTool(), kx, kz);
        closeUp = new CloseUp(machine, stock, tol, kx, kz, this::mark);
        closeUp.tool(tool, outline);
    }

    /** Whether the run has a blank to cut (from --stock, the program's stock header or the profile). */
    boolean hasStock() {
        return stock != null;
    }

    /** Can the tool, its tip anywhere in the segment box {xMin, xMax, zMin, zMax}, reach the obstacle box? */
    private boolean near(double[] obstacle, double[] seg) {
        if (obstacle == null) {
            return false;
        }
        double rLo = radius(seg[0], seg[1]);
        double[] reach = outline.reach;
        double rHi = outline.side > 0 ? seg[1] - centre() : centre() - seg[0];
        return rLo + reach[0] < obstacle[1] + tol && rHi + reach[1] > obstacle[0] - tol
                && seg[2] + reach[2] < obstacle[3] + tol && seg[3] + reach[3] > obstacle[2] - tol;
    }

    int tool() {
        return tool;
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

    /** The number of the DMC line being replayed (a finding without a program frame is placed by it). */
    private int dmcLine;

    void dmcLine(int n) {
        dmcLine = n;
    }

    void selectTool(int n) {
        tool = n;
        outline = new ToolInUse(machine.tool(n), kx, kz);
        closeUp.tool(n, outline);
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

    /**
     * Replays one sequence, started at {@code start} (its findings go to each segment's own line, or
     * there for a segment with none: {@link #place}). With {@code judgeCut} the stock is asked exactly
     * whether the move takes more than {@link Stock#DEPTH} of material (a feed with the spindle stopped
     * or the chuck open: a bar puller's pull in the air is no cut, E306/E307 are for a real one);
     * returns that answer, false without {@code judgeCut}.
     */
    boolean sequence(List<Segment> segs, double speed, boolean rapid, Source start, double acc, double dec,
                     boolean judgeCut) {
        int line = start.line();
        if (scrub != null) {
            scrub.before(line, sequences);
        }
        closeUp.sequence(judgeCut);
        sequences++;
        segments += segs.size();
        double length = 0;
        boolean travelX = false;
        boolean travelZ = false;
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
            Source place = place(s, start);
            int at = place.line();
            long block = s.source() == null ? -1 : s.source().block();
            if (k > 0 && (at != polyLine || block != lastBlock)) {
                // one finding per check per motion's block: a sequence of several blocks reports each one's
                closeUp.block();
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
            travelX = travelX || travel(place, "X", box[0], box[1], profile.x().min(), profile.x().max(),
                    profile.x().countsPerMm());
            travelZ = travelZ || travel(place, "Z", box[2], box[3], profile.z().min(), profile.z().max(),
                    profile.z().countsPerMm());
            double rMin = radius(box[0], box[1]);
            boolean nearChuck = near(chuckBox, box);
            boolean nearTail = near(tailBox, box);
            // a bar puller grips the bar: it neither cuts nor crashes into it
            double[] reach = outline.reach;
            boolean nearStock = stock != null && outline.insertMm != null
                    && outline.shape.kind() != MachineModel.ToolKind.PULLER && stock.mayTouch((box[2] + reach[2]) / kz,
                    (box[3] + reach[3]) / kz, (rMin + reach[0]) / kx);
            if (poly != null || nearChuck || nearTail || nearStock) {
                closeUp.segment(s, rapid, place, poly, nearChuck, nearTail, nearStock);
            }
            if (blended) {
                // the segment at its own speed, from the corner before it to the corner after it
                double v = Double.isNaN(s.speed()) ? speed : s.speed();
                double exit = k == segs.size() - 1 ? 0 : Double.isNaN(s.end()) ? v : s.end();
                seconds += Profiles.time(s.length(), entry, v, exit, acc, dec);
                exactStopSeconds += Profiles.time(s.length(), v, acc, dec);
                entry = exit;
            }
        }
        if (!blended) {
            double t = Profiles.time(length, speed, acc, dec);
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
            scrub.after(sequences - 1, tool, outline.placedInsert(tipZ, tipR),
                    outline.placedHolder(tipZ, tipR));
        }
        return closeUp.removed();
    }

    /** The studio's scrub ({@link SimOptions#withScrub}), null when none was asked for. */
    private final StockScrub scrub;

    /** See {@link Conformance#check}. */
    double[] conformance(Motion m, List<Segment> segs, Source block) {
        return conformance.check(m, segs, block);
    }

    /**
     * Where the findings about segment {@code s} of a sequence started at {@code start} go: its own
     * source, line, file and calls (a sequence may run on from the main program into a subprogram of
     * its file), or the start's for a segment with none (made by hand, or from no block).
     */
    static Source place(Segment s, Source start) {
        Source own = s.source();
        return own != null && own.line() > 0 ? own : start;
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
        return outline.side > 0 ? xLo - centre() : centre() - xHi;
    }

    /**
     * The finding, at machine position p = {x, z} (counts), with its place kept for the SVG: after
     * the lead arguments, where it is as the program writes it (X as a diameter, Z from work zero,
     * the DMC's line when the program frame is not known), the block's N word ("N110; " or ""), and the
     * machine position in mm. Without the program frame (a DMC replayed by itself: the work offsets
     * are not in it) the place is the DMC's line, "DMC line 57", whatever line the finding is
     * reported at (a source map's G-code line). The tool's outline is drawn with its tip at {@code tip}.
     */
    private void mark(Code code, Source at, double[] p, double[] tip, Object... lead) {
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
        out.report(code, at, args);
        if (path != null) {
            int line = at.line();
            String block = frame != null && !frame.sequence().isEmpty() ? frame.sequence() : "line " + line;
            path.mark(code.id(), block, line, p[0], p[1], outline.shape, outline.side, tip);
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
    private boolean travel(Source at, String axis, double lo, double hi, double min, double max, double perMm) {
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
        out.report(Code.E302_SIM_TRAVEL, at, axis, where, block, mm(bad / perMm), mm(min / perMm), mm(max / perMm));
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
