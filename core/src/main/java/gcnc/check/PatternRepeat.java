package gcnc.check;

import gcnc.check.cycle.Contour;
import gcnc.check.cycle.CycleCall;
import gcnc.check.cycle.FirstBlock;
import gcnc.check.cycle.Pattern;
import gcnc.check.geom.Coordinates;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;
import gcnc.machine.Units;
import java.util.List;

/**
 * G73 once its contour is followed: the relief (Fanuc first block U W, Haas I K), the number of
 * passes (Fanuc first block R, Haas D) and the finishing allowance (U W), the passes of
 * {@link Pattern} written as blocks at the cycle's line and checked one by one.
 */
final class PatternRepeat {
    private PatternRepeat() {
    }

    /**
     * The number of passes a word gives (R of a first block, D): a whole number of at least one,
     * read as written (no no-point rule: it counts passes); NaN after E013, E008 or E167.
     */
    static double passes(Diagnostics out, CycleCall call, Letter l) {
        Word w = call.words().get(l);
        double v = NumberText.decimal(w.number());
        if (v != Math.rint(v)) {
            out.error(Code.E013_INTEGER_EXPECTED, w.span(), l);
            return Double.NaN;
        }
        if (v < 1) {
            out.error(Code.E008_PARAMETER_TOO_SMALL, w.span(), l, w.number(), 1);
            return Double.NaN;
        }
        if (v > StockRemoval.MAX_PASSES) {
            out.error(Code.E167_CYCLE_TOO_MANY_PASSES, w.span(), call.name(), w, (long) v,
                    StockRemoval.MAX_PASSES);
            return Double.NaN;
        }
        return v;
    }

    /**
     * The cycle's passes over {@code contour} from {@code start}, in the counts of {@code c}; empty
     * after a finding. {@code firstBlock}: what a Fanuc first block left in force.
     */
    static java.util.Optional<CycleExpansion.Passes> expand(Diagnostics out, CycleCall call, Coordinates c,
                                                            Contour contour, ModalState start, FirstBlock firstBlock) {
        double n = call.has(Letter.D) ? passes(out, call, Letter.D) : firstBlock.passes();
        if (Double.isNaN(n)) {
            if (!call.has(Letter.D)) {
                out.error(Code.E157_CYCLE_DEPTH_MISSING, call.g().span(), call.name(),
                        "D, or a " + call.name() + " U W R block before it");
            }
            return java.util.Optional.empty();
        }
        Units u = start.units();
        double reliefX = call.has(Letter.I) ? call.value(Letter.I) : zeroIfNone(firstBlock.reliefX());
        double reliefZ = call.has(Letter.K) ? call.value(Letter.K) : zeroIfNone(firstBlock.reliefZ());
        double ux = call.has(Letter.U) ? call.value(Letter.U) * c.perX(u) : 0;
        double wz = call.has(Letter.W) ? call.value(Letter.W) * c.perZ(u) : 0;
        int passes = (int) n;
        return java.util.Optional.of(new CycleExpansion.Passes(
                Pattern.moves(contour, ux, wz, reliefX * c.perRadius(u), reliefZ * c.perZ(u), passes), passes));
    }

    private static double zeroIfNone(double v) {
        return Double.isNaN(v) ? 0 : v;
    }
}
