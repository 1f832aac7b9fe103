package gcnc.controller;

import gcnc.machine.GalilModel;
import java.util.ArrayDeque;
import java.util.Iterator;

/**
 * The segment buffer of coordinate system S ({@link VectorMotion}): the segments given and not yet
 * executing (511 slots, the model's), the slot VE holds until the end, and the geometry of a sequence
 * as its segments are given: its origin (where the axes stood when its first segment was given; every
 * VP is an end point from it), the cursor where the next segment starts (a CR starts where the previous
 * segment ended), the path given so far (TC 31 past {@link #MAX_SEQUENCE}) and the last corner reached
 * ({@code _VPa}). It checks VP and CR against the model's ranges and holds the look-ahead over its
 * segments ({@link #endSpeedCaps}).
 */
final class SegmentBuffer {
    /** TC 31 "Total move distance in a sequence > 2 billion" (the table's sequence_max is LI's 2^30, stricter). */
    static final double MAX_SEQUENCE = 2_000_000_000;

    private final int slots;
    /** The model's ranges (tables/galil_models.csv): segment length, radius, arc, segment speeds. */
    private final GalilModel.Range segment;
    private final GalilModel.Range radius;
    private final GalilModel.Range arc;
    private final GalilModel.Range speed;

    private final ArrayDeque<VectorSegment> waiting = new ArrayDeque<>();
    private boolean ve;
    private int given;
    private double pathTotal;
    private double origin1;
    private double origin2;
    private double cursor1;
    private double cursor2;
    private double corner1;
    private double corner2;

    SegmentBuffer(GalilModel model) {
        this.slots = (int) model.range(GalilModel.Limit.BUFFER_SEGMENTS).max();
        this.segment = model.range(GalilModel.Limit.SEGMENT_LENGTH);
        this.radius = model.range(GalilModel.Limit.ARC_RADIUS);
        this.arc = model.range(GalilModel.Limit.ARC_LENGTH);
        this.speed = model.range(GalilModel.Limit.SEGMENT_SPEED);
    }

    /** {@code _LMS}: free slots. */
    int free() {
        return slots - waiting.size() - (ve ? 1 : 0);
    }

    /** Whether VE has been given for the sequence. */
    boolean ended() {
        return ve;
    }

    boolean isEmpty() {
        return waiting.isEmpty();
    }

    /** The next segment to execute, taken off the buffer (its slot freed); null when there is none. */
    VectorSegment poll() {
        return waiting.poll();
    }

    /** {@code _VPa} of the first (second) plane axis: the last corner reached, whole counts. */
    double corner1() {
        return corner1;
    }

    double corner2() {
        return corner2;
    }

    /** A segment has ended at this corner. */
    void reached(double end1, double end2) {
        corner1 = Math.rint(end1);
        corner2 = Math.rint(end2);
    }

    /** A new sequence takes its origin from where the axes stand ({@code at1}, {@code at2}). */
    private void startIfNeeded(boolean running, double at1, double at2) {
        if (!running && waiting.isEmpty() && given == 0) {
            origin1 = at1;
            origin2 = at2;
            cursor1 = origin1;
            cursor2 = origin2;
            pathTotal = 0;
            corner1 = origin1;
            corner2 = origin2;
        }
    }

    /** Room for a segment: not after VE (TC 5), not in a full buffer. */
    void room() throws GalilException {
        if (ve) {
            throw new GalilException(Tc.WHILE_RUNNING);
        }
        if (free() <= 0) {
            throw new GalilException(Tc.BUFFER_FULL);
        }
    }

    /** {@code VP a,b <o >p}, the axes standing at {@code at1}, {@code at2}: o and p NaN when not given. */
    void vp(double a, double b, double o, double p, boolean running, double at1, double at2) throws GalilException {
        speeds(o, p);
        startIfNeeded(running, at1, at2);
        double e1 = origin1 + a;
        double e2 = origin2 + b;
        // COMALL VP: "The length of each vector segment must be limited to 8,388,607": the length, not each
        // axis's part of it (once each axis was held to it, and VP 6000000,6000000 ran: the DMC corpus's
        // segment-too-long)
        double length = Math.hypot(e1 - cursor1, e2 - cursor2);
        if (length > segment.max()) {
            throw new GalilException(Tc.RANGE);
        }
        if (length == 0) {
            throw new GalilException(Tc.SEGMENT_TOO_SHORT);
        }
        add(new VectorSegment(given + 1, false, cursor1, cursor2, e1, e2, 0, 0, 0, 0, 0, length, o, p, 0), e1, e2);
    }

