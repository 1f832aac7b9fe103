package gcnc.check;

import gcnc.check.cycle.Move;
import gcnc.check.cycle.ThreadPasses;
import gcnc.check.geom.Coordinates;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Phrase;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * G76, the multiple-pass thread cycle (docs/threading.md), in the Fanuc two-block form
 * ({@code G76 P(mmrraa) Q(min depth) R(allowance)} then {@code G76 X Z R(taper) P(height) Q(first
 * depth) F}) and the Haas one-block form ({@code G76 X Z K(height) D(first depth) F [I A P]}): the
 * depths of its passes ({@link ThreadPasses}), each pass four moves, written by
 * {@link ThreadPassWriter}. It keeps what a Fanuc first block leaves in force.
 */
final class MultipleThread {
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
    private final ThreadValues values;
    private final ThreadPassWriter writer;
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

    MultipleThread(CycleHost host, ThreadValues values, ThreadPassWriter writer) {
        this.host = host;
        this.values = values;
        this.writer = writer;
    }

    /**
     * G76: the Fanuc first block sets what stays in force; the second block, or the Haas one block,
     * cuts, each pass ending with the profile's chamfer when {@code pullsOut} (Haas M23 in force).
     */
    void run(List<CheckedBlock> done, RawBlock b, Word g, Map<Letter, Word> words, String label, boolean pullsOut) {
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
        Height h = height(g, words, label, haas);
        if (h == null) {
            return;
        }
        Infeed in = infeed(words, label, haas);
        if (in == null) {
            return;
        }
        if (in.allowance() >= h.height()) {
            host.out().error(Code.E197_THREAD_WORD_VALUE, h.heightWord().span(), label, h.heightWord(),
                    Phrase.THREAD_DEEPER_THAN_ALLOWANCE.with(NumberText.plain(in.allowance())));
            return;
        }
        double[] depths = ThreadPasses.depths(h.height(), h.first(), in.minimum(), in.allowance(), in.finishing(),
                in.kind(), MAX_PASSES);
        if (depths == null) {
            host.out().error(Code.E167_CYCLE_TOO_MANY_PASSES, h.depthWord().span(), label, h.depthWord(),
                    ThreadPasses.count(h.height(), h.first(), in.minimum(), in.allowance(), in.finishing(), in.kind()),
                    MAX_PASSES);
            return;
        }
        Word taperWord = words.get(haas ? Letter.I : Letter.R);
        double taper = 0;
        if (taperWord != null) {
            taper = values.length(taperWord);
            if (Double.isNaN(taper)) {
                return;
            }
        }
        cut(done, b, g, words, label, pullsOut, h, in, depths, taper);
    }

    /** The thread's height, first depth and lead, as the cutting block gives them (program units). */
    private record Height(Word heightWord, Word depthWord, double height, double first, double lead) { }

    /**
     * How the passes go in: the thread's angle, the infeed (Haas P1-P4: constant area or depth, one
     * flank or both), the finishing passes, the minimum depth and the allowance (a Fanuc first block's,
     * none on Haas), and the Haas Q start angle (degrees, 0 when none).
     */
    private record Infeed(int angle, boolean bothFlanks, ThreadPasses.Infeed kind, int finishing, double minimum,
                          double allowance, double startAngle) { }

    /**
     * The height (Haas K, Fanuc P) and first depth (Haas D, Fanuc Q) of the cutting block, and its
     * lead; null after the error that says what is missing or wrong. A height past the standard
     * form is cut as written, with a warning.
     */
    private Height height(Word g, Map<Letter, Word> words, String label, boolean haas) {
        Letter heightLetter = haas ? Letter.K : Letter.P;
        Letter depthLetter = haas ? Letter.D : Letter.Q;
        for (Letter l : new Letter[] {heightLetter, depthLetter}) {
            if (!words.containsKey(l)) {
                host.out().error(Code.E195_THREAD_WORD_MISSING, g.span(), label,
                        (l == heightLetter ? Phrase.THREAD_HEIGHT : Phrase.THREAD_FIRST_DEPTH).with(l));
                return null;
            }
        }
        for (Letter l : haas ? new Letter[] {Letter.R}
                : new Letter[] {Letter.K, Letter.D, Letter.A, Letter.I}) {
            if (words.containsKey(l)) {
                host.out().error(Code.E161_CYCLE_WORD, words.get(l).span(), label, words.get(l));
                return null;
            }
        }
        Word hw = words.get(heightLetter);
        Word dw = words.get(depthLetter);
        double height = haas ? values.length(hw) : values.increments(hw, label);
        double first = haas ? values.length(dw) : values.increments(dw, label);
        if (Double.isNaN(height) || Double.isNaN(first)) {
            return null;
        }
        double lead = values.lead(words, label, g.span());
        if (Double.isNaN(lead)) {
            return null;
        }
        if (!(height > 0)) {
            // Fanuc PS0062 (G71-G76 illegal command): zero or a negative thread height in G76
            host.out().error(Code.E180_PECK_NOT_POSITIVE, hw.span(), label, hw, "the thread height");
            return null;
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
            return null;
        }
        return new Height(hw, dw, height, first, lead);
    }

