package gcnc.check;

import gcnc.check.CornerWords.Request;
import gcnc.check.cycle.Move;
import gcnc.check.cycle.MoveWriter;
import gcnc.check.geom.CornerGeometry;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.Control;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.List;

/**
 * G01 chamfering and corner rounding (docs/chamfer.md): a G01 block that asks for a chamfer or a
 * rounded corner at its end (Haas {@code ,C} {@code ,R}, or I/K for a 90-degree chamfer; Fanuc T
 * C, I, K and R for a 90-degree corner) is held until the next move shows the corner. Then it goes
 * on shortened, followed by the chamfer line or tangent arc as a block of its own at the same line,
 * then the blocks held between, then the next move, which starts where the chamfer ends. Every
 * block goes through the checker as an ordinary block, so nose compensation, the backend and the
 * simulator see the chamfered contour and need nothing of their own.
 *
 * <p>At most {@value #STILL_LIMIT} blocks without a move may stand between the two moves (Haas
 * names a G04; Fanuc takes none, PS0051); past that, at the end of the program, or when the next
 * block does not move along a G01, the corner is an error and the block runs unchamfered, so the
 * rest of the program is still checked. The corner words ({@link CornerWords}) are taken out of
 * every block before anything else reads it, so no other check sees them.
 */
final class CornerInsertion {
    /** Blocks without a move held between a corner block and its next move (as NoseCompensation's). */
    static final int STILL_LIMIT = NoseCompensation.STILL_LIMIT;

    /** A corner block waiting for its next move, with the blocks without a move read since. */
    private record Held(RawBlock block, Request request, boolean isFirst, Point from, Point corner,
                        ModalState after, List<RawBlock> still, ModalState afterStill) {
    }

    private final CornerHost host;
    private final CornerWords words;
    private final AngleLine angles;
    private Held held;
    /** A G01 with ,A alone, waiting for the block that completes the two-block form ({@link AngleLine#pair}). */
    private RawBlock angleAlone;
    private boolean angleAloneFirst;

    CornerInsertion(CornerHost host) {
        this.host = host;
        this.words = new CornerWords(host);
        this.angles = new AngleLine(host);
    }

    /** The same insertion for the other position of the block delete switch (the checker's fork). */
    CornerInsertion copy(CornerHost other) {
        CornerInsertion c = new CornerInsertion(other);
        c.held = held == null ? null : new Held(held.block, held.request, held.isFirst, held.from, held.corner,
                held.after, new ArrayList<>(held.still), held.afterStill);
        c.angleAlone = angleAlone;
        c.angleAloneFirst = angleAloneFirst;
        return c;
    }

    /** A cycle's contour with its corners made ({@link ContourCorners#made}). */
    List<RawBlock> inContour(List<RawBlock> blocks, ModalState start) {
        return new ContourCorners(this, host, host.functions(), host.out(), words, angles)
                .made(blocks, start);
    }

    /** The next block of the program's flow: held, released with the corner, or passed on. */
    List<CheckedBlock> flow(RawBlock b, boolean isFirst) {
        if (angleAlone != null) {
            return completeAngle(b);
        }
        if (held != null) {
            return next(b);
        }
        if (b.malformed() || b.macro() != null || host.readingContour() != null) {
            // a contour block keeps its corner words: the cycle makes its corners ({@link #inContour})
            return host.flowOn(b, isFirst);
        }
        if (angles.alone(b)) {
            angleAlone = b;
            angleAloneFirst = isFirst;
            return List.of();
        }
        if (angles.asks(b)) {
            b = angles.resolve(b, host.state(), host.out());
        }
        if (!words.mayAsk(b)) {
            return host.flowOn(b, isFirst); // nearly every block: nothing allocated, nothing run twice
        }
        Diagnostics out = host.out();
        List<Word> rest = new ArrayList<>(b.words().size());
        Request r = words.read(b, host.state(), rest, out);
        if (r == null) {
            return host.flowOn(b, isFirst);
        }
        if (r.taken() != null) {
            host.takeFixed(r.taken());
            return List.of(); // the thesis's R on a G01 (E025): refused, the state taken past it
        }
        RawBlock stripped = b.called(rest, b.last(), b.depth());
        if (r.word() == null) {
            return host.flowOn(stripped, isFirst); // an error was reported; the block runs without it
        }
        if (host.startsCycle(stripped)) {
            out.error(Code.E607_CORNER_NOT_ON_G01, r.word().span(), r.name());
            return host.flowOn(stripped, isFirst);
        }
        Dry dry = host.peek(stripped, host.state(), new Diagnostics());
        if (dry == null) {
            return host.flowOn(stripped, isFirst); // its own errors are reported when it runs
        }
        Motion.Linear line = feedLine(dry.block());
        if (line == null) {
            out.error(Code.E607_CORNER_NOT_ON_G01, r.word().span(), r.name());
            return host.flowOn(stripped, isFirst);
        }
        held = new Held(stripped, r, isFirst, line.from(), line.to(), dry.next(), new ArrayList<>(), dry.next());
        return List.of();
    }

