package gcnc.check;

import gcnc.check.cycle.Move;
import gcnc.diag.Code;
import gcnc.diag.Phrase;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * Threads (docs/threading.md): G32 (Fanuc B G33) one spindle-synchronised pass, modal in group 1;
 * G92 (Fanuc B G78) the single-pass thread cycle (rapid in, thread, rapid out, rapid back), modal
 * in group 1 so that later blocks with X only cut the next passes; G76 the multiple-pass cycle in
 * the Fanuc two-block form ({@code G76 P(mmrraa) Q(min depth) R(allowance)} then
 * {@code G76 X Z R(taper) P(height) Q(first depth) F}) and the Haas one-block form
 * ({@code G76 X Z K(height) D(first depth) F [I A P]}), {@link MultipleThread}. Every thread
 * pass is a G01 block checked like a cut and built as a spindle-synchronised motion
 * ({@link CycleHost#thread}); the rapids are ordinary G00 blocks. Under Haas M23 each G92/G76 pass ends with the profile's chamfered pull-out
 * ({@link PullOut}, made by {@code MotionBuilder}); G32 never does.
 */
final class Threading extends ModalExpansion {
    private final ThreadValues values;
    private final ThreadPassWriter writer;
    /** G76, with what a Fanuc first block left in force. */
    private final MultipleThread multiple;
    /** G92 in force: its end point (counts), taper (radius counts) and lead (as written). */
    private Point end;
    private double taper;
    /** The G92 in force's start angle, degrees (Q; a later block without Q keeps it, as the end and taper). */
    private double startAngle;
    /**
     * Haas M23 in force: each pass of a G76 or G92 ends with the profile's chamfered pull-out
     * ({@link #pullsOut}). On at power-up on a control that has M23 (Haas), off after M24.
     */
    private boolean chamfer;

    Threading(CycleHost host) {
        super(host, new ModalCycle()); // the modal thread in force (G32 or G92), if any
        this.values = new ThreadValues(host);
        this.writer = new ThreadPassWriter(host);
        this.multiple = new MultipleThread(host, values, writer);
        this.chamfer = host.profile().control().allM().stream()
                .anyMatch(f -> f.role() == gcnc.machine.MRole.THREAD_CHAMFER_ON);
    }

    /** Follows M23/M24 in a block's words. */
    private void chamferWords(RawBlock b) {
        for (Word w : b.words()) {
            if (w.letter() == Letter.M && !w.number().isEmpty()) {
                gcnc.machine.MFunction f = host.functions().m(w.code());
                if (f != null && f.role() == gcnc.machine.MRole.THREAD_CHAMFER_ON) {
                    chamfer = true;
                } else if (f != null && f.role() == gcnc.machine.MRole.THREAD_CHAMFER_OFF) {
                    chamfer = false;
                }
            }
        }
    }

    /**
     * Where the last G32 pass ended, while nothing has moved since; null otherwise. A G32 that
     * starts there continues the thread without a break: {@link ThreadChain} joins them.
     */
    private Point continued;

    /** Another cycle moves the tool: a G32 after it starts a new pass. */
    void moved() {
        continued = null;
    }

    /** An ordinary block (or another cycle): a G of the thread's group ends it; an axis word breaks a thread's continuity. */
    @Override
    void note(RawBlock b) {
        chamferWords(b);
        for (Word w : b.words()) {
            Letter l = w.letter();
            if (l == Letter.X || l == Letter.U || l == Letter.Z || l == Letter.W || l == Letter.G) {
                continued = null;
                break;
            }
        }
        super.note(b);
    }

    /** A G32/G92/G76 block ({@code g} its word), or one that makes the G32/G92 in force again (g null). */
    @Override
    List<CheckedBlock> run(RawBlock b, Word g, boolean isFirst) {
        GRole role = role(g);
        String label = label(g);
        if (role != GRole.THREAD) {
            continued = null;
        }
        Map<Letter, Word> words = new EnumMap<>(Letter.class);
        List<Word> passOn = new ArrayList<>();
        Word foreign = null;
        Word twice = null;
        for (Word w : b.words()) {
            if (w == g) {
                continue;
            }
            switch (w.letter()) {
                case N, S, T, M -> passOn.add(w);
                case G -> foreign = otherG(w, passOn, foreign);
                default -> {
                    if (!takes(role, w.letter())) {
                        foreign = foreign == null ? w : foreign;
                    } else if (words.putIfAbsent(w.letter(), w) != null) {
                        twice = twice == null ? w : twice;
                    }
                }
            }
        }
        List<CheckedBlock> done = new ArrayList<>();
        CycleBlocks.passOn(host, b, passOn, isFirst).ifPresent(done::add);
        if (foreign != null) {
            host.out().error(Code.E161_CYCLE_WORD, foreign.span(), label, foreign);
            return done;
        }
        if (twice != null) {
            host.out().error(Code.E007_DUPLICATE_PARAMETER, twice.span(), twice.letter());
            return done;
        }
        chamferWords(b);
        Span at = g != null ? g.span() : b.words().get(0).span();
        if (host.profile().encoder().isEmpty()) {
            host.out().error(Code.E190_NO_SPINDLE_ENCODER, at, host.profile().name(), label);
            refused(role, g, label);
            return done;
        }
        if (role == GRole.THREAD) {
            if (g != null) {
                start(role, g, label);
            }
            pass(done, b, g, words, label);
        } else if (role == GRole.THREAD_SINGLE_CYCLE) {
            single(done, b, g, words, label, at);
        } else {
            multiple.run(done, b, g, words, label, pullsOut());
        }
        return done;
    }

    /**
     * A refused G32/G92 stays in force (without an end point for G92), so that the blocks that
     * repeat it are refused too, each at its line, instead of moving as whatever G was before.
     */
    private void refused(GRole role, Word g, String label) {
        if (g != null && role != GRole.THREAD_CYCLE) {
            start(role, g, label);
            end = null;
        }
    }

    private void start(GRole role, Word g, String label) {
        modal.start(role, function(g), label);
    }

    /** The letters a thread function reads (besides N S T M G). */
    private static boolean takes(GRole role, Letter l) {
        return switch (role) {
            case THREAD -> l == Letter.X || l == Letter.U || l == Letter.Z || l == Letter.W || l == Letter.F;
            case THREAD_SINGLE_CYCLE -> l == Letter.X || l == Letter.U || l == Letter.Z || l == Letter.W
                    || l == Letter.F || l == Letter.R || l == Letter.I || l == Letter.Q;
            default -> switch (l) {
                case X, U, Z, W, F, R, P, Q, K, D, I, A -> true;
                default -> false;
            };
        };
    }

    /** G32: the block's own axis words and F, as a G01 thread pass. */
    private void pass(List<CheckedBlock> done, RawBlock b, Word g, Map<Letter, Word> words, String label) {
        List<Word> axes = ThreadValues.axes(words);
        if (axes.isEmpty()) {
            host.out().error(Code.E195_THREAD_WORD_MISSING, g.span(), label, Phrase.THREAD_END_EITHER.arg());
            return;
        }
        Span at = g != null ? g.span() : axes.get(0).span();
        List<Word> ws = new ArrayList<>();
        ws.add(new Word(Letter.G, linearCode(), at));
        ws.addAll(axes);
        if (words.containsKey(Letter.F)) {
            ws.add(words.get(Letter.F));
        }
        // a G32 where the last one ended, nothing moved between: the same thread goes on (ThreadChain)
        boolean continues = continued != null && continued.distanceTo(host.state().position()) <= 1e-6;
        Optional<CheckedBlock> r = host.thread(new RawBlock(b.line(), ws, ws.get(ws.size() - 1).span(), false,
                b.blockDelete()), false, null, label, null); // G32 has no pull-out: M23 does not change it
        r.ifPresent(done::add);
        r.ifPresent(c -> host.threadChain().pass(c, continues));
        continued = r.isPresent() ? host.state().position() : null;
    }

    private String linearCode() {
        return host.profile().control().gFor(GRole.LINEAR).map(f -> f.name().substring(1)).orElseThrow();
    }

    /** G92/G78: the end point and taper (the ones not given as before), one pass of four moves. */
    private void single(List<CheckedBlock> done, RawBlock b, Word g, Map<Letter, Word> words, String label, Span at) {
        boolean x = words.containsKey(Letter.X) || words.containsKey(Letter.U);
        boolean z = words.containsKey(Letter.Z) || words.containsKey(Letter.W);
        if (g != null && (!x || !z) || g == null && end == null && (!x || !z)) {
            host.out().error(Code.E195_THREAD_WORD_MISSING, at, label, Phrase.THREAD_END_BOTH.arg());
            if (g != null) {
                modal.end();
            }
            return;
        }
        double lead = values.lead(words, label, at);
        if (Double.isNaN(lead)) {
            return;
        }
        Word taperWord = words.containsKey(Letter.R) ? words.get(Letter.R) : words.get(Letter.I);
        double t = g != null ? 0 : taper;
        if (taperWord != null) {
            double v = values.length(taperWord);
            if (Double.isNaN(v)) {
                return;
            }
            t = v * host.coordinates().perRadius(host.state().units());
        }
        double q = g != null ? 0 : startAngle;
        if (words.containsKey(Letter.Q)) {
            q = values.startAngle(words.get(Letter.Q), label);
            if (Double.isNaN(q)) {
                return;
            }
        }
        Point reached = values.target(b, ThreadValues.axes(words));
        if (reached == null) {
            return;
        }
        if (g != null) {
            start(GRole.THREAD_SINGLE_CYCLE, g, label);
        }
        Point to = new Point(x ? reached.x() : end.x(), z ? reached.z() : end.z());
        ModalState s = host.state();
        Point a = s.position();
        if (Math.abs(to.z() - a.z()) < 1) {
            host.out().error(Code.E196_THREAD_NOT_ALONG_Z, at, label);
            return;
        }
        // the side of the thread the start point is on: where an M23 chamfer pulls out to
        int side = (int) Math.signum(a.x() - to.x());
        side = side != 0 ? side : (int) Math.signum(a.x() - (to.x() + t));
        PullOut pullOut = null;
        if (pullsOut()) {
            if (side == 0) {
                host.out().error(Code.E160_CYCLE_START_INSIDE, at, label, b.line());
                return;
            }
            pullOut = new PullOut(host.profile().threadChamfer(), side);
        }
        end = to;
        taper = t;
        startAngle = q;
        List<Move> moves = List.of(Move.line(true, new Point(end.x() + taper, a.z()), 1), Move.line(false, end, 1),
                Move.line(true, new Point(a.x(), end.z()), 1), Move.line(true, a, 1));
        writer.write(done, b.line(), at, s, moves, lead, label, i -> CycleOrigin.single(modal.name(), b.line()), pullOut, q);
    }

    /** Whether a G76 or G92 pass now ends with a chamfer: M23 in force and a chamfer of some length in the profile. */
    private boolean pullsOut() {
        return chamfer && host.profile().threadChamfer().cuts();
    }

}
