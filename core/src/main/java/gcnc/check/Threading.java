package gcnc.check;

import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
import gcnc.check.cycle.ThreadPasses;
import gcnc.check.geom.Coordinates;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Phrase;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Threads (docs/threading.md): G32 (Fanuc B G33) one spindle-synchronised pass, modal in group 1;
 * G92 (Fanuc B G78) the single-pass thread cycle (rapid in, thread, rapid out, rapid back), modal
 * in group 1 so that later blocks with X only cut the next passes; G76 the multiple-pass cycle in
 * the Fanuc two-block form ({@code G76 P(mmrraa) Q(min depth) R(allowance)} then
 * {@code G76 X Z R(taper) P(height) Q(first depth) F}) and the Haas one-block form
 * ({@code G76 X Z K(height) D(first depth) F [I A P]}). Every thread pass is a G01 block checked
 * like a cut and built as a spindle-synchronised motion ({@link CycleHost#thread}); the rapids are
 * ordinary G00 blocks. Under Haas M23 each G92/G76 pass ends with the profile's chamfered pull-out
 * ({@link PullOut}, made by {@code MotionBuilder}); G32 never does.
 */
final class Threading {
    /** The most passes a G76 is expanded into (E167 past it). */
    static final int MAX_PASSES = 1000;
    /**
     * The depth of a standard 60-degree thread, as a fraction of the lead: a deeper height is cut
     * as written, with warning E640 (a 1/2-14 NPT pipe thread is 0.8 x its pitch; docs/threading.md).
     */
    static final double HEIGHT_PER_LEAD = 0.65;
    /**
     * The sharp V (H = 0.866 P): no 60-degree thread is deeper, so a greater height is warning E193
     * (the control cuts it as written; no Haas or Fanuc manual alarms on the height against the lead).
     */
    static final double SHARP_V_PER_LEAD = 0.866;
    private static final Set<Integer> FANUC_ANGLES = Set.of(0, 29, 30, 55, 60, 80);

    private final CycleHost host;
    /** The modal thread in force (G32 or G92), if any. */
    private final ModalCycle modal = new ModalCycle();
    /** G92 in force: its end point (counts), taper (radius counts) and lead (as written). */
    private Point end;
    private double taper;
    /** The G92 in force's start angle, degrees (Q; a later block without Q keeps it, as the end and taper). */
    private double startAngle;
    /** What the Fanuc first block G76 P Q R left in force: finishing passes, angle, minimum depth and allowance (program units). */
    private int finishes = 1;
    private int angle = 60;
    private double minimum;
    private double allowance;
    /**
     * The Fanuc thread chamfer rr of the first block G76 P(mmrraa), in tenths of a lead
     * (parameter 5130, which that block sets): every G76 pass on a control without Haas's M23
     * ends with it ({@link PullOut#fanuc}). None before a first block gives one.
     */
    private int runOut;

    /**
     * Haas M23 in force: each pass of a G76 or G92 ends with the profile's chamfered pull-out
     * ({@link #pullsOut}). On at power-up on a control that has M23 (Haas), off after M24.
     */
    private boolean chamfer;

    Threading(CycleHost host) {
        this.host = host;
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

    private GFunction function(Word w) {
        return CycleBlocks.function(host, w);
    }

    /** The thread in force as the program wrote it ("G92"), for a finding about running it again. */
    String name() {
        return modal.name();
    }

    /** Whether the block makes the G32/G92 in force again: an axis word and no G of its group or one-shot G. */
    boolean repeats(RawBlock b) {
        return modal.repeats(host, b);
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
    void note(RawBlock b) {
        chamferWords(b);
        for (Word w : b.words()) {
            Letter l = w.letter();
            if (l == Letter.X || l == Letter.U || l == Letter.Z || l == Letter.W || l == Letter.G) {
                continued = null;
                break;
            }
        }
        modal.note(host, b);
    }

    /** A G32/G92/G76 block ({@code g} its word), or one that makes the G32/G92 in force again (g null). */
    List<CheckedBlock> run(RawBlock b, Word g, boolean isFirst) {
        GRole role = g == null ? modal.kind() : function(g).role();
        String label = g == null ? modal.name() : "G" + g.number();
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
            GFunction f = function(w);
            switch (w.letter()) {
                case N, S, T, M -> passOn.add(w);
                case G -> {
                    if (f != null && (f.role().thread() || f.role().singleCycle() || f.role().contourCycle())) {
                        foreign = foreign == null ? w : foreign;
                    } else {
                        passOn.add(w);
                    }
                }
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
        if (!passOn.isEmpty()) {
            host.one(new RawBlock(b.line(), passOn, passOn.get(passOn.size() - 1).span(), false, b.blockDelete()),
                    isFirst, null).ifPresent(done::add);
        }
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
            multiple(done, b, g, words, label);
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
        List<Word> axes = axes(words);
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

    private static List<Word> axes(Map<Letter, Word> words) {
        List<Word> axes = new ArrayList<>(2);
        for (Letter l : new Letter[] {Letter.X, Letter.U, Letter.Z, Letter.W}) {
            if (words.containsKey(l)) {
                axes.add(words.get(l));
            }
        }
        axes.sort((p, q) -> Integer.compare(p.span().column(), q.span().column()));
        return axes;
    }

    /** The lead: the block's F, else the F in force; NaN after reporting E195 or E198. */
    private double lead(Map<Letter, Word> words, String label, Span at) {
        Word f = words.get(Letter.F);
        double lead = f != null ? NumberText.decimal(f.number()) : host.state().feed();
        if (f != null && Double.isNaN(lead)) {
            host.out().error(Code.E014_DECIMAL_EXPECTED, f.span(), Letter.F);
            return Double.NaN;
        }
        if (Double.isNaN(lead)) {
            host.out().error(Code.E195_THREAD_WORD_MISSING, at, label, Phrase.THREAD_LEAD.arg());
            return Double.NaN;
        }
        if (!(lead > 0)) {
            host.out().error(Code.E198_THREAD_LEAD, f != null ? f.span() : at, label, NumberText.plain(lead));
            return Double.NaN;
        }
        return lead;
    }

    /** A length word in program units, radius (no-point rule of the control when written without a point), or NaN after E014. */
    private double length(Word w) {
        double v = NumberText.decimal(w.number());
        if (Double.isNaN(v)) {
            host.out().error(Code.E014_DECIMAL_EXPECTED, w.span(), w.letter());
            return Double.NaN;
        }
        if (!NumberText.hasPoint(w.number())) {
            v *= host.state().units() == Units.INCH ? host.profile().noPointInch() : host.profile().noPointMm();
        }
        return v;
    }

    /** A start angle Q in degrees (ThreadWords.startAngle); NaN after E197. */
    private double startAngle(Word w, String label) {
        double v = ThreadWords.startAngle(w.number());
        if (Double.isNaN(v)) {
            host.out().error(Code.E197_THREAD_WORD_VALUE, w.span(), label, w, Phrase.THREAD_START_ANGLE.arg());
        }
        return v;
    }

    /** A Fanuc G76 P/Q depth: a whole number of least increments, without a point; NaN after E197. */
    private double increments(Word w, String label) {
        long n = NumberText.integer(w.number());
        if (NumberText.hasPoint(w.number()) || n == NumberText.NOT_INTEGER) {
            host.out().error(Code.E197_THREAD_WORD_VALUE, w.span(), label, w,
                    Phrase.THREAD_LEAST_INCREMENTS.arg());
            return Double.NaN;
        }
        return n * (host.state().units() == Units.INCH ? 0.0001 : 0.001);
    }

    /** Where the axis words lead from the start (followed aside as a rapid), or null after their error. */
    private Point target(RawBlock b, List<Word> axes) {
        List<Word> ws = new ArrayList<>(axes.size() + 1);
        String rapid = host.profile().control().gFor(GRole.RAPID).map(f -> f.name().substring(1)).orElseThrow();
        ws.add(new Word(Letter.G, rapid, axes.get(0).span()));
        ws.addAll(axes);
        Diagnostics found = new Diagnostics();
        Dry dry = host.dry(new RawBlock(b.line(), ws, ws.get(ws.size() - 1).span(), false), host.state(),
                found);
        host.out().addAll(found);
        return dry == null ? null : dry.block().end();
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
        double lead = lead(words, label, at);
        if (Double.isNaN(lead)) {
            return;
        }
        Word taperWord = words.containsKey(Letter.R) ? words.get(Letter.R) : words.get(Letter.I);
        double t = g != null ? 0 : taper;
        if (taperWord != null) {
            double v = length(taperWord);
            if (Double.isNaN(v)) {
                return;
            }
            t = v * host.coordinates().perRadius(host.state().units());
        }
        double q = g != null ? 0 : startAngle;
        if (words.containsKey(Letter.Q)) {
            q = startAngle(words.get(Letter.Q), label);
            if (Double.isNaN(q)) {
                return;
            }
        }
        Point reached = target(b, axes(words));
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
        write(done, b.line(), at, s, moves, lead, label, i -> CycleOrigin.single(modal.name(), b.line()), pullOut, q);
    }

    /** Whether a G76 or G92 pass now ends with a chamfer: M23 in force and a chamfer of some length in the profile. */
    private boolean pullsOut() {
        return chamfer && host.profile().threadChamfer().cuts();
    }

    /** Whether the control has Haas's M23/M24 (its chamfer, not the Fanuc rr, ends a G76 pass). */
    private boolean m23() {
        return host.profile().control().allM().stream().anyMatch(f -> f.role() == gcnc.machine.MRole.THREAD_CHAMFER_ON);
    }

    /** G76: the Fanuc first block sets what stays in force; the second block, or the Haas one block, cuts. */
    private void multiple(List<CheckedBlock> done, RawBlock b, Word g, Map<Letter, Word> words, String label) {
        boolean x = words.containsKey(Letter.X) || words.containsKey(Letter.U);
        boolean z = words.containsKey(Letter.Z) || words.containsKey(Letter.W);
        boolean k = words.containsKey(Letter.K);
        boolean d = words.containsKey(Letter.D);
        // Haas: K and D (or one of them and no Fanuc Q); a K or D beside a Fanuc P/Q is a stray word
        boolean haas = k && d || (k || d) && !words.containsKey(Letter.Q);
        if (!x && !z && !haas) {
            first(words, label);
            return;
        }
        if (!x || !z) {
            host.out().error(Code.E195_THREAD_WORD_MISSING, g.span(), label, Phrase.THREAD_END_BOTH.arg());
            return;
        }
        Letter heightLetter = haas ? Letter.K : Letter.P;
        Letter depthLetter = haas ? Letter.D : Letter.Q;
        for (Letter l : new Letter[] {heightLetter, depthLetter}) {
            if (!words.containsKey(l)) {
                host.out().error(Code.E195_THREAD_WORD_MISSING, g.span(), label,
                        (l == heightLetter ? Phrase.THREAD_HEIGHT : Phrase.THREAD_FIRST_DEPTH).with(l));
                return;
            }
        }
        for (Letter l : haas ? new Letter[] {Letter.R}
                : new Letter[] {Letter.K, Letter.D, Letter.A, Letter.I}) {
            if (words.containsKey(l)) {
                host.out().error(Code.E161_CYCLE_WORD, words.get(l).span(), label, words.get(l));
                return;
            }
        }
        Word hw = words.get(heightLetter);
        Word dw = words.get(depthLetter);
        double height = haas ? length(hw) : increments(hw, label);
        double first = haas ? length(dw) : increments(dw, label);
        if (Double.isNaN(height) || Double.isNaN(first)) {
            return;
        }
        double lead = lead(words, label, g.span());
        if (Double.isNaN(lead)) {
            return;
        }
        if (!(height > 0)) {
            // Fanuc PS0062 (G71-G76 illegal command): zero or a negative thread height in G76
            host.out().error(Code.E180_PECK_NOT_POSITIVE, hw.span(), label, hw, "the thread height");
            return;
        }
        if (height > SHARP_V_PER_LEAD * lead + 1e-9) {
            // the control cuts it (no manual alarms on a height against the lead; issue 31): a
            // warning with the reason, which stands in for E640's
            host.out().report(Diagnostic.warning(Code.E193_THREAD_TOO_DEEP, hw.span(), label, hw,
                    NumberText.plain(SHARP_V_PER_LEAD * lead, 4), NumberText.plain(lead)));
        } else if (height > HEIGHT_PER_LEAD * lead + 1e-9) {
            host.out().report(Diagnostic.warning(Code.E640_THREAD_DEEPER_THAN_STANDARD, hw.span(), label, hw,
                    NumberText.plain(HEIGHT_PER_LEAD * lead, 4), NumberText.plain(lead)));
        }
        if (!(first > 0)) {
            host.out().error(Code.E194_THREAD_FIRST_DEPTH, dw.span(), label, dw);
            return;
        }
        int angle = this.angle;
        boolean bothFlanks = false; // Haas P2/P4
        ThreadPasses.Infeed infeed = ThreadPasses.Infeed.CONSTANT_AREA;
        int finishing = this.finishes;
        double min = this.minimum;
        double allow = this.allowance;
        if (haas) {
            finishing = 0;
            min = 0;
            allow = 0;
            angle = 60;
            if (words.containsKey(Letter.A)) {
                Word a = words.get(Letter.A);
                long v = ThreadWords.degrees(a.number());
                if (v == NumberText.NOT_INTEGER || v > 120) {
                    host.out().error(Code.E197_THREAD_WORD_VALUE, a.span(), label, a, Phrase.THREAD_ANGLE_RANGE.arg());
                    return;
                }
                angle = (int) v;
            }
            if (words.containsKey(Letter.P)) {
                Word p = words.get(Letter.P);
                long v = NumberText.integer(p.number());
                if (v < 1 || v > 4) {
                    host.out().error(Code.E197_THREAD_WORD_VALUE, p.span(), label, p,
                            Phrase.THREAD_INFEED.arg());
                    return;
                }
                infeed = v == 3 || v == 4 ? ThreadPasses.Infeed.CONSTANT_DEPTH : ThreadPasses.Infeed.CONSTANT_AREA;
                bothFlanks = v == 2 || v == 4;
            }
        }
        double q = 0;
        if (haas && words.containsKey(Letter.Q)) {
            q = startAngle(words.get(Letter.Q), label);
            if (Double.isNaN(q)) {
                return;
            }
        }
        if (allow >= height) {
            host.out().error(Code.E197_THREAD_WORD_VALUE, hw.span(), label, hw,
                    Phrase.THREAD_DEEPER_THAN_ALLOWANCE.with(NumberText.plain(allow)));
            return;
        }
        double[] depths = ThreadPasses.depths(height, first, min, allow, finishing, infeed, MAX_PASSES);
        if (depths == null) {
            host.out().error(Code.E167_CYCLE_TOO_MANY_PASSES, dw.span(), label, dw,
                    ThreadPasses.count(height, first, min, allow, finishing, infeed), MAX_PASSES);
            return;
        }
        Word taperWord = words.get(haas ? Letter.I : Letter.R);
        double taperProgram = 0;
        if (taperWord != null) {
            taperProgram = length(taperWord);
            if (Double.isNaN(taperProgram)) {
                return;
            }
        }
        Point root = target(b, axes(words));
        if (root == null) {
            return;
        }
        ModalState s = host.state();
        Units u = s.units();
        Coordinates c = host.coordinates();
        double perRadius = c.perRadius(u);
        double perZ = c.perZ(u);
        Point a = s.position();
        double t = taperProgram * perRadius;
        // +1: the start is above the thread (outside), -1 below it (a bore): the side the depth goes from
        double side = Math.signum(a.x() - root.x());
        double top = root.x() + side * height * perRadius;
        if (side == 0) {
            host.out().error(Code.E160_CYCLE_START_INSIDE, g.span(), label, b.line());
            return;
        }
        if (side * (a.x() - (top + t)) < 0 || side * (a.x() - top) < 0) {
            // between the root and the top: the control runs it (each pass rapids out to its depth
            // from the top), but the tool starts inside the thread's full form
            host.out().report(Diagnostic.warning(Code.E641_THREAD_START_BELOW_TOP, g.span(), label,
                    NumberText.plain((top - c.origin(s.next()).x()) / c.perX(u), 4)));
        }
        if (Math.abs(root.z() - a.z()) < 1) {
            host.out().error(Code.E196_THREAD_NOT_ALONG_Z, g.span(), label);
            return;
        }
        double dir = Math.signum(root.z() - a.z());
        double flank = Math.tan(Math.toRadians(angle / 2.0));
        List<Move> moves = new ArrayList<>(depths.length * 4);
        for (int i = 0; i < depths.length; i++) {
            double depth = depths[i];
            double xEnd = top - side * depth * perRadius;
            // flank infeed: the pass moves back along Z by depth x tan(angle / 2), so one flank cuts;
            // both flanks in turn (Haas P2/P4): ThreadWords.alternate
            double shift = bothFlanks ? -dir * ThreadWords.alternate(i, height, depth, flank) * perZ
                    : -dir * depth * flank * perZ;
            int pass = i + 1;
            moves.add(Move.line(true, new Point(xEnd + t, a.z() + shift), pass));
            moves.add(Move.line(false, new Point(xEnd, root.z() + shift), pass));
            moves.add(Move.line(true, new Point(a.x(), root.z() + shift), pass));
            moves.add(Move.line(true, a, pass));
        }
        int passes = depths.length;
        PullOut pullOut = pullsOut() ? new PullOut(host.profile().threadChamfer(), (int) side)
                : m23() ? null : PullOut.fanuc(runOut, host.profile().threadChamfer(), (int) side);
        write(done, b.line(), g.span(), s, moves, lead, label,
                i -> CycleOrigin.thread(label, i, passes, b.line(), Math.round(depths[i - 1] * 1e6)), pullOut, q);
    }

    /** The Fanuc first block G76 P(mmrraa) Q(minimum depth) R(finishing allowance): what stays in force. */
    private void first(Map<Letter, Word> words, String label) {
        for (Letter l : new Letter[] {Letter.F, Letter.K, Letter.D, Letter.I, Letter.A}) {
            if (words.containsKey(l)) {
                host.out().error(Code.E161_CYCLE_WORD, words.get(l).span(), label, words.get(l));
                return;
            }
        }
        int m = finishes;
        int rr = runOut;
        int aa = angle;
        double q = minimum;
        double r = allowance;
        if (words.containsKey(Letter.P)) {
            Word p = words.get(Letter.P);
            long v = NumberText.integer(p.number());
            if (v == NumberText.NOT_INTEGER || v > 999999) {
                host.out().error(Code.E197_THREAD_WORD_VALUE, p.span(), label, p,
                        Phrase.THREAD_P_DIGITS.arg());
                return;
            }
            m = (int) (v / 10000);
            rr = (int) (v / 100 % 100);
            aa = (int) (v % 100);
            if (m < 1) {
                host.out().error(Code.E197_THREAD_WORD_VALUE, p.span(), label, p,
                        Phrase.THREAD_FINISH_PASSES.arg());
                return;
            }
            if (!FANUC_ANGLES.contains(aa)) {
                host.out().error(Code.E197_THREAD_WORD_VALUE, p.span(), label, p,
                        Phrase.THREAD_ANGLE_DIGITS.arg());
                return;
            }
        }
        if (words.containsKey(Letter.Q)) {
            q = increments(words.get(Letter.Q), label);
            if (Double.isNaN(q)) {
                return;
            }
        }
        if (words.containsKey(Letter.R)) {
            Word w = words.get(Letter.R);
            r = length(w);
            if (Double.isNaN(r)) {
                return;
            }
            if (r < 0) {
                host.out().error(Code.E197_THREAD_WORD_VALUE, w.span(), label, w, Phrase.THREAD_ALLOWANCE.arg());
                return;
            }
        }
        finishes = m;
        runOut = rr;
        angle = aa;
        minimum = q;
        allowance = r;
    }

    /**
     * The moves as blocks at the cycle's line: rapids as G00 blocks, the thread passes as G01
     * blocks with the lead as F, checked as threads, ending with {@code pullOut}'s chamfer when it
     * is not null (Haas M23). After one fails, a rapid back to the start ends the cycle
     * ({@link CycleExpansion#abandon}).
     */
    private void write(List<CheckedBlock> done, int line, Span at, ModalState start, List<Move> moves, double lead,
                       String label, java.util.function.IntFunction<CycleOrigin> origins, PullOut pullOut,
                       double startAngle) {
        MoveWriter writer = new MoveWriter(CycleExpansion.frame(host, start), line, at);
        Point a = start.position();
        Point from = a;
        Word f = new Word(Letter.F, MoveWriter.number(lead), at);
        for (Move m : moves) {
            if (m.to().distanceTo(from) <= 1e-9) {
                continue;
            }
            CycleOrigin origin = origins.apply(m.pass());
            RawBlock block = writer.block(m, from);
            Optional<CheckedBlock> r;
            if (m.kind() == Move.Kind.FEED) {
                List<Word> ws = new ArrayList<>(block.words());
                ws.add(f);
                r = host.thread(new RawBlock(line, ws, at, false), false, origin, label, pullOut, startAngle);
            } else {
                r = host.one(block, false, origin);
            }
            if (r.isEmpty()) {
                CycleExpansion.abandon(host, writer, a, origin).ifPresent(done::add);
                break;
            }
            done.add(r.get());
            from = host.state().position();
        }
    }
}
