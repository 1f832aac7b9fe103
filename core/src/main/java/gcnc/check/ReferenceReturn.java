package gcnc.check;

import gcnc.check.cycle.CycleWords;
import gcnc.check.cycle.Move;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
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
 *
 * <p>It only checks: {@link #read} splits the block, {@link #reference} finds the point,
 * {@link #moves} gives the two rapids; the checker checks the block of other words, follows the
 * intermediate point and checks and commits the moves ({@link OffsetAndReturn#returnToReference}).
 */
final class ReferenceReturn {
    private static final Set<Letter> OWN = EnumSet.of(Letter.P);

    private ReferenceReturn() {
    }

    /** The block's G30 word, or null. */
    static Word word(RawBlock b, FunctionIndex functions) {
        return CycleBlocks.gWord(b, functions, GRole.OTHER_HOME);
    }

    /** The G30 block's words: its other words as a block of their own, and its P and axes (null after their error). */
    static CycleBlocks.Split read(RawBlock b, Word g, Diagnostics out) {
        return CycleBlocks.split(b, g, OWN, out);
    }

    /** The reference point P names (2 without P) in the profile; empty after an error (to {@code out}). */
    static Optional<Point> reference(Word g, CycleWords words, MachineProfile profile, Diagnostics out) {
        String label = "G" + g.number();
        int n = words.has(Letter.P) ? (int) Math.round(words.value(Letter.P)) : 2;
        if (n < 2 || n > 4) {
            Word p = words.word(Letter.P);
            out.error(Code.E630_G30_REFERENCE_NUMBER, p.span(), label, p);
            return Optional.empty();
        }
        if (words.axes().isEmpty()) {
            out.error(Code.E030_PARAMETER_EXPECTED, g.span(), label);
            return Optional.empty();
        }
        Optional<Point> reference = profile.reference(n);
        if (reference.isEmpty()) {
            out.error(Code.E631_G30_NO_REFERENCE, g.span(), label, n, profile.name());
        }
        return reference;
    }

    /** The two rapids: to the intermediate point {@code via}, then the axes named to {@code ref}. */
    static List<Move> moves(CycleWords words, Point ref, Point via) {
        Point end = new Point(words.hasAxis(true) ? ref.x() : via.x(), words.hasAxis(false) ? ref.z() : via.z());
        return List.of(Move.line(true, via, 1), Move.line(true, end, 1));
    }
}
