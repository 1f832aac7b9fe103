package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.check.NoseSide;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Word;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;

/**
 * Thesis §4.2.2 action 14: modal G codes without motion or parameters. G40/G41/G42 (tool nose
 * radius compensation: the side is recorded here, the path offset by gcnc.check.NoseCompensation;
 * G41 to G42 or back without G40 is the warning E174), G96
 * (constant surface speed: S of this and later blocks is m/min or ft/min), and, added by gcnc for
 * real safe-start lines, G80 (canned cycle cancel) and the plane: G18 (ZX, the lathe's plane) is
 * accepted, G17 and G19 are E112. Emits E016, E112, E174. Writes next.css, next.nose, d.g96.
 */
public final class Sa14ModalNoMotion implements SyntaxAction {
    @Override
    public int number() {
        return 14;
    }

    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        GFunction f = d.functions.g(w.code());
        if (!d.claimG(f.group(), w, out)) {
            return;
        }
        if (f.role() == GRole.PLANE_XY || f.role() == GRole.PLANE_YZ) {
            d.fail(out, Code.E112_PLANE_NOT_ZX, w.span(), w);
        } else if (f.role() == GRole.NOSE_COMP_LEFT || f.role() == GRole.NOSE_COMP_RIGHT) {
            NoseSide side = f.role() == GRole.NOSE_COMP_LEFT ? NoseSide.LEFT : NoseSide.RIGHT;
            NoseSide before = d.prior.nose();
            if (before != NoseSide.OFF && before != side) {
                // Fanuc changes sides in offset mode without an alarm: a warning, and the
                // compensation ends before this block and starts again on the other side (NoseCompensation)
                String was = before == NoseSide.LEFT ? "G41" : "G42";
                out.report(gcnc.diag.Diagnostic.warning(Code.E174_NOSE_SIDE_CHANGE, w.span(), w, was));
            }
            d.next.nose = side;
        } else if (f.role() == GRole.NOSE_COMP_CANCEL) {
            d.next.nose = NoseSide.OFF;
        } else if (f.role() == GRole.CSS) {
            d.next.css = true;
            d.g96 = w;
        }
    }
}