    /**
     * The infeed: on Fanuc what the first block left in force; on Haas a 60-degree thread unless A
     * says otherwise, P's infeed, no finishing passes or allowance, and Q's start angle. Null after
     * the error about a word out of range.
     */
    private Infeed infeed(Map<Letter, Word> words, String label, boolean haas) {
        if (!haas) {
            return new Infeed(angle, false, ThreadPasses.Infeed.CONSTANT_AREA, finishes, minimum, allowance, 0);
        }
        int degrees = 60;
        if (words.containsKey(Letter.A)) {
            Word a = words.get(Letter.A);
            long v = ThreadWords.degrees(a.number());
            if (v == NumberText.NOT_INTEGER || v > 120) {
                host.out().error(Code.E197_THREAD_WORD_VALUE, a.span(), label, a, Phrase.THREAD_ANGLE_RANGE.arg());
                return null;
            }
            degrees = (int) v;
        }
        ThreadPasses.Infeed kind = ThreadPasses.Infeed.CONSTANT_AREA;
        boolean bothFlanks = false; // Haas P2/P4
        if (words.containsKey(Letter.P)) {
            Word p = words.get(Letter.P);
            long v = NumberText.integer(p.number());
            if (v < 1 || v > 4) {
                host.out().error(Code.E197_THREAD_WORD_VALUE, p.span(), label, p, Phrase.THREAD_INFEED.arg());
                return null;
            }
            kind = v == 3 || v == 4 ? ThreadPasses.Infeed.CONSTANT_DEPTH : ThreadPasses.Infeed.CONSTANT_AREA;
            bothFlanks = v == 2 || v == 4;
        }
        double q = 0;
        if (words.containsKey(Letter.Q)) {
            q = values.startAngle(words.get(Letter.Q), label);
            if (Double.isNaN(q)) {
                return null;
            }
        }
        return new Infeed(degrees, bothFlanks, kind, 0, 0, 0, q);
    }

    /**
     * The passes, each four moves from the start point {@code a}: in to its depth (on the taper), along
     * Z to the end, out, and back; handed to the writer with the pull-out each pass ends with. Errors
     * where the start leaves no side to cut from (E160) or the thread does not run along Z (E196).
     */
    private void cut(List<CheckedBlock> done, RawBlock b, Word g, Map<Letter, Word> words, String label,
                     boolean pullsOut, Height h, Infeed in, double[] depths, double taperProgram) {
        Point root = values.target(b, ThreadValues.axes(words));
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
        double top = root.x() + side * h.height() * perRadius;
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
        double flank = Math.tan(Math.toRadians(in.angle() / 2.0));
        List<Move> moves = new ArrayList<>(depths.length * 4);
        for (int i = 0; i < depths.length; i++) {
            double depth = depths[i];
            double xEnd = top - side * depth * perRadius;
            // flank infeed: the pass moves back along Z by depth x tan(angle / 2), so one flank cuts;
            // both flanks in turn (Haas P2/P4): ThreadWords.alternate
            double shift = in.bothFlanks() ? -dir * ThreadWords.alternate(i, h.height(), depth, flank) * perZ
                    : -dir * depth * flank * perZ;
            int pass = i + 1;
            moves.add(Move.line(true, new Point(xEnd + t, a.z() + shift), pass));
            moves.add(Move.line(false, new Point(xEnd, root.z() + shift), pass));
            moves.add(Move.line(true, new Point(a.x(), root.z() + shift), pass));
            moves.add(Move.line(true, a, pass));
        }
        int passes = depths.length;
        PullOut pullOut = pullsOut ? new PullOut(host.profile().threadChamfer(), (int) side)
                : m23() ? null : PullOut.fanuc(runOut, host.profile().threadChamfer(), (int) side);
        writer.write(done, b.line(), g.span(), s, moves, h.lead(), label,
                i -> CycleOrigin.thread(label, i, passes, b.line(), Math.round(depths[i - 1] * 1e6)), pullOut,
                in.startAngle());
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
            q = values.increments(words.get(Letter.Q), label);
            if (Double.isNaN(q)) {
                return;
            }
        }
        if (words.containsKey(Letter.R)) {
            Word w = words.get(Letter.R);
            r = values.length(w);
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

    /** Whether the control has Haas's M23/M24 (its chamfer, not the Fanuc rr, ends a G76 pass). */
    private boolean m23() {
        return host.profile().control().allM().stream().anyMatch(f -> f.role() == gcnc.machine.MRole.THREAD_CHAMFER_ON);
    }
}
