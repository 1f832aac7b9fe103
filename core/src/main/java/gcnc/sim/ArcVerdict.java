package gcnc.sim;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.galil.ArcPlanner;
import gcnc.galil.GalilFrame;
import gcnc.galil.GalilNumbers;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;

/**
 * What {@code check} says about an arc that {@code compile} would reject: one verdict for both.
 * The galil dialect writes an arc as a CR of a whole number of counts with its angles to 4
 * decimals ({@link ArcPlanner}); for a long radius over a short chord no such arc may end on the
 * target (E202, the backend's), or the one that does may run off the programmed arc's centre or
 * middle by more than the replay allows (E308, the simulator's). Compile finds both only when it
 * runs the backend and the simulator; check runs neither, and used to pass such a program.
 *
 * <p>Here each arc is planned exactly as the backend plans it ({@link ArcPlanner#forMotion}, the
 * same code), from the whole-count position the controller is at (the arc's start rounded: every
 * sequence the galil dialect writes ends on its target's count), replayed into segments as the DMC
 * interpreter replays a CR (the same {@code Plane.cr}; ArcVerdictTest compares check's codes with
 * compile's) and compared with the program by
 * the simulator's own {@link Conformance} at the default tolerance. Same codes, same lines.
 */
public final class ArcVerdict {
    private final GalilFrame frame;
    private final Plane plane;
    private final Diagnostics out;
    private final Conformance conformance;

    public ArcVerdict(MachineProfile profile, Diagnostics out) {
        this.frame = new GalilFrame(profile);
        this.plane = new Plane(profile);
        this.out = out;
        SimOptions options = SimOptions.defaults();
        this.conformance = new Conformance((code, line, args) -> out.error(code, Span.of(line, 1), args), null,
                options.tolerance(), Simulator.threadTolerance(profile, options));
    }

    /** Every arc of a checked block. */
    public void block(CheckedBlock b) {
        for (Motion m : b.motions()) {
            if (m instanceof Motion.Arc a) {
                arc(b.line(), a);
            }
        }
    }

    private void arc(int line, Motion.Arc a) {
        long su = GalilNumbers.round(frame.u(a.from()));
        long sv = GalilNumbers.round(frame.v(a.from()));
        ArcPlanner.Written w = ArcPlanner.forMotion(frame, su, sv, a);
        if (w == null) {
            return; // a straight move to the end count: within a count of the arc
        }
        if (w.cr() == null) {
            out.error(Code.E202_ARC_NOT_REPRESENTABLE, Span.of(line, 1), GalilNumbers.round(a.radius()));
            return;
        }
        // the CR as the controller runs it: its printed angles, about the centre they imply
        double start = GalilNumbers.printedAngle(w.cr().start()); // the value the printed angle stands for,
        double sweep = GalilNumbers.printedAngle(w.cr().sweep()); // without printing it and reading it back
        List<Segment> segs = new ArrayList<>(2);
        segs.add(plane.cr(su, sv, w.cr().radius(), start, sweep, new gcnc.dmc.Instruction(
                new gcnc.dmc.Command.CircularArc(gcnc.dmc.Fixed.of(w.cr().radius()),
                        gcnc.dmc.Fixed.fourDecimals(w.cr().start()), gcnc.dmc.Fixed.fourDecimals(w.cr().sweep())),
                gcnc.dmc.Source.line(line)), new double[2]));
        if (w.cr().closing()) {
            Segment s = segs.get(0);
            segs.add(new Segment(s.toX(), s.toZ(), plane.machineX(w.tu(), w.tv()), plane.machineZ(w.tu(), w.tv()),
                    false, 0, 0, 0, 0, 0, null));
        }
        conformance.check(a, segs, line);
    }
}
