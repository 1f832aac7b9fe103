package gcnc.check;

import gcnc.check.cycle.CycleWords;
import gcnc.check.geom.Coordinates;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import gcnc.tables.Tables.Param;
import java.util.EnumSet;
import java.util.Optional;
import java.util.Set;

/**
 * G10 L2 (docs/semantics.md, "Work offsets set by the program"): {@code G10 L2 P(n) X Z} writes
 * work offset n from the program, P1-P6 for G54-G59 and P0 for the external (common) offset that
 * every one of them adds, as the Fanuc 0i-TF and Haas controls do. X and Z replace the value (a
 * machine position as G53's words are: in the program's units from the machine zero, X a
 * diameter where X is); U and W, or X and Z under G91, add to it. The
 * blocks after it use the new value, the block's own frame and the moves already made do not
 * change. Other L numbers (tool offsets, parameters) are not supported yet (E625).
 *
 * <p>It only checks: {@link #read} splits the block, {@link #offset} says which offset the words
 * write and where; the checker checks the block of other words and commits the offset
 * ({@link OffsetAndReturn#setOffset}), findings go to the sink it is given.
 */
final class OffsetSetting {
    private static final Set<Letter> OWN = EnumSet.of(Letter.L, Letter.P);

    private OffsetSetting() {
    }

    /** Work offset {@code index} (0 the external one, 54-59 for G54-G59) to be set to {@code at}. */
    record Write(int index, Point at) {
    }

    /** The block's G10 word, or null. */
    static Word word(RawBlock b, FunctionIndex functions) {
        return CycleBlocks.gWord(b, functions, GRole.SET_OFFSETS);
    }

    /** The G10 block's words: its other words as a block of their own, and its L, P and axes (null after their error). */
    static CycleBlocks.Split read(RawBlock b, Word g, Diagnostics out) {
        return CycleBlocks.split(b, g, OWN, out);
    }

    /**
     * The offset the words write, from the state {@code s} after the block of other words and the
     * offsets in {@code now}; empty after an error (to {@code out}).
     */
    static Optional<Write> offset(Word g, CycleWords words, ModalState s, MachineProfile profile, Coordinates now,
                                  Diagnostics out) {
        String label = "G" + g.number();
        if (!words.has(Letter.L) || words.value(Letter.L) != 2) {
            Word l = words.word(Letter.L);
            out.error(Code.E625_G10_NOT_SUPPORTED, l != null ? l.span() : g.span(), label,
                    l != null ? l.toString() : "without L");
            return Optional.empty();
        }
        Word p = words.word(Letter.P);
        long n = p == null ? -1 : Math.round(words.value(Letter.P));
        if (n < 0 || n > 6) {
            out.error(Code.E626_G10_WORK_OFFSET_NUMBER, p != null ? p.span() : g.span(), label,
                    p != null ? p.toString() : "no P");
            return Optional.empty();
        }
        boolean uw = profile.control().gFor(GRole.RAPID).map(f -> f.words() == null
                || f.words().contains(Param.U)).orElse(true);
        Units u = s.units();
        double noPoint = u == Units.INCH ? profile.noPointInch() : profile.noPointMm();
        int index = n == 0 ? 0 : 53 + (int) n;
        Point was = now.work(index);
        double x = was.x();
        double z = was.z();
        for (Word w : words.axes()) {
            boolean incremental = w.letter() == Letter.U || w.letter() == Letter.W;
            if (incremental && !uw) {
                out.error(Code.E161_CYCLE_WORD, w.span(), label, w);
                return Optional.empty();
            }
            double v = NumberText.decimal(w.number());
            if (Double.isNaN(v)) {
                out.error(Code.E014_DECIMAL_EXPECTED, w.span(), w.letter());
                return Optional.empty();
            }
            v = NumberText.hasPoint(w.number()) ? v : v * noPoint;
            boolean add = incremental || s.incremental();
            // an offset is a machine position, as G53's words are: from the control's machine zero;
            // the external offset is a shift that the others add
            Point zero = index == 0 ? Point.ORIGIN : profile.machineZero();
            if (w.letter() == Letter.X || w.letter() == Letter.U) {
                double c = v * now.perX(u);
                x = add ? x + c : zero.x() + c;
            } else {
                double c = v * now.perZ(u);
                z = add ? z + c : zero.z() + c;
            }
        }
        return Optional.of(new Write(index, new Point(x, z)));
    }
}
