package gcnc.plan;

import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;

/**
 * Every motion its own sequence, stopped at its end: what gcnc wrote before it planned (and the
 * thesis wrote). Holds nothing back. Given the profile, a straight move longer than one VP segment
 * ({@link SegmentLimit}) is still one sequence, of equal pieces from rest to rest; without it (the
 * thesis's format) every motion is written whole.
 */
public final class ExactStop implements Planner {
    private final MachineProfile profile;
    private final SegmentLimit limit;

    /** Every motion whole (the thesis dialect). */
    public ExactStop() {
        this.profile = null;
        this.limit = null;
    }

    /** Every motion stopped at its end, a long straight move in pieces of the profile's Galil model. */
    public ExactStop(MachineProfile profile) {
        this.profile = profile;
        this.limit = SegmentLimit.of(profile);
    }

    @Override
    public void accept(CheckedBlock b, Consumer<Step> out) {
        out.accept(new Step.Before(b));
        for (int i = 0; i < b.motions().size(); i++) {
            Step.Group split = split(b, i);
            out.accept(split != null ? split : new Step.Alone(b, i));
        }
        out.accept(new Step.After(b));
    }

    /**
     * A straight move too long for one segment as one sequence of equal pieces, or null. The pieces
     * join in a straight line, so the machine keeps its speed between them; it starts and ends at
     * rest, each joint at most what it can reach from the start and still stop from by the end.
     */
    private Step.Group split(CheckedBlock b, int i) {
        if (limit == null || !(b.motions().get(i) instanceof Motion.Linear l)) {
            return null;
        }
        double length = Math.hypot(l.to().x() - l.from().x(), l.to().z() - l.from().z());
        int n = limit.parts(length);
        if (n == 1) {
            return null;
        }
        double speed = l.rapid() ? profile.rapidSpeed() : l.feed().countsPerSecond();
        double a = Math.min(profile.acceleration(), profile.deceleration());
        double usable = Math.max(0, length / n - Contouring.ROUNDING);
        List<Piece> pieces = new ArrayList<>(n);
        for (int k = 0; k < n; k++) {
            double exit = k == n - 1 ? 0
                    : Math.min(speed, Math.sqrt(2 * a * usable * Math.min(k + 1, n - 1 - k)));
            pieces.add(new Piece(b, i, speed, exit, length / n, false, List.of(), k, n));
        }
        return new Step.Group(pieces, Stop.EXACT_STOP);
    }

    @Override
    public void finish(Consumer<Step> out) {
    }

    @Override
    public boolean holding() {
        return false;
    }

    @Override
    public java.util.List<CheckedBlock> held() {
        return java.util.List.of();
    }
}
