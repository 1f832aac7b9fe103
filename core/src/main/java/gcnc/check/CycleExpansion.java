package gcnc.check;

import gcnc.check.cycle.Axes;
import gcnc.check.cycle.Contour;
import gcnc.check.cycle.CycleCall;
import gcnc.check.cycle.FirstBlock;
import gcnc.check.cycle.Move;
import gcnc.diag.Code;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

/**
 * The cycles in the checker's flow (docs/cycles.md). A G71/G72/G73 with P and Q reads its
 * contour ahead: the blocks N(P)..N(Q) right after it, at most {@link #LOOK_AHEAD} of them, are
 * taken out of the flow (the control skips them after the cycle) and followed from the cycle's
 * start without changing the program's state ({@link ContourReader}). {@link StockRemoval} then
 * plans the passes, writes them as blocks and checks each like any other, with its origin. A G70
 * follows the stored contour of an earlier G71/G72/G73 again ({@link StoredContours},
 * {@link Finishing}); G73 is {@link PatternRepeat}, G90/G94 {@link SingleCycle}. The Fanuc first block (G71 U R, G72 W R,
 * G73 U W R) only sets what the next cycles of its kind use ({@link FirstBlock}).
 */
final class CycleExpansion {
    /** How many blocks after a G71/G72/G73 its contour's last block N(Q) may be. */
    static final int LOOK_AHEAD = 1000;

    private final CycleHost host;
    private final ContourReader contours;
    private final SingleCycle single;
    private final Grooving grooving;
    private final HoleDrilling drilling;
    private final Threading threads;
    /** The cycle whose contour is being read, with the blocks read so far; null when none. */
    private Pending pending;
    /** What the Fanuc first blocks left in force, per cycle. */
    private final Map<GRole, FirstBlock> firstBlocks = new EnumMap<>(GRole.class);
    /** The contours G71-G73 read, for a later G70. */
    private final StoredContours stored = new StoredContours();

    /**
     * A G71/G72/G73 whose contour is being read: the blocks so far, the blocks between the cycle and
     * N(P) (which the control never runs, E644), whether one of them broke it, and whether the cycle
     * block itself was rejected (its P and Q still name the contour the control would skip and a
     * G70 would finish: it is read and kept, not expanded).
     */
    private static final class Pending {
        final CycleCall call;
        final int line;
        final boolean rejected;
        final List<RawBlock> blocks = new ArrayList<>();
        final List<RawBlock> before = new ArrayList<>();
        boolean broken;

        Pending(CycleCall call, int line, boolean rejected) {
            this.call = call;
            this.line = line;
            this.rejected = rejected;
        }
    }

    /**
     * Which way the contour lies from its start along the depth axis (+1: the start is on the +
     * side): where its first move goes, or (a type II first move along the cutting axis only) where
     * the contour reaches farthest from the start's level.
     */
    private static int signs(Axes axes, Contour c) {
        int first = (int) Math.signum(axes.depth(c.start()) - axes.depth(c.shapeStart()));
        if (first != 0) {
            return first;
        }
        double a = axes.depth(c.start());
        double below = 0;
        double above = 0;
        for (Contour.Piece p : c.shape()) {
            below = Math.max(below, a - axes.depth(p.to()));
            above = Math.max(above, axes.depth(p.to()) - a);
        }
        return below >= above ? 1 : -1;
    }

    CycleExpansion(CycleHost host) {
        this.host = host;
        this.contours = new ContourReader(host, this::role);
        this.single = new SingleCycle(host);
        this.grooving = new Grooving(host);
        this.drilling = new HoleDrilling(host);
        this.threads = new Threading(host);
        this.any = host.profile().control().allG().stream().anyMatch(f -> expanded(f.role()));
    }

    /** Whether the control has any cycle gcnc expands (the thesis's has none: no block is looked at). */
    private final boolean any;

    boolean reading() {
        return pending != null;
    }

