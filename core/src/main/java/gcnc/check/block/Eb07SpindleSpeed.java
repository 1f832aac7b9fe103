package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.machine.GRole;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Word;

/**
 * Thesis end-of-block operation 7: an S outside a G50 block needs a G50 clamp first (50) on a
 * control whose rule that is (thesis-2004; elsewhere the machine's maximum is the clamp until the
 * program sets one). Under G96 it is the surface speed; otherwise an rpm that may not exceed the
 * G50 clamp (48, which the thesis never raised: it compared volts with rpm, §12.9) nor the
 * machine's maximum (E119, which names it and the machine; the thesis used 15). Every one of them
 * is the S word's fault, so it is reported at the S word.
 * On a control that clamps instead ({@code spindle_above_clamp = clamp}: Fanuc, Haas) an S above
 * the G50 (G92 on system B) limit runs at the limit, and is the warning E280 (issue 31).
 * Emits E048, E050, E119, E280. Writes nothing: the S takes effect in {@code MotionBuilder}, so a block
 * that breaks only this check still sets its speed when the checker recovers from it.
 */
public final class Eb07SpindleSpeed implements BlockCheck {
    @Override
    public boolean prerequisite() {
        return true;
    }

    @Override
    public void run(BlockDraft d, Diagnostics out) {
        if (!d.has(Letter.S) || d.function == 50) {
            return;
        }
        double s = d.value(Letter.S);
        Word w = d.word(Letter.S);
        boolean clamped = !Double.isNaN(d.next.rpmClamp);
        if (!clamped && d.functions.control().clampFromG50()) {
            d.fail(out, Code.E050_S_BEFORE_G50, w.span());
            return;
        }
        if (d.next.css) {
            return;
        }
        if (clamped && s > d.next.rpmClamp) {
            if (d.functions.control().clampAboveLimit()) {
                out.report(Diagnostic.warning(Code.E280_S_CLAMPED_BY_LIMIT, w.span(), w.number(),
                        NumberText.plain(d.next.rpmClamp), clampName(d)));
                // the control turns at the limit: E119 below only if the limit is above the machine's
                s = d.next.rpmClamp;
            } else {
                d.fail(out, Code.E048_S_ABOVE_G50, w.span(), w.number(), NumberText.plain(d.next.rpmClamp));
                return;
            }
        }
        if (s > d.profile.maxRpm()) {
            d.fail(out, Code.E119_S_ABOVE_MACHINE_MAXIMUM, w.span(), w, NumberText.plain(d.profile.maxRpm()),
                    d.profile.name());
        }
    }

    /** The G that sets the limit as the control writes it: G50, or G92 on Fanuc's system B. */
    private static String clampName(BlockDraft d) {
        gcnc.machine.GFunction f = d.functions.g(GRole.REGISTER_AND_CLAMP);
        return f != null ? f.name() : "G50";
    }
}
