package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.ir.Point;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.machine.GRole;
import gcnc.ir.Word;
import gcnc.machine.Units;

/**
 * Thesis §4.2.2 action 2 ({@code ChkActiveParameter}, reading §4.1, §5): N, X, Z, U, W, I, K, R, P.
 * A word once per block; its number present and well formed; Table 6's range; N increasing where
 * the control says (thesis-2004; elsewhere a repeated N is a warning, from the checker). P is an
 * integer, except a dwell in seconds written with a point where the control reads G04 P so (Haas).
 * The letters of cycles and threads (Q, D, A ...) are read here too; Eb01 says where they belong.
 * A coordinate written without a decimal point is scaled by the profile's no-point rule in the
 * block's units. Emits E006, E007, E008, E009, E013, E014, E043. Writes the word and next.lastN.
 */
public final class Sa02Parameter implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        Letter l = w.letter();
        if (!d.fresh(w, out)) {
            return;
        }
        double v;
        boolean pSeconds = l == Letter.P && d.functions.control().dwellPSeconds() && NumberText.hasPoint(w.number());
        if (l == Letter.N || l == Letter.P && !pSeconds) {
            long n = w.code();
            if (n == NumberText.NOT_INTEGER) {
                d.fail(out, Code.E013_INTEGER_EXPECTED, w.span(), l);
                return;
            }
            v = n;
        } else {
            v = NumberText.decimal(w.number());
            if (Double.isNaN(v)) {
                d.fail(out, Code.E014_DECIMAL_EXPECTED, w.span(), l);
                return;
            }
            if (!pSeconds && !NumberText.hasPoint(w.number())) {
                double literal = v;
                v *= d.units == Units.INCH ? d.profile.noPointInch() : d.profile.noPointMm();
                if (v != literal) {
                    missingPoint(w, literal, v, d, out);
                }
            }
        }
        if (l == Letter.P && d.oneShot == GRole.LOOKAHEAD_LIMIT.number()) {
            // Haas G103 P: 0 (no limit) to 15 blocks, not Table 6's P; a count, never seconds
            if (pSeconds) {
                d.fail(out, Code.E013_INTEGER_EXPECTED, w.span(), l);
                return;
            }
            if (v > Sa14ModalNoMotion.MOST_LOOKAHEAD) {
                d.fail(out, Code.E009_PARAMETER_TOO_LARGE, w.span(), l, w.number(), Sa14ModalNoMotion.MOST_LOOKAHEAD);
                return;
            }
        } else if (pSeconds ? !positive(w, v, d, out) : !Limits.within(w, v, d, out)) {
            return;
        }
        if (l == Letter.N) {
            if (v <= d.prior.lastN() && d.functions.control().increasingN()) {
                d.fail(out, Code.E043_LINE_NUMBER_ORDER, w.span(), w.number(), d.prior.lastN());
                return;
            }
            d.next.lastN = (long) v;
        }
        d.accept(w, v);
    }

    /** How much larger than a point-less value its axis's last position must be for E107. */
    private static final double FAR = 50;

    /**
     * E107 (a warning): X42 on a control that reads it as 0.042 mm, where the tool stands 40 mm
     * from work zero on that axis, is almost surely X42. without its point. Only X and Z, only
     * values read as under 1 mm, and only where the last position is FAR times larger.
     */
    private static void missingPoint(Word w, double literal, double read, BlockDraft d, Diagnostics out) {
        if (w.letter() != Letter.X && w.letter() != Letter.Z || read == 0) {
            return;
        }
        double mm = d.units == Units.INCH ? read * 25.4 : read;
        if (Math.abs(mm) >= 1) {
            return;
        }
        Point origin = d.coordinates.origin(d.next);
        double last = w.letter() == Letter.X
                ? (d.prior.position().x() - origin.x()) / d.coordinates.perX(d.units)
                : (d.prior.position().z() - origin.z()) / d.coordinates.perZ(d.units);
        if (Math.abs(last) < FAR * Math.abs(read)) {
            return;
        }
        Word next = GluedWords.after(d.block, w);
        if (next != null && next.letter() == Letter.O) {
            return; // Z-1O0: not Z-1 without its point but Z-100 with an O for a zero (E120, Sa03)
        }
        String unit = d.units == Units.INCH ? "in" : "mm";
        out.report(Diagnostic.warning(Code.E107_NO_DECIMAL_POINT, w.span(), w, NumberText.plain(read), unit,
                NumberText.plain(literal)));
    }

    /** A dwell P in seconds with a point (Haas {@code G04 P0.5}): above zero, Table 6's upper limit. */
    private static boolean positive(Word w, double v, BlockDraft d, Diagnostics out) {
        if (v <= 0) {
            d.fail(out, Code.E008_PARAMETER_TOO_SMALL, w.span(), w.letter(), w.number(), 0);
            return false;
        }
        return Limits.within(w, Math.max(v, 1), d, out);
    }
}
