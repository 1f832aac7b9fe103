package gcnc.check;

import gcnc.check.CornerWords.Request;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Motion;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.util.ArrayList;
import java.util.List;

/**
 * The chamfers, corners and angle lines of a G71/G72/G73 contour, made when the cycle has read it
 * (docs/chamfer.md, "Together with the rest"): the roughing passes are planned over the contour the
 * control follows, and G70 runs the same blocks. The geometry and the errors are
 * {@link CornerInsertion}'s; here the contour's blocks are followed from the cycle's start, one
 * after the other, without the program's state.
 */
final class ContourCorners {
    private final CornerInsertion insertion;
    /** The checker, to look only: nothing here commits a block or a state. */
    private final Lookahead look;
    private final FunctionIndex functions;
    private final Diagnostics out;
    private final CornerWords words;
    private final AngleLine angles;

    ContourCorners(CornerInsertion insertion, Lookahead look, FunctionIndex functions, Diagnostics out,
                   CornerWords words, AngleLine angles) {
        this.insertion = insertion;
        this.look = look;
        this.functions = functions;
        this.out = out;
        this.words = words;
        this.angles = angles;
    }

    /**
     * The contour of a cycle (G71, G72, G73) with its corners made, followed from {@code start}
     * as the control follows it: each ,A line given its end, each chamfer or corner block
     * shortened, the chamfer line or arc after it, and the next move from the corner's end
     * (written with the G01 in force again, so that the arc's G02/G03 does not carry on when G70
     * runs the blocks). A corner that cannot be made is reported as in the program's flow (E607,
     * E609-E613, E210, E615) and its block goes into the contour without it. The blocks gcnc
     * cannot follow are passed on as they are: the contour reader reports them.
     */
    List<RawBlock> made(List<RawBlock> blocks, ModalState start) {
        List<RawBlock> in = new ArrayList<>(blocks);
        List<RawBlock> made = new ArrayList<>(blocks.size() + 4);
        ModalState s = start;
        for (int i = 0; i < in.size(); i++) {
            RawBlock b = in.get(i);
            if (b.malformed() || b.macro() != null) {
                made.add(b);
                continue;
            }
            if (angles.alone(b) && i + 1 < in.size()) {
                RawBlock[] pair = angles.pair(b, in.get(i + 1), s, out);
                if (pair != null) {
                    b = pair[0];
                    in.set(i + 1, pair[1]);
                }
            }
            if (angles.asks(b)) {
                b = angles.resolve(b, s, out);
            }
            List<Word> rest = new ArrayList<>(b.words().size());
            Request r = words.mayAsk(b) ? words.read(b, s, rest, out) : null;
            RawBlock stripped = r == null ? b : b.called(rest, b.last(), b.depth());
            Dry dry = look.peek(stripped, s, new Diagnostics());
            CornerInsertion.Made m = r == null || r.word() == null || dry == null ? null : contourCorner(stripped, r, dry, in, i);
            if (m == null) {
                made.add(stripped);
                s = dry == null ? s : dry.next();
                continue;
            }
            made.add(m.shortened());
            made.add(m.insert());
            in.set(i + 1, m.next());
            Dry cut = look.peek(m.shortened(), s, new Diagnostics());
            Dry round = cut == null ? null : look.peek(m.insert(), cut.next(), new Diagnostics());
            s = round == null ? dry.next() : round.next();
        }
        return made;
    }

    /** The corner of contour block {@code at} (run as {@code dry}) with the block after it, or null after its error. */
    private CornerInsertion.Made contourCorner(RawBlock b, Request r, Dry dry, List<RawBlock> in, int at) {
        Motion.Linear line = CornerInsertion.feedLine(dry.block());
        if (line == null || look.startsCycle(b)) {
            out.error(Code.E607_CORNER_NOT_ON_G01, r.word().span(), r.name());
            return null;
        }
        if (at + 1 >= in.size()) {
            out.error(Code.E609_CORNER_NO_NEXT_MOVE, r.word().span(), r.name(), b.line());
            return null;
        }
        RawBlock next = in.get(at + 1);
        if (next.malformed() || next.macro() != null) {
            return null;
        }
        if (angles.asks(next)) {
            next = angles.resolve(next, dry.next(), out);
            in.set(at + 1, next);
        }
        List<Word> rest = new ArrayList<>(next.words().size());
        RawBlock plain = !words.mayAsk(next) || words.read(next, dry.next(), rest, new Diagnostics()) == null ? next
                : next.called(rest, next.last(), next.depth());
        Dry after = look.peek(plain, dry.next(), new Diagnostics());
        if (after == null) {
            return null; // its own errors are reported when the contour is followed
        }
        if (!MotionKind.moves(after.block())) {
            out.error(Code.E609_CORNER_NO_NEXT_MOVE, r.word().span(), r.name(), next.line());
            return null;
        }
        Motion.Linear to = CornerInsertion.feedLine(after.block());
        if (to == null) {
            out.error(Code.E610_CORNER_NEXT_NOT_G01, r.word().span(), r.name(), next.line());
            return null;
        }
        CornerInsertion.Made m = insertion.make(b, r, line.from(), line.to(), dry.next(), next, to.to(), after.next());
        if (m == null) {
            return null;
        }
        return new CornerInsertion.Made(m.shortened(), m.insert(), withFeed(m.next()));
    }

    /** {@code b} with a G01 first when it has no motion G of its own (after an inserted arc). */
    private RawBlock withFeed(RawBlock b) {
        for (Word w : b.words()) {
            gcnc.machine.GFunction f = w.letter() == Letter.G && !w.number().isEmpty() ? functions.g(w.code()) : null;
            if (f != null && f.role().motion()) {
                return b;
            }
        }
        String code = String.format("%02d", functions.g(gcnc.machine.GRole.LINEAR).code());
        Word g01 = new Word(Letter.G, code, b.words().isEmpty() ? b.last() : b.words().get(0).span());
        List<Word> ws = new ArrayList<>(b.words().size() + 1);
        int at = 0;
        while (at < b.words().size() && b.words().get(at).letter() == Letter.N) {
            ws.add(b.words().get(at++));
        }
        ws.add(g01);
        ws.addAll(b.words().subList(at, b.words().size()));
        return b.called(ws, b.last(), b.depth());
    }
}
