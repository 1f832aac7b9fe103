package gcnc.plan;

import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import gcnc.machine.Blending;
import gcnc.machine.MachineProfile;
import java.util.List;

/**
 * What a block asks of the path {@link Contouring} gathers: why its start stops the machine (a
 * spindle speed, a tool, an output), and of its M functions whether one stops the program (M00; M01 with the optional stop switch on), switches an output at all, or switches one
 * that must not switch while the axes move (every output but those of the profile's {@code
 * plan.on_the_fly}).
 */
record BlockStops(MachineProfile profile, Blending blending) {
    /** Why the block's start stops the machine (its spindle, tool or outputs), or null when it does not. */
    Stop before(CheckedBlock b) {
        if (b.spindleRpm().isPresent()) {
            return Stop.SPINDLE;
        }
        if (b.tool().isPresent()) {
            return Stop.TOOL;
        }
        return stops(b.before()) ? Stop.OUTPUT : null;
    }

    /** Whether one of the M functions stops the program (M00; M01 when the optional stop switch is on). */
    boolean programStop(List<MCall> calls) {
        for (MCall m : calls) {
            if (profile.control().stopsProgram(m.code())) {
                return true;
            }
        }
        return false;
    }

    /** Whether any of the M functions switches an output (one without outputs writes nothing: no stop). */
    boolean switches(List<MCall> calls) {
        for (MCall m : calls) {
            if (!profile.outputsFor(m.code()).isEmpty()) {
                return true;
            }
        }
        return false;
    }

    /** Whether any of the M functions switches an output that must not switch while the axes move. */
    boolean stops(List<MCall> calls) {
        for (MCall m : calls) {
            if (!profile.outputsFor(m.code()).isEmpty() && !blending.flies(m.code())) {
                return true;
            }
        }
        return false;
    }
}