    /** {@code CR r,start,sweep <o >p}, angles in degrees. */
    void cr(double r, double startDeg, double sweepDeg, double o, double p, boolean running, double at1, double at2)
            throws GalilException {
        speeds(o, p);
        if (!radius.holds(r, false) || Math.abs(startDeg) > 32000 || Math.abs(sweepDeg) > 32000
                || !arc.holds(r * Math.abs(sweepDeg), true)) {
            throw new GalilException(Tc.RANGE);
        }
        if (sweepDeg == 0) {
            throw new GalilException(Tc.SEGMENT_TOO_SHORT);
        }
        startIfNeeded(running, at1, at2);
        // the simulator's own arithmetic for a CR (gcnc.dmc's), so that the two end every arc on the same
        // double and the trace compares count for count
        double[] g = gcnc.dmc.Command.CircularArc.geometry(cursor1, cursor2, r, startDeg, sweepDeg);
        double c1 = g[0];
        double c2 = g[1];
        double e1 = g[2];
        double e2 = g[3];
        double th = Math.toRadians(startDeg);
        double sweep = Math.toRadians(sweepDeg);
        add(new VectorSegment(given + 1, true, cursor1, cursor2, e1, e2, c1, c2, r, th, sweep, Math.abs(sweep) * r, o, p, 0),
                e1, e2);
    }

    private void speeds(double o, double p) throws GalilException {
        if (!Double.isNaN(o) && !speed.holds(o, false) || !Double.isNaN(p) && (p < 0 || p > speed.max())) {
            throw new GalilException(Tc.RANGE);
        }
    }

    private void add(VectorSegment seg, double e1, double e2) throws GalilException {
        if (pathTotal + seg.length() > MAX_SEQUENCE) {
            throw new GalilException(Tc.SEQUENCE_TOO_LONG);
        }
        pathTotal += seg.length();
        given++;
        waiting.add(seg);
        cursor1 = e1;
        cursor2 = e2;
    }

    /** {@code VE} (the plane set): whether it changed the buffer; a VE with nothing to end is accepted, no effect. */
    boolean ve(boolean running) throws GalilException {
        if (given == 0 && !running) {
            return false; // nothing to end: accepted, no effect
        }
        if (!ve) {
            if (free() <= 0) {
                throw new GalilException(Tc.BUFFER_FULL);
            }
            ve = true;
            return true;
        }
        return false;
    }

    /** Empties the buffer: {@code CS S}, and the end of a sequence. */
    void clear() {
        waiting.clear();
        ve = false;
        given = 0;
    }

    /**
     * The end-speed cap of {@code current} and of every waiting segment, from the last back (the look-ahead):
     * each so that every later {@code >p} (times VR) and the VE stop are reachable at VD. Into {@code caps},
     * in the buffer's order after {@code current}, or a larger array that it returns.
     */
    double[] endSpeedCaps(VectorSegment current, double vr, double vd, double[] caps) {
        int n = waiting.size() + 1;
        if (caps.length < n) {
            caps = new double[Math.max(n, 2 * caps.length)];
        }
        VectorSegment[] order = new VectorSegment[n];
        order[0] = current;
        Iterator<VectorSegment> it = waiting.iterator();
        for (int i = 1; i < n; i++) {
            order[i] = it.next();
        }
        double after = ve ? 0 : Double.POSITIVE_INFINITY;
        for (int i = n - 1; i >= 0; i--) {
            double own = Double.isNaN(order[i].p()) ? Double.POSITIVE_INFINITY : order[i].p() * vr;
            caps[i] = Math.min(own, after);
            after = Math.sqrt(caps[i] * caps[i] + 2 * vd * order[i].length());
        }
        return caps;
    }
}