    /** The cycle whose contour is being read ("G71"), while {@link #reading()}. */
    String readingName() {
        return pending.call.name();
    }

    /** The block's G70/G71/G72 word, or null. */
    Word cycleWord(RawBlock b) {
        if (!any) {
            return null;
        }
        for (Word w : b.words()) {
            if (w.letter() == Letter.G && !w.number().isEmpty()) {
                GRole r = role((int) w.code());
                if (r != null && expanded(r)) {
                    return w;
                }
            }
        }
        return null;
    }

    /** A cycle the checker expands into moves. */
    private static boolean expanded(GRole r) {
        return r.contourCycle() || r.singleCycle() || r.peckCycle() || r.drillCycle() || r.thread();
    }

    private GRole role(int code) {
        GFunction f = code < 0 ? null : host.functions().g(code);
        return f == null ? null : f.role();
    }

    /** Whether the block makes the G90/G94 in force again (X or Z, no G of its group). */
    boolean repeats(RawBlock b) {
        return any && (single.repeats(b) || drilling.repeats(b) || threads.repeats(b));
    }

    /** The modal cycle the block would run again ("G92"): the one {@link #repeats} found. */
    String repeating(RawBlock b) {
        return drilling.repeats(b) ? drilling.name() : threads.repeats(b) ? threads.name() : single.name();
    }

    List<CheckedBlock> repeat(RawBlock b, boolean isFirst) {
        if (drilling.repeats(b)) {
            return drilling.run(b, null, isFirst);
        }
        return threads.repeats(b) ? threads.run(b, null, isFirst) : single.run(b, null, isFirst);
    }

    /** An ordinary block: a G of the G90/G94's (or G32/G92's) group ends it. */
    void note(RawBlock b) {
        if (any) {
            single.note(b);
            drilling.note(b);
            threads.note(b);
        }
    }

