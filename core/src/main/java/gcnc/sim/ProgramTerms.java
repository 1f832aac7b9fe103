package gcnc.sim;

import gcnc.ir.ProgramFrame;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * What a run measures for a person rather than for the machine: the envelope in the program's
 * own terms ({@link ProgramEnvelope}: each move in its block's frame), the work zero of the first
 * cut, and each station's use (first and last line, time). Fed by {@link MotionChecks} with every
 * sequence's box; a few multiplications a segment, so a long program pays nothing for it.
 */
final class ProgramTerms {
    private final double kx;
    private final double kz;
    private final boolean diameter;
    private ProgramFrame frame;
    /** Millimetres per program unit of the first move's block (1 or 25.4), NaN until a move with a frame. */
    private double unitMm = Double.NaN;
    private double xMin = Double.POSITIVE_INFINITY;
    private double xMax = Double.NEGATIVE_INFINITY;
    private double zMin = Double.POSITIVE_INFINITY;
    private double zMax = Double.NEGATIVE_INFINITY;
    /** The same box over the feed moves alone (the part, not the rapids and home moves): {xMin, xMax, zMin, zMax}. */
    private final double[] feeds = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY,
        Double.NEGATIVE_INFINITY};
    /** The work zero (machine counts {x, z}) of the first feed move, else of the first move. */
    private double[] firstCut;
    private double[] firstMove;
    private double maxRpm = Double.NaN;
    /** Station to {first line, last line}, and to seconds, in the order of first use. */
    private final Map<Integer, int[]> lines = new LinkedHashMap<>();
    private final Map<Integer, Double> seconds = new LinkedHashMap<>();

    ProgramTerms(MachineProfile profile) {
        this.kx = profile.x().countsPerMm();
        this.kz = profile.z().countsPerMm();
        this.diameter = profile.diameterX();
    }

    /** The block being replayed (null: not known, its moves count in the machine frame only). */
    void frame(ProgramFrame f) {
        frame = f;
    }

    /** One segment's box {xMin, xMax, zMin, zMax}, machine counts, of a move by {@code rapid}. */
    void box(double[] box, boolean rapid) {
        if (frame == null) {
            return;
        }
        if (Double.isNaN(unitMm)) {
            // the program's units are its first move's: G21 1 mm, G20 25.4 mm a unit
            unitMm = frame.perZ() / kz;
        }
        if (firstCut == null && !rapid) {
            firstCut = new double[] {frame.origin().x(), frame.origin().z()};
        }
        if (firstMove == null) {
            firstMove = new double[] {frame.origin().x(), frame.origin().z()};
        }
        double perX = kx * unitMm / (diameter ? 2 : 1);
        double perZ = kz * unitMm;
        double x0 = (box[0] - frame.origin().x()) / perX;
        double x1 = (box[1] - frame.origin().x()) / perX;
        double z0 = (box[2] - frame.origin().z()) / perZ;
        double z1 = (box[3] - frame.origin().z()) / perZ;
        xMin = Math.min(xMin, x0);
        xMax = Math.max(xMax, x1);
        zMin = Math.min(zMin, z0);
        zMax = Math.max(zMax, z1);
        if (!rapid) {
            feeds[0] = Math.min(feeds[0], x0);
            feeds[1] = Math.max(feeds[1], x1);
            feeds[2] = Math.min(feeds[2], z0);
            feeds[3] = Math.max(feeds[3], z1);
        }
    }

    /** A sequence of station {@code tool} from G-code line {@code line}, taking {@code s} seconds. */
    void move(int tool, int line, double s) {
        int[] l = lines.get(tool);
        if (l == null) {
            lines.put(tool, new int[] {line, line});
        } else {
            l[0] = Math.min(l[0], line);
            l[1] = Math.max(l[1], line);
        }
        time(tool, s);
    }

    /** Time spent by station {@code tool} without a move (a dwell). */
    void time(int tool, double s) {
        seconds.merge(tool, s, Double::sum);
    }

    /** The spindle was set to {@code rpm}. */
    void spindle(double rpm) {
        if (!(rpm <= maxRpm)) {
            maxRpm = Double.isNaN(maxRpm) ? Math.abs(rpm) : Math.max(maxRpm, Math.abs(rpm));
        }
    }

    /**
     * The envelope in program terms, null when no move had a program frame. The machine stands on
     * whole counts, so may be replayed at X-1.5992: each value is given as the program would
     * write it, the shortest decimal (at most 3 in mm, 4 in inches) within half a count of it.
     */
    ProgramEnvelope envelope() {
        return envelope(xMin, xMax, zMin, zMax);
    }

    /** The envelope of the feed moves alone (where the part is cut), in program terms; null when no move fed. */
    ProgramEnvelope feedEnvelope() {
        return envelope(feeds[0], feeds[1], feeds[2], feeds[3]);
    }

    private ProgramEnvelope envelope(double xMin, double xMax, double zMin, double zMax) {
        if (Double.isNaN(unitMm) || xMin > xMax) {
            return null;
        }
        boolean inch = unitMm > 2;
        double halfX = 0.5 / (kx * unitMm / (diameter ? 2 : 1));
        double halfZ = 0.5 / (kz * unitMm);
        int places = inch ? 4 : 3;
        return new ProgramEnvelope(inch ? Units.INCH : Units.MM, diameter, written(xMin, halfX, places),
                written(xMax, halfX, places), written(zMin, halfZ, places), written(zMax, halfZ, places));
    }

    /** The shortest decimal of at most {@code places} places within {@code half} of {@code v}, else v. */
    static double written(double v, double half, int places) {
        for (int p = 0; p <= places; p++) {
            double r = java.math.BigDecimal.valueOf(v).setScale(p, java.math.RoundingMode.HALF_UP).doubleValue();
            if (Math.abs(r - v) <= half) {
                return r;
            }
        }
        return v;
    }

    SetupFacts facts(SimMachine machine, StockSize blank) {
        List<ToolUse> tools = new ArrayList<>();
        for (Map.Entry<Integer, int[]> e : lines.entrySet()) {
            int n = e.getKey();
            SimMachine.ToolShape t = machine.tool(n);
            tools.add(new ToolUse(n, t.kind(), t.name(), n != 0 && machine.described(n), e.getValue()[0],
                    e.getValue()[1], seconds.getOrDefault(n, 0.0)));
        }
        double[] zero = firstCut != null ? firstCut : firstMove;
        return new SetupFacts(java.util.Optional.ofNullable(blank), machine.chuckFace() / kz,
                zero == null ? Double.NaN : zero[0] / kx, zero == null ? Double.NaN : zero[1] / kz, maxRpm, tools);
    }
}
