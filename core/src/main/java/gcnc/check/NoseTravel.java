package gcnc.check;

import gcnc.check.geom.NumberText;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.machine.Axis;
import gcnc.machine.MachineProfile;

/**
 * E179: a compensated move beyond the travel. The checker judged the programmed point (E015), which
 * may be inside while the tool, the nose radius off it, is not (facing to the centreline on a
 * machine with little travel past it).
 */
final class NoseTravel {
    private NoseTravel() {
    }

    /** Reports E179 once for the block when one of its compensated moves leaves the travel. */
    static void check(CheckedBlock b, NoseInfo at, MachineProfile profile, Diagnostics out) {
        for (Motion m : b.motions()) {
            double[] box;
            Motion.Arc a = MotionKind.arc(m);
            if (a != null) {
                box = gcnc.ir.ArcGeometry.bounds(a);
            } else if (MotionKind.of(m).linear()) {
                // its start is the end of the move before, judged there
                gcnc.ir.Point to = NoseMoves.to(m);
                box = new double[] {to.x(), to.x(), to.z(), to.z()};
            } else {
                continue;
            }
            if (beyond("X", profile.x(), box[0], box[1], at, profile, out)
                    || beyond("Z", profile.z(), box[2], box[3], at, profile, out)) {
                break;
            }
        }
    }

    private static boolean beyond(String name, Axis a, double min, double max, NoseInfo at, MachineProfile profile,
                                  Diagnostics out) {
        double where = min < a.min() - 0.5 ? min : max > a.max() + 0.5 ? max : Double.NaN;
        if (Double.isNaN(where)) {
            return false;
        }
        double per = a.countsPerMm();
        out.report(at.error(Code.E179_NOSE_BEYOND_TRAVEL, name, NumberText.plain(where / per, 3),
                NumberText.plain(a.min() / per, 3), NumberText.plain(a.max() / per, 3), profile.name()));
        return true;
    }
}
