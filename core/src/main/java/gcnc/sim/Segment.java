package gcnc.sim;

/**
 * One replayed vector segment in the machine frame (counts; x = machine X, not the radius), with
 * the speeds its VP/CR gave it ({@code speed} from {@code <o}, {@code end} from {@code >p}, counts/s;
 * NaN where it gave none).
 * A line has {@code arc == false}; an arc carries its centre, radius and signed sweep in the
 * machine drawing (z right, x up; counter-clockwise positive), as the Galil CR made it.
 */
record Segment(double fromX, double fromZ, double toX, double toZ, boolean arc, double centreX, double centreZ,
               double radius, double startDeg, double sweepDeg, gcnc.dmc.Instruction instruction, double speed, double end) {
    /** A segment with no speeds of its own: the sequence's VS, and no slowing at its end. */
    Segment(double fromX, double fromZ, double toX, double toZ, boolean arc, double centreX, double centreZ,
            double radius, double startDeg, double sweepDeg, gcnc.dmc.Instruction instruction) {
        this(fromX, fromZ, toX, toZ, arc, centreX, centreZ, radius, startDeg, sweepDeg, instruction, Double.NaN, Double.NaN);
    }

    /**
     * The arc a Galil {@code CR r,start,sweep} draws from the Galil-plane position (p1, p2), as the
     * controller derives it: the centre from the start angle, the end from start + sweep. One
     * place for the replay ({@code ReplayController}) and for check's prediction of it
     * ({@code ArcVerdict}), so that the two cannot differ. {@code end} receives the end in the
     * Galil plane (first, second channel).
     */
    static Segment cr(gcnc.machine.Plane plane, double p1, double p2, double r, double startDeg, double sweepDeg,
                      gcnc.dmc.Instruction instruction, double[] end) {
        double[] g = gcnc.dmc.Command.CircularArc.geometry(p1, p2, r, startDeg, sweepDeg);
        double c1 = g[0];
        double c2 = g[1];
        end[0] = g[2];
        end[1] = g[3];
        double fx = plane.machineX(p1, p2);
        double fz = plane.machineZ(p1, p2);
        double cx = plane.machineX(c1, c2);
        double cz = plane.machineZ(c1, c2);
        double from = Math.toDegrees(Math.atan2(fx - cx, fz - cz));
        return new Segment(fx, fz, plane.machineX(end[0], end[1]), plane.machineZ(end[0], end[1]), true, cx, cz, r, from,
                sweepDeg * plane.handedness(), instruction);
    }

    /** The same segment with the speeds its command gives ({@code <o >p}; NaN where none). */
    Segment withSpeeds(double speed, double end) {
        return new Segment(fromX, fromZ, toX, toZ, arc, centreX, centreZ, radius, startDeg, sweepDeg, instruction, speed, end);
    }

    /** Where it came from: the G-code block and motion it carries out (null: a segment made by hand). */
    gcnc.dmc.Source source() {
        return instruction == null ? null : instruction.source();
    }

    /** The DMC line that made it, for findings (printed only when one is made). */
    String text() {
        return instruction == null ? "" : instruction.text();
    }

    /** Point at fraction t of the way along (arcs by angle). Returns {x, z}. */
    double[] at(double t) {
        if (!arc) {
            return new double[] {fromX + (toX - fromX) * t, fromZ + (toZ - fromZ) * t};
        }
        double a = Math.toRadians(startDeg + sweepDeg * t);
        return new double[] {centreX + radius * Math.sin(a), centreZ + radius * Math.cos(a)};
    }

    double length() {
        return arc ? Math.abs(Math.toRadians(sweepDeg)) * radius : Geometry.length(toX - fromX, toZ - fromZ);
    }

    /** How many straight pieces approximate it within half a count (1 for a line). */
    int pieces() {
        if (!arc || radius < 1) {
            return 1;
        }
        double step = Math.toDegrees(2 * Math.acos(Math.max(-1, 1 - 0.5 / radius)));
        return (int) Math.max(1, Math.min(256, Math.ceil(Math.abs(sweepDeg) / Math.max(step, 1e-3))));
    }
}
