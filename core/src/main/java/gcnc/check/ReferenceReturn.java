package gcnc.check;

import gcnc.check.cycle.CycleWords;
import gcnc.check.cycle.Move;
import gcnc.diag.Code;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;

/**
 * G30 (Fanuc 0i-TF, docs/semantics.md): {@code G30 [P2|P3|P4] X(U) Z(W)} returns the axes named
 * to the second (third, fourth) reference point through the intermediate point the words give, as
 * G28 does to the first: two rapids. The reference points are the machine's, so they are data of
 * the profile ({@code reference.2} .. {@code reference.4}); a G30 to one the profile does not give
 * is E631, a P other than 2-4 E630, no axis word E030.
 */
final class ReferenceReturn {
    private static final Set<Letter> OWN = EnumSet.of(Letter.P);

    private final Checker host;

    ReferenceReturn(Checker host) {
        this.host = host;
    }

    /** The block's G30 word, or null. */
    static Word word(RawBlock b, FunctionIndex functions) {
        java.util.List<Word> ws = b.words();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            if (w.letter() == Letter.G && !w.number().isEmpty()) {
                GFunction f = functions.g(w.code());
                if (f != null && f.role() == GRole.OTHER_HOME) {
                    return w;
                }
            }
        }
        return null;
    }

    /** The G30 block: its other words as a block of their own, then the two rapids. */
    List<CheckedBlock> run(RawBlock b, Word g, boolean isFirst) {
        String label = "G" + g.number();
        CycleWords words = CycleWords.read(b, g, label, OWN, OWN, 1, 1, w -> false, host.out());
        List<CheckedBlock> done = new ArrayList<>(3);
        List<Word> passOn = words != null ? words.passOn() : List.of();
        CycleBlocks.passOn(host, b, passOn, isFirst).ifPresent(done::add);
        if (words == null) {
            return done;
        }
        int n = words.has(Letter.P) ? (int) Math.round(words.value(Letter.P)) : 2;
        if (n < 2 || n > 4) {
            Word p = words.word(Letter.P);
            host.out().error(Code.E630_G30_REFERENCE_NUMBER, p.span(), label, p);
            return done;
        }
        if (words.axes().isEmpty()) {
            host.out().error(Code.E030_PARAMETER_EXPECTED, g.span(), label);
            return done;
        }
        Optional<Point> reference = host.profile().reference(n);
        if (reference.isEmpty()) {
            host.out().error(Code.E631_G30_NO_REFERENCE, g.span(), label, n, host.profile().name());
            return done;
        }
        ModalState start = host.state();
        Point via = CycleBlocks.target(host, b, words.axes(), start);
        if (via == null) {
            return done;
        }
        Point ref = reference.get();
        Point end = new Point(words.hasAxis(true) ? ref.x() : via.x(), words.hasAxis(false) ? ref.z() : via.z());
        List<Move> moves = List.of(Move.line(true, via, 1), Move.line(true, end, 1));
        done.addAll(CycleBlocks.write(host, label, b.line(), g.span(), moves, 1, start, -1, null));
        return done;
    }
}
