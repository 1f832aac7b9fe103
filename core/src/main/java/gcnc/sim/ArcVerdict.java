package gcnc.sim;

import gcnc.machine.Plane;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.galil.ArcPlanner;
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
 * interpreter replays a CR (the same {@code Segment.cr}; ArcVerdictTest compares check's codes with
 * compile's) and compared with the program by
 * the simulator's own {@link Conformance} at the default tolerance. Same codes, same lines.
 *
 * <p>The verdict is a function of the arc's geometry alone (its start, end, centre, radius and
 * direction: the start fixes the whole-count position, the feed and the words play no part), so
 * an arc already judged clean is not planned again: a roughing program repeats the same arcs pass
 * after pass, and planning was a sixth of a check's time (bench/HISTORY.md, issue 23). Only clean
 * verdicts are remembered, so every finding is still reported at its own line.
 */
public final class ArcVerdict {
    private final Plane plane;
    private final Diagnostics out;
    private final Conformance conformance;
    /** Set when the conformance check reports: the arc is then not remembered as clean. */
    private boolean found;
    /** The arcs judged clean, up to {@link #REMEMBERED} of them (then forgotten all at once). */
    private final java.util.Set<Shape> clean = new java.util.HashSet<>();
    private static final int REMEMBERED = 4096;

    private final gcnc.machine.ControllerLimits limits;

    public ArcVerdict(MachineProfile profile, Diagnostics out) {
        this.limits = profile.controllerLimits();
        this.plane = Plane.of(profile);
        this.out = out;
        SimOptions options = SimOptions.defaults();
        this.conformance = new Conformance((code, at, args) -> {
            found = true;
            // unplaced: the checker's Diagnostics puts it in the file of the block it checks
            out.error(code, Span.of(at.line(), 1), args);
        }, null, options.tolerance(), Simulator.threadTolerance(profile, options));
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
        Shape shape = new Shape(a);
        if (clean.contains(shape)) {
            return;
        }
        if (judge(line, a)) {
            if (clean.size() >= REMEMBERED) {
                clean.clear();
            }
            clean.add(shape);
        }
    }

    /** Plans and replays one arc; true when it is clean (nothing reported). */
    private boolean judge(int line, Motion.Arc a) {
        long su = GalilNumbers.round(plane.galil1(a.from()));
        long sv = GalilNumbers.round(plane.galil2(a.from()));
        ArcPlanner.Written w = ArcPlanner.forMotion(plane, su, sv, a);
        if (w == null) {
            return true; // a straight move to the end count: within a count of the arc
        }
        if (w.cr() == null) {
            out.error(Code.E202_ARC_NOT_REPRESENTABLE, Span.of(line, 1), GalilNumbers.round(a.radius()));
            return false;
        }
        // the controller's CR range (E224, E225): compile's limit check on the same CR, one verdict
        java.util.Optional<gcnc.machine.ControllerLimits.Violation> v = limits.arcRadius(w.cr().radius());
        if (v.isEmpty()) {
            v = limits.arc(w.cr().radius(), GalilNumbers.printedAngle(w.cr().sweep()));
        }
        if (v.isPresent()) {
            out.report(v.get().diagnostic(Span.of(line, 1)));
            return false;
        }
        // the CR as the controller runs it: its printed angles, about the centre they imply
        double start = GalilNumbers.printedAngle(w.cr().start()); // the value the printed angle stands for,
        double sweep = GalilNumbers.printedAngle(w.cr().sweep()); // without printing it and reading it back
        List<Segment> segs = new ArrayList<>(2);
        segs.add(Segment.cr(plane, su, sv, w.cr().radius(), start, sweep, new gcnc.dmc.Instruction(
                new gcnc.dmc.Command.CircularArc(gcnc.dmc.Fixed.of(w.cr().radius()),
                        gcnc.dmc.Fixed.fourDecimals(w.cr().start()), gcnc.dmc.Fixed.fourDecimals(w.cr().sweep())),
                gcnc.dmc.Source.line(line)), new double[2]));
        if (w.cr().closing()) {
            Segment s = segs.get(0);
            segs.add(new Segment(s.toX(), s.toZ(), plane.machineX(w.tu(), w.tv()), plane.machineZ(w.tu(), w.tv()),
                    false, 0, 0, 0, 0, 0, null));
        }
        found = false;
        conformance.check(a, segs, gcnc.dmc.Source.line(line));
        return !found;
    }

    /**
     * What the verdict depends on: the arc's start, end, centre, radius and direction, compared bit
     * for bit. (Equality written out rather than a record's: a record's is made at run time by a
     * bootstrap method, which a short check would pay for in start-up.)
     */
    private static final class Shape {
        private final double[] v;
        private final boolean clockwise;
        private final int hash;

        Shape(Motion.Arc a) {
            v = new double[] {a.from().x(), a.from().z(), a.to().x(), a.to().z(), a.centre().x(), a.centre().z(),
                a.radius()};
            clockwise = a.clockwise();
            int h = clockwise ? 1 : 0;
            for (double d : v) {
                long bits = Double.doubleToLongBits(d);
                h = 31 * h + (int) (bits ^ bits >>> 32);
            }
            hash = h;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Shape s && s.hash == hash && s.clockwise == clockwise && java.util.Arrays.equals(s.v, v);
        }

        @Override
        public int hashCode() {
            return hash;
        }
    }
}
