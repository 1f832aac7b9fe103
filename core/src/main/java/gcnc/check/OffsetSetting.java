package gcnc.check;

import gcnc.check.cycle.CycleWords;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.Units;
import gcnc.tables.Tables.Param;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

/**
 * G10 L2 (docs/semantics.md, "Work offsets set by the program"): {@code G10 L2 P(n) X Z} writes
 * work offset n from the program, P1-P6 for G54-G59 and P0 for the external (common) offset that
 * every one of them adds, as the Fanuc 0i-TF and Haas controls do. X and Z replace the value (a
 * machine position as G53's words are: in the program's units from the machine zero, X a
 * diameter where X is); U and W, or X and Z under G91, add to it. The
 * blocks after it use the new value, the block's own frame and the moves already made do not
 * change. Other L numbers (tool offsets, parameters) are not supported yet (E625).
 */
final class OffsetSetting {
    private static final Set<Letter> OWN = EnumSet.of(Letter.L, Letter.P);

    private final Checker host;

    OffsetSetting(Checker host) {
        this.host = host;
    }

    /** The block's G10 word, or null. */
    static Word word(RawBlock b, FunctionIndex functions) {
        java.util.List<Word> ws = b.words();
        for (int at = 0; at < ws.size(); at++) { // an index: no iterator per block
            Word w = ws.get(at);
            if (w.letter() == Letter.G && !w.number().isEmpty()) {
                GFunction f = functions.g(w.code());
                if (f != null && f.role() == GRole.SET_OFFSETS) {
                    return w;
                }
            }
        }
        return null;
    }

    /** The G10 block: its other words as a block of their own, then the offset written. */
    List<CheckedBlock> run(RawBlock b, Word g, boolean isFirst) {
        String label = "G" + g.number();
        CycleWords words = CycleWords.read(b, g, label, OWN, OWN, 1, 1, w -> false, host.out());
        List<CheckedBlock> done = new ArrayList<>(1);
        List<Word> passOn = words != null ? words.passOn() : List.of();
        if (!passOn.isEmpty()) {
            host.one(new RawBlock(b.line(), passOn, passOn.get(passOn.size() - 1).span(), false, b.blockDelete()),
                    isFirst, null).ifPresent(done::add);
        }
        if (words == null) {
            return done;
        }
        if (!words.has(Letter.L) || words.value(Letter.L) != 2) {
            Word l = words.word(Letter.L);
            host.out().error(Code.E625_G10_NOT_SUPPORTED, l != null ? l.span() : g.span(), label,
                    l != null ? l.toString() : "without L");
            return done;
        }
        Word p = words.word(Letter.P);
        long n = p == null ? -1 : Math.round(words.value(Letter.P));
        if (n < 0 || n > 6) {
            host.out().error(Code.E626_G10_WORK_OFFSET_NUMBER, p != null ? p.span() : g.span(), label,
                    p != null ? p.toString() : "no P");
            return done;
        }
        boolean uw = host.profile().control().gFor(GRole.RAPID).map(f -> f.words() == null
                || f.words().contains(Param.U)).orElse(true);
        ModalState s = host.state();
        Units u = s.units();
        double noPoint = u == Units.INCH ? host.profile().noPointInch() : host.profile().noPointMm();
        int index = n == 0 ? 0 : 53 + (int) n;
        Point now = host.coordinates().work(index);
        double x = now.x();
        double z = now.z();
        for (Word w : words.axes()) {
            boolean incremental = w.letter() == Letter.U || w.letter() == Letter.W;
            if (incremental && !uw) {
                host.out().error(Code.E161_CYCLE_WORD, w.span(), label, w);
                return done;
            }
            double v = NumberText.decimal(w.number());
            if (Double.isNaN(v)) {
                host.out().error(Code.E014_DECIMAL_EXPECTED, w.span(), w.letter());
                return done;
            }
            v = NumberText.hasPoint(w.number()) ? v : v * noPoint;
            boolean add = incremental || s.incremental();
            // an offset is a machine position, as G53's words are: from the control's machine zero;
            // the external offset is a shift that the others add
            Point zero = index == 0 ? Point.ORIGIN : host.profile().machineZero();
            if (w.letter() == Letter.X || w.letter() == Letter.U) {
                double c = v * host.coordinates().perX(u);
                x = add ? x + c : zero.x() + c;
            } else {
                double c = v * host.coordinates().perZ(u);
                z = add ? z + c : zero.z() + c;
            }
        }
        host.coordinates().setWork(index, new Point(x, z));
        return done;
    }
}
