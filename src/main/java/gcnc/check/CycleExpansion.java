package gcnc.check;

import gcnc.check.cycle.Axes;
import gcnc.check.cycle.Contour;
import gcnc.check.cycle.CycleCall;
import gcnc.check.cycle.Fault;
import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
import gcnc.check.cycle.Roughing;
import gcnc.check.geom.Coordinates;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * G70, G71 and G72 in the checker's flow (docs/cycles.md). A G71/G72 with P and Q reads its
 * contour ahead: the blocks N(P)..N(Q) right after it, at most {@link #LOOK_AHEAD} of them, are
 * taken out of the flow (the control skips them after the cycle) and followed from the cycle's
 * start without changing the program's state. The cycle's passes ({@link Roughing}) are then
 * written as blocks ({@link MoveWriter}) and checked like any other, each with its origin. A G70
 * follows the stored contour of an earlier G71/G72 again, as ordinary blocks, and returns to
 * its start point. The Fanuc first block (G71 U R / G72 W R) only sets the depth and retract.
 */
final class CycleExpansion {
    /** How many blocks after a G71/G72 its contour's last block N(Q) may be. */
    static final int LOOK_AHEAD = 1000;
    /** The most passes one cycle is expanded into. */
    static final int MAX_PASSES = 10_000;
    /** How many contours are kept for a later G70 (the oldest is forgotten first). */
    static final int STORED = 100;
    /** Geometric tolerance, mm. */
    private static final double EPS_MM = 0.001;

    private final Checker host;
    /** The cycle whose contour is being read, with the blocks read so far; null when none. */
    private Pending pending;
    /** Depth (program units, a radius for G71) and retract (mm) of a Fanuc first block, per cycle. */
    private final Map<GRole, double[]> firstBlocks = new EnumMap<>(GRole.class);
    private final Map<String, Stored> stored = new LinkedHashMap<>(16, 0.75f, false) {
        @Override
        protected boolean removeEldestEntry(Map.Entry<String, Stored> eldest) {
            return size() > STORED;
        }
    };

    private record Pending(CycleCall call, int line, List<RawBlock> blocks, boolean[] broken) {
    }

    /** A contour kept for G70: its blocks and how the cycle that read it cut. */
    private record Stored(List<RawBlock> blocks, Axes axes, int depthSign) {
    }

    /** Which way the contour lies from its start along the depth axis (+1: the start is on the + side). */
    private static int signs(Axes axes, Contour c) {
        return (int) Math.signum(axes.depth(c.start()) - axes.depth(c.shapeStart()));
    }

    CycleExpansion(Checker host) {
        this.host = host;
    }

    boolean reading() {
        return pending != null;
    }

    /** The block's G70/G71/G72 word, or null. */
    Word cycleWord(RawBlock b) {
        for (Word w : b.words()) {
            if (w.letter() == Letter.G && !w.number().isEmpty()) {
                GRole r = role((int) NumberText.integer(w.number()));
                if (r != null && r.contourCycle()) {
                    return w;
                }
            }
        }
        return null;
    }

    private GRole role(int code) {
        GFunction f = code < 0 ? null : host.functions().g(code);
        return f == null ? null : f.role();
    }

    /** A cycle block: its other words first, as a block of their own; then what the cycle does. */
    List<CheckedBlock> start(RawBlock b, Word g, boolean isFirst) {
        GRole kind = role((int) NumberText.integer(g.number()));
        Units units = host.state().units();
        MachineProfile p = host.profile();
        double noPoint = units == Units.INCH ? p.noPointInch() : p.noPointMm();
        CycleCall call = CycleCall.read(b, g, kind, this::role, noPoint, host.out());
        List<CheckedBlock> done = new ArrayList<>();
        List<Word> passOn = call != null ? call.passOn() : passOn(b);
        if (!passOn.isEmpty()) {
            host.one(new RawBlock(b.line(), passOn, passOn.get(passOn.size() - 1).span(), false, b.blockDelete()),
                    isFirst, null).ifPresent(done::add);
        }
        if (call == null) {
            return done;
        }
        if (call.firstOfTwo()) {
            first(call);
        } else if (kind == GRole.FINISHING_CYCLE) {
            done.addAll(finish(call, b.line()));
        } else {
            pending = new Pending(call, b.line(), new ArrayList<>(), new boolean[1]);
        }
        return done;
    }

    /**
     * The words of a cycle block that the cycle could not read which belong to other functions
     * (its F, S, M, N): they still take effect, so that the blocks after it are not judged
     * without them (as {@link Salvage} keeps a rejected block's modal words).
     */
    private List<Word> passOn(RawBlock b) {
        List<Word> kept = new ArrayList<>();
        for (Word w : b.words()) {
            boolean other = switch (w.letter()) {
                case N, F, S, T, M -> true;
                case G -> {
                    GRole r = w.number().isEmpty() ? null : role((int) NumberText.integer(w.number()));
                    yield r != null && !r.contourCycle();
                }
                default -> false;
            };
            if (other) {
                kept.add(w);
            }
        }
        return kept;
    }

    /** The Fanuc first block: remembers the depth and retract for the next cycle of its kind. */
    private void first(CycleCall call) {
        Letter depth = call.kind() == GRole.FACING_CYCLE ? Letter.W : Letter.U;
        double d = Double.NaN;
        if (call.has(depth)) {
            d = call.value(depth);
            if (d <= 0) {
                host.out().error(Code.E156_CYCLE_DEPTH, call.words().get(depth).span(), call.name(),
                        call.words().get(depth));
                return;
            }
        }
        double r = Double.NaN;
        if (call.has(Letter.R)) {
            r = call.value(Letter.R);
            if (r < 0) {
                host.out().error(Code.E158_CYCLE_RETRACT, call.words().get(Letter.R).span(), call.name(),
                        call.words().get(Letter.R));
                return;
            }
            r *= host.state().units() == Units.INCH ? 25.4 : 1;
        }
        double[] old = firstBlocks.getOrDefault(call.kind(), new double[] {Double.NaN, Double.NaN});
        firstBlocks.put(call.kind(), new double[] {Double.isNaN(d) ? old[0] : d, Double.isNaN(r) ? old[1] : r});
    }

    /** The next block while a contour is read: kept aside; the cycle at its last block. */
    List<CheckedBlock> read(RawBlock b) {
        Pending p = pending;
        p.blocks().add(b);
        long n = sequence(b);
        long first = p.call().label(Letter.P);
        long last = p.call().label(Letter.Q);
        if (p.blocks().size() == 1 && n != first) {
            host.out().error(Code.E152_CONTOUR_NOT_NEXT, p.call().words().get(Letter.P).span(), p.call().name(), first);
            return replay();
        }
        if (p.blocks().size() > 1 && n == first) {
            host.out().error(Code.E151_CYCLE_LABEL_TWICE, nWord(b).span(), p.call().name(), p.line(), n);
            p.broken()[0] = true;
        }
        if (n == last) {
            pending = null;
            return roughing(p);
        }
        if (p.blocks().size() >= LOOK_AHEAD) {
            host.out().error(Code.E153_CONTOUR_TOO_LONG, p.call().words().get(Letter.Q).span(), p.call().name(), last,
                    LOOK_AHEAD);
            return replay();
        }
        return List.of();
    }

    /** The program ended while a contour was read: E150, and the blocks read are checked as they stand. */
    void finish() {
        if (pending != null) {
            Word q = pending.call().words().get(Letter.Q);
            host.out().error(Code.E150_CYCLE_LABEL_NOT_FOUND, q.span(), pending.call().name(), q);
            replay();
        }
    }

    /** Gives up reading a contour: its blocks go back into the program's flow. */
    private List<CheckedBlock> replay() {
        List<RawBlock> blocks = pending.blocks();
        pending = null;
        List<CheckedBlock> done = new ArrayList<>();
        for (RawBlock b : blocks) {
            done.addAll(host.flow(b, false));
        }
        return done;
    }

    private static long sequence(RawBlock b) {
        Word n = nWord(b);
        return n == null ? -1 : NumberText.integer(n.number());
    }

    private static Word nWord(RawBlock b) {
        for (Word w : b.words()) {
            if (w.letter() == Letter.N) {
                return w;
            }
        }
        return null;
    }

    /** G71/G72 once its contour is read: the contour followed, the passes planned, written and checked. */
    private List<CheckedBlock> roughing(Pending p) {
        CycleCall call = p.call();
        Axes axes = call.kind() == GRole.TURNING_CYCLE ? Axes.TURNING : Axes.FACING;
        ModalState start = host.state();
        List<Contour.Piece> pieces = follow(call, p.line(), p.blocks(), start);
        if (pieces == null || p.broken()[0]) {
            return List.of();
        }
        if (pieces.size() < 2) {
            host.out().error(Code.E163_CONTOUR_EMPTY, call.g().span(), call.name(), axes.cutName());
            return List.of();
        }
        Contour contour = new Contour(start.position(), pieces.get(0), pieces.subList(1, pieces.size()));
        stored.remove(key(call));
        stored.put(key(call), new Stored(List.copyOf(p.blocks()), axes, signs(axes, contour)));
        Roughing.Settings settings = settings(call, axes, start);
        if (settings == null) {
            return List.of();
        }
        Roughing.Outcome o = new Roughing(axes, settings).plan(contour);
        if (o instanceof Fault f) {
            report(f, call, p.line(), p.blocks());
            return List.of();
        }
        Roughing.Plan plan = (Roughing.Plan) o;
        return write(plan.moves(), plan.passes(), call, p.line(), start);
    }

    /**
     * Follows the contour blocks from the cycle's start, each checked aside (E162 for what a
     * contour cannot hold); their moves, or null when a block has an error.
     */
    private List<Contour.Piece> follow(CycleCall call, int line, List<RawBlock> blocks, ModalState start) {
        List<Contour.Piece> pieces = new ArrayList<>();
        ModalState s = start;
        boolean ok = true;
        for (RawBlock b : blocks) {
            if (b.malformed()) {
                ok = false;
                continue;
            }
            Word foreign = foreign(b);
            if (foreign != null) {
                host.out().error(Code.E162_CONTOUR_WORD, foreign.span(), call.name(), line, foreign);
                ok = false;
                continue;
            }
            Diagnostics found = new Diagnostics();
            Checker.Dry dry = host.dry(b, s, found);
            host.reportAside(found);
            if (dry == null) {
                ok = false;
                continue;
            }
            s = dry.next();
            for (Motion m : dry.block().motions()) {
                pieces.add(new Contour.Piece(m, b.line()));
            }
        }
        return ok ? pieces : null;
    }

    /** The first word of a contour block that a contour cannot hold: an M, a T, a G other than a move. */
    private Word foreign(RawBlock b) {
        for (Word w : b.words()) {
            if (w.letter() == Letter.M || w.letter() == Letter.T) {
                return w;
            }
            if (w.letter() == Letter.G && !w.number().isEmpty()) {
                GRole r = role((int) NumberText.integer(w.number()));
                if (r != null && !r.motion() && r != GRole.NOSE_COMP_CANCEL && r != GRole.NOSE_COMP_LEFT
                        && r != GRole.NOSE_COMP_RIGHT && r != GRole.CSS && r != GRole.RPM) {
                    return w;
                }
            }
        }
        return null;
    }

    /** The cycle's allowances, depth and retract in counts; null after E156, E157 or E158. */
    private Roughing.Settings settings(CycleCall call, Axes axes, ModalState start) {
        Coordinates c = host.coordinates();
        MachineProfile p = host.profile();
        Units u = start.units();
        double[] firstBlock = firstBlocks.getOrDefault(call.kind(), new double[] {Double.NaN, Double.NaN});
        double depth;
        if (call.has(Letter.D)) {
            depth = call.value(Letter.D);
            if (depth <= 0) {
                host.out().error(Code.E156_CYCLE_DEPTH, call.words().get(Letter.D).span(), call.name(),
                        call.words().get(Letter.D));
                return null;
            }
        } else if (!Double.isNaN(firstBlock[0])) {
            depth = firstBlock[0];
        } else {
            host.out().error(Code.E157_CYCLE_DEPTH_MISSING, call.g().span(), call.name(),
                    "D, or a " + call.name() + (axes == Axes.TURNING ? " U" : " W") + " R block before it");
            return null;
        }
        double retractMm = Double.isNaN(firstBlock[1]) ? p.control().cycleRetractMm() : firstBlock[1];
        if (Double.isNaN(retractMm)) {
            host.out().error(Code.E157_CYCLE_DEPTH_MISSING, call.g().span(), call.name(),
                    "a " + call.name() + " R block before it, or cycle.retract_mm in the control");
            return null;
        }
        double dx = call.has(Letter.U) ? call.value(Letter.U) * c.perX(u) : 0;
        double dz = call.has(Letter.W) ? call.value(Letter.W) * c.perZ(u) : 0;
        double depthCounts = axes == Axes.TURNING ? depth * c.perRadius(u) : depth * c.perZ(u);
        double perMmDepth = axes == Axes.TURNING ? p.x().countsPerMm() : p.z().countsPerMm();
        double perMmCut = axes == Axes.TURNING ? p.z().countsPerMm() : p.x().countsPerMm();
        return new Roughing.Settings(dx, dz, depthCounts, retractMm * perMmDepth, retractMm * perMmCut,
                EPS_MM * Math.min(p.x().countsPerMm(), p.z().countsPerMm()), MAX_PASSES);
    }

    /** Reports why a cycle cannot be expanded, where its fault says. */
    private void report(Fault f, CycleCall call, int line, List<RawBlock> blocks) {
        List<Object> args = new ArrayList<>();
        args.add(call.name());
        Span at = call.g().span();
        if (f.contourLine() > 0) {
            args.add(line);
            for (RawBlock b : blocks) {
                if (b.line() == f.contourLine()) {
                    at = b.words().isEmpty() ? b.last() : b.words().get(0).span();
                    break;
                }
            }
        } else if (f.word() != null) {
            Word w = call.words().get(f.word());
            if (w != null) {
                at = w.span();
            }
            args.add(w != null ? w : f.word());
        }
        args.addAll(f.args());
        host.out().error(f.code(), at, args.toArray());
    }

    /** The moves as blocks at the cycle's line, each checked; stops at the first that fails. */
    private List<CheckedBlock> write(List<Move> moves, int passes, CycleCall call, int line, ModalState start) {
        MoveWriter writer = new MoveWriter(frame(start), line, call.g().span());
        List<CheckedBlock> done = new ArrayList<>();
        Point at = start.position();
        for (Move m : moves) {
            CycleOrigin origin = new CycleOrigin(call.name(), m.pass(), passes, line, call.label(Letter.P),
                    call.label(Letter.Q), false);
            Optional<CheckedBlock> b = host.one(writer.block(m, at), false, origin);
            if (b.isEmpty()) {
                break;
            }
            done.add(b.get());
            at = host.state().position();
        }
        return done;
    }

    private MoveWriter.Frame frame(ModalState s) {
        Coordinates c = host.coordinates();
        Units u = s.units();
        List<String> codes = new ArrayList<>(4);
        for (GRole r : new GRole[] {GRole.RAPID, GRole.LINEAR, GRole.ARC_CW, GRole.ARC_CCW}) {
            codes.add(host.profile().control().gFor(r).map(f -> f.name().substring(1)).orElseThrow());
        }
        return new MoveWriter.Frame(c.origin(s.next()), c.perX(u), c.perRadius(u), c.perZ(u), s.incremental(), codes);
    }

    private static String key(CycleCall call) {
        return call.label(Letter.P) + "/" + call.label(Letter.Q);
    }

    /**
     * G70: the stored contour's blocks followed again as ordinary blocks (their F and S apply),
     * then a rapid return to the start point, first along the axis that leaves the part.
     */
    private List<CheckedBlock> finish(CycleCall call, int line) {
        Stored s = stored.get(key(call));
        if (s == null) {
            host.out().error(Code.E166_FINISH_WITHOUT_CONTOUR, call.g().span(), call.name(), call.label(Letter.P),
                    call.label(Letter.Q));
            return List.of();
        }
        ModalState start = host.state();
        Point a = start.position();
        CycleOrigin origin = new CycleOrigin(call.name(), 1, 1, line, call.label(Letter.P), call.label(Letter.Q), true);
        List<CheckedBlock> done = new ArrayList<>();
        for (RawBlock b : s.blocks()) {
            Optional<CheckedBlock> r = host.one(b, false, origin);
            if (r.isEmpty()) {
                return done;
            }
            done.add(r.get());
        }
        Point at = host.state().position();
        Axes ax = s.axes();
        boolean endsOutside = (ax.depth(at) - ax.depth(a)) * s.depthSign() >= 0;
        Point corner = endsOutside ? ax.point(ax.depth(at), ax.cut(a)) : ax.point(ax.depth(a), ax.cut(at));
        MoveWriter writer = new MoveWriter(frame(host.state()), line, call.g().span());
        CycleOrigin back = new CycleOrigin(call.name(), 1, 1, line, call.label(Letter.P), call.label(Letter.Q), false);
        for (Point to : new Point[] {corner, a}) {
            if (to.distanceTo(at) <= 1e-9) {
                continue;
            }
            Optional<CheckedBlock> r = host.one(writer.block(Move.line(true, to, 1), at), false, back);
            if (r.isEmpty()) {
                break;
            }
            done.add(r.get());
            at = host.state().position();
        }
        return done;
    }
}