    /** The block after a G01 with ,A alone: the two-block form made, or E606 and both run as written. */
    private List<CheckedBlock> completeAngle(RawBlock b) {
        RawBlock first = angleAlone;
        boolean isFirst = angleAloneFirst;
        angleAlone = null;
        RawBlock[] pair = angles.pair(first, b, host.state(), host.out());
        List<CheckedBlock> done = new ArrayList<>();
        if (pair == null) {
            done.addAll(flow(angles.resolve(first, host.state(), host.out()), isFirst));
            done.addAll(flow(b, false));
        } else {
            done.addAll(flow(pair[0], isFirst));
            done.addAll(flow(pair[1], false));
        }
        return done;
    }

    /** The program ended with a corner block held (it has no M30 either): E609. */
    void finish(int lastLine) {
        if (angleAlone != null) {
            RawBlock first = angleAlone;
            angleAlone = null;
            flow(angles.resolve(first, host.state(), host.out()), angleAloneFirst); // a corner on it is E609 below
        }
        if (held != null) {
            host.out().report(held.block.error(Code.E609_CORNER_NO_NEXT_MOVE, held.request.word().span(), held.request.name(), lastLine));
            held = null;
        }
    }

    /** A block after a held corner block. */
    private List<CheckedBlock> next(RawBlock b) {
        Held h = held;
        if (!b.malformed() && b.macro() == null && angles.asks(b)) {
            b = angles.resolve(b, h.afterStill, host.out());
        }
        if (b.malformed() || b.macro() != null || host.startsCycle(b)) {
            // a block gcnc cannot follow (reported on its own) or a cycle: no G01 to make the corner with
            if (!b.malformed() && b.macro() == null) {
                host.out().report(h.block.error(Code.E610_CORNER_NEXT_NOT_G01, h.request.word().span(), h.request.name(), b.line()));
            }
            return release(b);
        }
        // the next block's own corner words are not part of its move
        List<Word> rest = new ArrayList<>(b.words().size());
        RawBlock plain = !words.mayAsk(b) || words.read(b, h.afterStill, rest, new Diagnostics()) == null ? b
                : b.called(rest, b.last(), b.depth());
        Dry dry = host.peek(plain, h.afterStill, new Diagnostics());
        if (dry == null) {
            return release(b); // its own errors are reported when it runs
        }
        if (!MotionKind.moves(dry.block())) {
            boolean letters = host.profile().control().corners() == Control.Corners.LETTERS;
            if (dry.next().ended() || letters || h.still.size() >= STILL_LIMIT) {
                // the end of the program; Fanuc: the very next block must move (PS0051); Haas: bounded
                host.out().report(h.block.error(Code.E609_CORNER_NO_NEXT_MOVE, h.request.word().span(), h.request.name(), b.line()));
                return release(b);
            }
            h.still.add(b);
            held = new Held(h.block, h.request, h.isFirst, h.from, h.corner, h.after, h.still, dry.next());
            return List.of();
        }
        Motion.Linear line = feedLine(dry.block());
        if (line == null) {
            host.out().report(h.block.error(Code.E610_CORNER_NEXT_NOT_G01, h.request.word().span(), h.request.name(), b.line()));
            return release(b);
        }
        return corner(h, b, line.to(), dry.next());
    }

    /** Makes the corner between the held move and the next one ending at {@code end}, or reports why not. */
    private List<CheckedBlock> corner(Held h, RawBlock next, Point end, ModalState nextState) {
        Made m = make(h.block, h.request, h.from, h.corner, h.after, next, end, nextState);
        if (m == null) {
            return release(next);
        }
        held = null;
        List<CheckedBlock> done = new ArrayList<>();
        done.addAll(host.flowOn(m.shortened, h.isFirst));
        done.addAll(host.flowOn(m.insert, false));
        host.keepMotion(h.after.motion());
        for (RawBlock s : h.still) {
            done.addAll(host.flowOn(s, false));
        }
        done.addAll(flow(m.next, false));
        return done;
    }

    /** A corner made: the corner block shortened, the chamfer line or arc, and the next move from its end. */
    record Made(RawBlock shortened, RawBlock insert, RawBlock next) {
    }

