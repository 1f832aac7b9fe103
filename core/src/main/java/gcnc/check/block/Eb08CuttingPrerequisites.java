package gcnc.check.block;

import gcnc.check.BlockDraft;
import gcnc.check.ModalState;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.machine.Control;
import gcnc.machine.MFunction;
import gcnc.machine.MRole;
import gcnc.diag.Diagnostics;

/**
 * Thesis end-of-block operation 8 ({@code GenOutputRecord}, reading §7.2, §12.8): before a cut
 * (G01-G03 that moves), in this order: F set (39), chuck closed by M11 (38), spindle turning
 * (51 when no spindle M was ever given, 37 when it was stopped by M05/M19), G50 clamp set (41,
 * only where the control requires it). On a control where the operator closes the chuck, the
 * chuck starts closed ({@code ModalState.initial}), so 38 comes only after the program opened it.
 * The M functions applied before the motion in this same block count. Each is reported at the
 * cut's G01/G02/G03, or at its first axis word under a modal motion ({@link BlockDraft#blame}),
 * not at the block's last word as in the thesis. Emits E037-E039, E041, E051.
 *
 * <p>A feed per minute (G98/G94) with the spindle stopped by the program (M05, M19) is not judged
 * a cut here: a bar puller or stock puller feeds with the spindle stopped and the chuck open
 * ({@code M05 M11 G98 G01 Z-50. F1000. M10} on a Haas), and the control runs it. Whether such a
 * move meets stock is the simulator's to say (E306, E307 in {@code compile}); {@code check}, which
 * does not simulate, warns instead (E660, E661). Under a feed per revolution (G99/G95) the axis
 * cannot feed with the spindle stopped, so E037/E038 stay errors there. E038 names the control's
 * own chuck-close M code (Haas M10, the thesis's M11).
 */
public final class Eb08CuttingPrerequisites implements BlockCheck {
    @Override
    public boolean prerequisite() {
        return true;
    }

    @Override
    public void run(BlockDraft d, Diagnostics out) {
        if (d.function < 1 || d.function > 3 || d.motionWords() == 0) {
            return;
        }
        int spindle = d.spindleBefore != BlockDraft.NONE ? d.spindleBefore : d.prior.spindle();
        boolean stopped = spindle == MRole.SPINDLE_STOP.number() || spindle == MRole.SPINDLE_ORIENT.number();
        boolean open = d.next.chuck != 11 && d.next.chuck != ModalState.UNKNOWN;
        Control control = d.functions.control();
        if (Double.isNaN(d.next.feed)) {
            d.fail(out, Code.E039_FEED_NOT_SET, d.blame());
        } else if (stopped && !d.next.feedPerRev) {
            // not a cut unless it meets stock: compile's simulation decides (E306/E307)
            out.report(open ? Diagnostic.warning(Code.E661_PULL_NOT_JUDGED, d.blame(), mName(control, MRole.CHUCK_OPEN, "M10"))
                    : Diagnostic.warning(Code.E660_FEED_SPINDLE_STOPPED_NOT_JUDGED, d.blame(),
                            mName(control, MRole.SPINDLE_STOP, "M05")));
        } else if (open) {
            d.fail(out, Code.E038_CHUCK_OPEN_CUT, d.blame(), mName(control, MRole.CHUCK_CLOSE, "M11"));
        } else if (spindle == ModalState.UNKNOWN) {
            return;
        } else if (spindle == BlockDraft.NONE) {
            d.fail(out, Code.E051_SPINDLE_DIRECTION, d.blame());
        } else if (spindle != 3 && spindle != 4) {
            d.fail(out, Code.E037_SPINDLE_DIRECTION_BEFORE_CUT, d.blame());
        } else if (Double.isNaN(d.next.rpmClamp) && d.functions.control().clampFromG50()) {
            d.fail(out, Code.E041_G50_NOT_SET_BEFORE_CUT, d.blame());
        }
    }

    /** The control's own M code for {@code role} (Haas's chuck close is M10), else the thesis's. */
    static String mName(Control control, MRole role, String thesis) {
        return control.mFor(role).map(MFunction::name).orElse(thesis);
    }
}
