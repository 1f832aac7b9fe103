package gcnc.check.geom;

import gcnc.check.BlockDraft;
import gcnc.check.ModalState;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.ir.Letter;
import gcnc.ir.Point;
import gcnc.ir.Word;
import gcnc.machine.Axis;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;

/**
 * Programmed coordinates to machine counts: units of the whole block, X/U as diameters when the
 * profile says so, G90/G91 (X/Z absolute or incremental, U/W always incremental), and the work
 * coordinate origin = work offset (G54-G59) + tool offset (T: geometry + wear) + the G50/G92 shift, all taken
 * from the block's own new state, so they apply to the block they appear in.
 */
public final class Coordinates {
    private final MachineProfile p;
    /** G54..G59 and tool offsets 0..99 as arrays: no map look-up per block. */
    private final Point[] work = new Point[100];
    private final Point[] tool = new Point[100];

    public Coordinates(MachineProfile p) {
        this.p = p;
        for (int i = 0; i < 100; i++) {
            work[i] = p.workOffset(i).orElse(Point.ORIGIN);
            tool[i] = i == 0 ? Point.ORIGIN : p.appliedOffset(i).orElse(Point.ORIGIN); // geometry + wear
        }
    }

    /** Counts per programmed unit of X and U (half when X is a diameter). */
    public double perX(Units u) {
        return p.x().countsPer(u) / (p.diameterX() ? 2 : 1);
    }

    /** Counts per programmed unit of a radius along X (I, R: always a radius). */
    public double perRadius(Units u) {
        return p.x().countsPer(u);
    }

    public double perZ(Units u) {
        return p.z().countsPer(u);
    }

    /** Work offset + the external offset + tool offset, machine counts (no G50/G92 shift). */
    public Point offsets(ModalState.Next s) {
        Point w = work[s.workOffset];
        Point t = tool[s.toolOffset];
        return new Point(w.x() + t.x() + external.x(), w.z() + t.z() + external.z());
    }

    /**
     * The external (common) work offset that every G54-G59 adds, counts: zero until a program
     * writes it (G10 L2 P0); a profile gives the work offsets with it included.
     */
    private Point external = Point.ORIGIN;

    /** Work offset {@code index} (54..59; 0 the external offset), machine counts. */
    public Point work(int index) {
        return index == 0 ? external : work[index];
    }

    /** Writes work offset {@code index} (54..59; 0 the external offset) for the blocks after (G10 L2). */
    public void setWork(int index, Point at) {
        if (index == 0) {
            external = at;
        } else {
            work[index] = at;
        }
        lastShift = null; // the origin kept for the last block is stale
    }

    /** Takes the work offsets another checker's program has written so far (the other block delete position). */
    public void takeWork(Coordinates from) {
        System.arraycopy(from.work, 0, work, 0, work.length);
        external = from.external;
        lastShift = null;
    }

    /**
     * Where the block's work coordinate zero is, machine counts. Asked several times for every
     * block and nearly always the same: the last answer is kept (the offset tables change only
     * with G10 L2, which forgets it, and the shift is compared by value).
     */
    public Point origin(ModalState.Next s) {
        Point shift = s.shift;
        if (s.workOffset != lastWork || s.toolOffset != lastTool || lastShift == null
                || shift.x() != lastShift.x() || shift.z() != lastShift.z()) {
            Point o = offsets(s);
            lastOrigin = o.plus(s.shift.x(), s.shift.z());
            lastWork = s.workOffset;
            lastTool = s.toolOffset;
            lastShift = shift;
        }
        return lastOrigin;
    }

    private int lastWork = -1;
    private int lastTool = -1;
    private Point lastShift;
    private Point lastOrigin;

    /**
     * The end of the block's X/Z/U/W words: absolute words from the work origin (or from
     * {@code base} under G91), U/W from {@code base}. Axes without a word stay at {@code base}.
     */
    public Point target(BlockDraft d, Point base) {
        Point o = origin(d.next);
        Units u = d.units;
        double x = base.x();
        double z = base.z();
        if (d.has(Letter.X)) {
            double v = d.value(Letter.X) * perX(u);
            x = d.next.incremental ? base.x() + v : o.x() + v;
        } else if (d.has(Letter.U)) {
            x = base.x() + d.value(Letter.U) * perX(u);
        }
        if (d.has(Letter.Z)) {
            double v = d.value(Letter.Z) * perZ(u);
            z = d.next.incremental ? base.z() + v : o.z() + v;
        } else if (d.has(Letter.W)) {
            z = base.z() + d.value(Letter.W) * perZ(u);
        }
        return new Point(x, z);
    }

    /**
     * Reports E015 and returns true when {@code end} is outside the machine's travel, at the X/U
     * or Z/W word that took it there. The message gives the travel in the block's own terms (see
     * {@link #programTravel}), so the machinist reads the limit beside the word that broke it:
     * {@code Z-170. is beyond the Z travel -150..200 of machine generic}. {@code zero} is where the
     * block's coordinates start: the work origin, or machine zero for G53.
     */
    public boolean beyondTravel(BlockDraft d, Point end, Point zero, Diagnostics out) {
        boolean x = !p.x().inTravel(end.x());
        if (!x && p.z().inTravel(end.z())) {
            return false;
        }
        Word w = x ? axisWord(d, Letter.X, Letter.U) : axisWord(d, Letter.Z, Letter.W);
        double[] travel = programTravel(x, zero, d.units);
        d.fail(out, Code.E015_OUT_OF_RANGE, w.span(), w, x ? "X" : "Z", NumberText.plain(travel[0]),
                NumberText.plain(travel[1]), p.name());
        return true;
    }

    /**
     * The travel of X ({@code x}) or Z as the block's words read it: the machine's limits (counts)
     * measured from {@code zero} and divided by the counts per programmed unit, so X is a diameter
     * where the machine programs diameters, in the block's units. Rounded inward to the last digit
     * a word of those units carries (0.001 mm, 0.0001 in), so that every value shown can be reached.
     */
    public double[] programTravel(boolean x, Point zero, Units u) {
        Axis a = x ? p.x() : p.z();
        double per = x ? perX(u) : perZ(u);
        double from = x ? zero.x() : zero.z();
        double lo = (a.min() - from) / per;
        double hi = (a.max() - from) / per;
        double scale = u == Units.INCH ? 1e4 : 1e3;
        // the 1e-6 keeps a limit that is a whole number of digits from being pushed off it by rounding noise
        return new double[] {Math.ceil(Math.min(lo, hi) * scale - 1e-6) / scale,
            Math.floor(Math.max(lo, hi) * scale + 1e-6) / scale};
    }

    /** Whether {@code end} is inside the travel of both axes. */
    public boolean inTravel(Point end) {
        return p.x().inTravel(end.x()) && p.z().inTravel(end.z());
    }

    private static Word axisWord(BlockDraft d, Letter a, Letter b) {
        Word w = d.word(a);
        if (w == null) {
            w = d.word(b);
        }
        return w != null ? w : d.block.words().get(d.block.words().size() - 1);
    }

    /** The part diameter at a machine point, mm (G96): twice its distance from work X zero. */
    public double diameterMm(Point machine, ModalState.Next s) {
        return 2 * Math.abs(machine.x() - origin(s).x()) / p.x().countsPerMm();
    }
}