    /**
     * The blocks of the corner {@code r} of {@code block} (from {@code from} to {@code corner}, the
     * state {@code after} it) with the next move {@code next} ending at {@code end}; null after the
     * error that says why there is none.
     */
    Made make(RawBlock block, Request r, Point from, Point corner, ModalState after, RawBlock next,
                      Point end, ModalState nextState) {
        Units u = after.units();
        double px = host.coordinates().perRadius(u);
        double pz = host.coordinates().perZ(u);
        Point p0 = new Point(from.x() / px, from.z() / pz);
        Point p1 = new Point(corner.x() / px, corner.z() / pz);
        Point p2 = new Point(end.x() / px, end.z() / pz);
        CornerGeometry.Corner c = r.round() ? CornerGeometry.round(p0, p1, p2, r.size())
                : CornerGeometry.chamfer(p0, p1, p2, r.size());
        if (c.ok() && r.square() && !squareFits(block, r, p0, p1, p2, next)) {
            return null;
        }
        if (!c.ok()) {
            if (c.failure() == CornerGeometry.Failure.IN_LINE) {
                host.out().report(block.error(Code.E613_CORNER_IN_LINE, r.word().span(), r.name()));
            } else {
                host.out().report(block.error(Code.E611_CORNER_TOO_LARGE, r.word().span(), r.name(), length(c.taken(), u),
                        length(c.length(), u), c.failure() == CornerGeometry.Failure.FIRST_TOO_SHORT
                                ? block.line() : next.line()));
            }
            return null;
        }
        MoveWriter writer = new MoveWriter(CycleBlocks.frame(host.coordinates(), host.profile(), after), block.line(), r.word().span());
        Point start = counts(c.start(), px, pz);
        Point stop = counts(c.end(), px, pz);
        Move.Kind kind = c.centre() == null ? Move.Kind.FEED
                : c.clockwise() ? Move.Kind.ARC_CW : Move.Kind.ARC_CCW;
        Point centre = c.centre() == null ? null : counts(c.centre(), px, pz);
        RawBlock insert = writer.block(new Move(kind, stop, centre, 0), start);
        // the next move now starts where the corner ends: written as increments it is rewritten
        // from there, so that it still ends where the program put it
        RawBlock moved = incremental(next, nextState)
                ? moveTo(next, new MoveWriter(CycleBlocks.frame(host.coordinates(), host.profile(), nextState), next.line(),
                        next.words().get(0).span()), end, stop)
                : next;
        return new Made(moveTo(block, writer, start, from), insert, moved);
    }

    /** The 90-degree forms: the moves along the two axes, and I for a first move along Z, K along X. */
    private boolean squareFits(RawBlock block, Request r, Point p0, Point p1, Point p2, RawBlock next) {
        Letter l = r.word().letter();
        boolean alongZ = CornerGeometry.firstAlongZ(p0, p1);
        boolean letters = host.profile().control().corners() == Control.Corners.LETTERS;
        if (letters && (l == Letter.C || l == Letter.R) && !CornerGeometry.square(p0, p1, p2)) {
            // Fanuc's C and R are for a corner between the two axes (PS0054); at another angle the
            // control wants the direct drawing form with its comma, which gcnc reads
            host.out().report(block.error(Code.E210_CORNER_WANTS_COMMA, r.word().span(), r.name(), next.line(), "," + l.name()));
            return false;
        }
        if (!CornerGeometry.square(p0, p1, p2) || l == Letter.I && !alongZ || l == Letter.K && alongZ) {
            host.out().report(block.error(Code.E612_CORNER_NOT_SQUARE, r.word().span(), r.name(), next.line()));
            return false;
        }
        // Fanuc: the sign says which way the next move goes (C-1. into a -Z move); a corner the
        // other way is not a path gcnc can follow, and not what the program meant
        double along = alongZ ? p2.x() - p1.x() : p2.z() - p1.z();
        if (letters && Math.signum(along) != r.sign()) {
            host.out().report(block.error(Code.E615_CORNER_SIGN, r.word().span(), r.name(), next.line()));
            return false;
        }
        return true;
    }

    /** Gives up the held corner: its block runs as written (without the corner), then the rest. */
    private List<CheckedBlock> release(RawBlock next) {
        Held h = held;
        held = null;
        List<CheckedBlock> done = new ArrayList<>(host.flowOn(h.block, h.isFirst));
        for (RawBlock s : h.still) {
            done.addAll(host.flowOn(s, false));
        }
        done.addAll(flow(next, false));
        return done;
    }

    /** {@code b} with its X, Z, U and W replaced by a move from {@code from} to {@code to}. */
    static RawBlock moveTo(RawBlock b, MoveWriter writer, Point to, Point from) {
        List<Word> words = new ArrayList<>(b.words().size() + 1);
        for (Word w : b.words()) {
            Letter l = w.letter();
            if (l != Letter.X && l != Letter.Z && l != Letter.U && l != Letter.W) {
                words.add(w);
            }
        }
        List<Word> axes = writer.block(Move.line(false, to, 0), from).words();
        words.addAll(axes.subList(1, axes.size())); // its X and Z; the block keeps its own G words
        return b.called(words, b.last(), b.depth());
    }

    /** Whether the next block moves by increments (U, W, or G91 in force after it). */
    private static boolean incremental(RawBlock b, ModalState after) {
        if (after.incremental()) {
            return true;
        }
        for (Word w : b.words()) {
            if (w.letter() == Letter.U || w.letter() == Letter.W) {
                return true;
            }
        }
        return false;
    }

    /** The block's one feed move (a G01), or null. */
    static Motion.Linear feedLine(CheckedBlock c) {
        return CornerWords.feedLine(c.motions());
    }

    private static Point counts(Point p, double px, double pz) {
        return new Point(p.x() * px, p.z() * pz);
    }

    private static String length(double v, Units u) {
        return NumberText.plain(v, 4) + (u == Units.INCH ? " in" : " mm");
    }
}