    /** A cycle block: its other words first, as a block of their own; then what the cycle does. */
    List<CheckedBlock> start(RawBlock b, Word g, boolean isFirst) {
        GRole kind = role((int) g.code());
        if (kind.thread()) {
            single.note(b);
            drilling.note(b);
            return threads.run(b, g, isFirst);
        }
        threads.note(b);
        threads.moved();
        if (kind.singleCycle()) {
            drilling.note(b);
            return single.run(b, g, isFirst);
        }
        single.note(b);
        drilling.note(b);
        if (kind.peckCycle()) {
            return grooving.run(b, g, kind, isFirst);
        }
        if (kind.drillCycle()) {
            return drilling.run(b, g, isFirst);
        }
        Units units = host.state().units();
        MachineProfile p = host.profile();
        double noPoint = units == Units.INCH ? p.noPointInch() : p.noPointMm();
        CycleCall call = CycleCall.read(b, g, kind, this::role, noPoint, host.out());
        List<CheckedBlock> done = new ArrayList<>();
        List<Word> passOn = call != null ? call.passOn() : passOn(b);
        CycleBlocks.passOn(host, b, passOn, isFirst).ifPresent(done::add);
        if (call == null) {
            // rejected: as after the operator fixed this block, its contour is still skipped and
            // kept for the G70, so that neither is judged as an echo of this error
            CycleCall labels = kind == GRole.FINISHING_CYCLE ? null : CycleCall.labels(b, g, kind);
            if (labels != null) {
                pending = new Pending(labels, b.line(), true);
            }
            return done;
        }
        if (call.firstOfTwo()) {
            first(call);
        } else if (kind == GRole.FINISHING_CYCLE) {
            StoredContours.Found found = stored.find(call, host.out());
            if (found != null && found.contour().usable()) {
                StoredContours.Stored s = found.contour();
                done.addAll(new Finishing(host).expand(call, b.line(), found.blocks(), s.axes(), s.depthSign()));
            }
        } else {
            pending = new Pending(call, b.line(), false);
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
                    GRole r = w.number().isEmpty() ? null : role((int) w.code());
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

    /**
     * The Fanuc first block: its depth and retract (G71, G72) or relief and passes (G73) stay in
     * force for the next cycles of its kind; E156, E158 or the passes' errors otherwise.
     */
    private void first(CycleCall call) {
        double nan = Double.NaN;
        FirstBlock said;
        if (call.kind() == GRole.PATTERN_CYCLE) {
            double passes = call.has(Letter.R) ? PatternRepeat.passes(host.out(), call, Letter.R) : nan;
            if (Double.isNaN(passes) && call.has(Letter.R)) {
                return;
            }
            said = new FirstBlock(nan, nan, call.has(Letter.U) ? call.value(Letter.U) : nan,
                    call.has(Letter.W) ? call.value(Letter.W) : nan, passes);
        } else {
            Letter depth = call.kind() == GRole.FACING_CYCLE ? Letter.W : Letter.U;
            double d = call.has(depth) ? call.value(depth) : nan;
            if (d <= 0) {
                host.out().error(Code.E156_CYCLE_DEPTH, call.words().get(depth).span(), call.name(),
                        call.words().get(depth));
                return;
            }
            double r = call.has(Letter.R) ? call.value(Letter.R) : nan;
            if (r < 0) {
                host.out().error(Code.E158_CYCLE_RETRACT, call.words().get(Letter.R).span(), call.name(),
                        call.words().get(Letter.R));
                return;
            }
            said = new FirstBlock(d, r * (host.state().units() == Units.INCH ? 25.4 : 1), nan, nan, nan);
        }
        firstBlocks.merge(call.kind(), said, FirstBlock::then);
    }

    /** The next block while a contour is read: kept aside; the cycle at its last block. */
    List<CheckedBlock> read(RawBlock b) {
        Pending p = pending;
        long n = StoredContours.sequence(b);
        long first = p.call.label(Letter.P);
        long last = p.call.label(Letter.Q);
        if (p.blocks.isEmpty() && n != first) {
            // the control searches ahead for N(P): a block before it is passed over (E644 once N(P) is found)
            p.before.add(b);
            if (p.before.size() >= LOOK_AHEAD) {
                host.out().error(Code.E153_CONTOUR_TOO_LONG, p.call.words().get(Letter.P).span(), p.call.name(), first,
                        LOOK_AHEAD);
                return replay();
            }
            return List.of();
        }
        if (p.blocks.isEmpty()) {
            for (RawBlock skipped : p.before) {
                Word at = skipped.words().isEmpty() ? null : skipped.words().get(0);
                host.out().report(gcnc.diag.Diagnostic.warning(Code.E644_BLOCK_BEFORE_CONTOUR,
                        at != null ? at.span() : skipped.last(), p.call.name(), p.line, first));
            }
        }
        p.blocks.add(b);
        if (p.blocks.size() > 1 && n == first) {
            host.out().error(Code.E151_CYCLE_LABEL_TWICE, StoredContours.nWord(b).span(), p.call.name(), p.line, n);
            p.broken = true;
        }
        if (n == last) {
            pending = null;
            return roughing(p);
        }
        if (p.blocks.size() >= LOOK_AHEAD) {
            host.out().error(Code.E153_CONTOUR_TOO_LONG, p.call.words().get(Letter.Q).span(), p.call.name(), last,
                    LOOK_AHEAD);
            return replay();
        }
        return List.of();
    }

    /** The program ended while a contour was read: E150, and the blocks read are checked as they stand. */
    void finish() {
        if (pending != null) {
            Word q = pending.call.words().get(Letter.Q);
            host.out().error(Code.E150_CYCLE_LABEL_NOT_FOUND, q.span(), pending.call.name(), q);
            replay();
        }
    }

    /** Gives up reading a contour: its blocks go back into the program's flow. */
    private List<CheckedBlock> replay() {
        List<RawBlock> blocks = new ArrayList<>(pending.before);
        blocks.addAll(pending.blocks);
        pending = null;
        List<CheckedBlock> done = new ArrayList<>();
        for (RawBlock b : blocks) {
            done.addAll(host.flow(b, false));
        }
        return done;
    }

    /** G71/G72/G73 once its contour is read: the contour followed, the passes planned, written and checked. */
    private List<CheckedBlock> roughing(Pending p) {
        CycleCall call = p.call;
        ModalState start = host.state();
        stored.forget(call);
        // the contour as the control follows it: its chamfers and corners made (G70 runs these blocks too)
        List<RawBlock> blocks = p.rejected ? p.blocks : host.cornersInContour(p.blocks, start);
        StoredContours.Stored rejected = new StoredContours.Stored(List.copyOf(blocks), List.copyOf(p.before), null, 0, call.name(), p.line);
        stored.keep(call, rejected); // until the contour is known good: a G70 over it does nothing
        if (p.rejected) {
            return List.of();
        }
        List<Contour.Piece> pieces = contours.follow(call, p.line, blocks, start);
        if (pieces == null || p.broken) {
            return List.of();
        }
        Axes axes = call.kind() == GRole.FACING_CYCLE ? Axes.FACING : Axes.TURNING;
        if (pieces.size() < 2) {
            host.out().error(Code.E163_CONTOUR_EMPTY, call.g().span(), call.name(),
                    call.kind() == GRole.PATTERN_CYCLE ? "X or Z" : axes.cutName());
            return List.of();
        }
        Contour.Piece lead = positioning(call, axes, pieces) ? pieces.get(0) : null;
        Contour contour = lead == null ? new Contour(start.position(), pieces.get(0), pieces.subList(1, pieces.size()))
                : new Contour(lead.to(), pieces.get(1), pieces.subList(2, pieces.size()));
        stored.keep(call, new StoredContours.Stored(rejected.blocks(), rejected.passedOver(), axes, signs(axes, contour),
                call.name(), p.line));
        FirstBlock firstBlock = firstBlocks.getOrDefault(call.kind(), FirstBlock.NONE);
        if (call.kind() == GRole.PATTERN_CYCLE) {
            // G71-G73 only plan their passes; they are written and checked here, one by one
            return PatternRepeat.expand(host.out(), call, host.coordinates(), contour, start, firstBlock)
                    .map(g -> CycleBlocks.write(host, call, p.line, g.moves(), g.passes(), start)).orElse(List.of());
        }
        return new StockRemoval(host.coordinates(), host.profile(), host.out(), call, p.line)
                .expand(contour, blocks, start, firstBlock, lead)
                .map(g -> CycleBlocks.write(host, call, p.line, g.moves(), g.passes(), start)).orElse(List.of());
    }

    /**
     * Whether the contour's first move is a positioning move at the start's level (Haas,
     * {@code cycle.type1_first_move = positions}): a G71 (G72) whose first move goes along Z (X)
     * alone, and a second move to rough type I from. Fanuc's alarm PS0065 (E155) otherwise.
     */
    private boolean positioning(CycleCall call, Axes axes, List<Contour.Piece> pieces) {
        if (!host.profile().control().cutFirstMovePositions() || call.kind() == GRole.PATTERN_CYCLE
                || call.typeTwo() || pieces.size() < 3) {
            return false;
        }
        Contour.Piece first = pieces.get(0);
        return MotionKind.of(first.motion()).linear()
                && Math.abs(axes.depth(first.to()) - axes.depth(first.from())) <= 1e-9
                && Math.abs(axes.cut(first.to()) - axes.cut(first.from())) > 1e-9;
    }

    /** A roughing cycle's moves (G71-G73), planned from what it read, to be written and checked by {@link CycleBlocks#write}. */
    record Passes(List<Move> moves, int passes) {
    }

}
