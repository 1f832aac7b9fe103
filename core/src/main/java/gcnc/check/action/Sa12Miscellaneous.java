package gcnc.check.action;

import gcnc.check.BlockDraft;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.MCall;
import gcnc.ir.Word;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;

/**
 * Thesis §4.2.2 action 12: an M function (every M but the program end), by what it does in the
 * control (Haas's M10 closes the chuck, the thesis's M11). One M per group per block (the text
 * asks for it, the code never checked: §12.19). The chuck may not open while the spindle runs
 * (error 40, thesis §4.5; only a running spindle counts, not "never stopped"). The M goes to
 * {@code before} (moments 0, 1) or {@code after} (99) in source order (decision D2).
 * A C-axis or live-tool code (function {@code axis_option}) is a no-op with note E649; Fanuc's
 * M29 (function {@code rigid_tap}) one with note E720.
 * Emits E016, E040, E649, E720. Writes next.spindle, next.chuck, d.spindleBefore.
 */
public final class Sa12Miscellaneous implements SyntaxAction {
    @Override
    public void apply(Word w, BlockDraft d, Diagnostics out) {
        int code = (int) w.code();
        MFunction f = d.functions.m(code);
        if (!d.claimM(f.group(), w, out)) {
            return;
        }
        MRole r = f.role();
        if (r == MRole.CHUCK_OPEN && (running(d.prior.spindle()) || running(d.spindleBefore))
                || running(r.number()) && d.next.chuck == MRole.CHUCK_OPEN.number()
                && d.prior.chuck() != MRole.CHUCK_OPEN.number()) {
            d.fail(out, Code.E040_SPINDLE_RUNNING_CHUCK_OPEN, w.span());
            return;
        }
        if (r == MRole.AXIS_OPTION || r == MRole.RIGID_TAP) {
            // the control runs it; what gcnc makes of it differs (no C axis; a tap not geared to the spindle)
            out.report(new gcnc.diag.Diagnostic(r == MRole.AXIS_OPTION ? Code.E649_M_FOR_AXIS_NOT_USED
                    : Code.E720_RIGID_TAP_NOT_GEARED, gcnc.diag.Severity.NOTE, w.span(),
                    java.util.List.of(Integer.toString(code))));
        }
        d.next.set(r);
        if (r.spindleGroup() && f.beforeMotion()) {
            d.spindleBefore = r.number();
        }
        d.unpoweredM(f, w);
        d.addM(new MCall(code), f.beforeMotion());
    }

    private static boolean running(int spindle) {
        return spindle == MRole.SPINDLE_CW.number() || spindle == MRole.SPINDLE_CCW.number();
    }
}
