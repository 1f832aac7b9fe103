package gcnc.controller;

import gcnc.machine.GalilModel;

/**
 * The coordinated (vector) motion of coordinate system S in time: the segment buffer (511 slots), the
 * sequence origin, and the profiler that runs the segments one after the other.
 *
 * <p>Galil's rules (command reference VM, VP, CR, VE, VR, BG; docs/virtual-controller.md): a sequence's
 * origin is where the axes stood when its first segment was given, and every VP is an end point from that
 * origin; a CR starts where the previous segment ended (0 degrees along the first plane axis,
 * counter-clockwise positive). A segment runs at its {@code <o} speed, or VS, times VR, accelerating at VA
 * and decelerating at VD; {@code >p} is the speed it must have come down to at its end. After VE the
 * profiler decelerates, over as many segments as it needs, to stop on the last end point. When the buffer
 * runs dry without VE the motion "stops instantly at the last vector" and the sequence ends (an underrun).
 *
 * <p>The profile is a trapezoid per segment integrated in steps of at most one millisecond of controller
 * time; a look-ahead (backward) pass over the buffer caps each segment's end speed so that every later
 * {@code >p} and the VE stop are reachable at VD. Slot accounting: a segment frees its slot when it starts
 * executing, VE holds one until the end, so {@code _LMS = 511 - waiting segments - VE} and a sender that
 * keeps {@code sent - _CSS <= 511} never overflows (the EPICS driver's rule). The buffer, the sequence's
 * geometry and the look-ahead over the buffer are {@link SegmentBuffer}'s; this class is the profiler.
 */
final class VectorMotion {
    /** What becomes of a segment and a sequence; the trace and the program threads listen. */
    interface Events {
        void segmentDone(int sequence, int number, VectorSegment s, int free, double time);

        void sequenceEnded(int sequence, String why, double p1, double p2, double time);

        /** The limit fault has tripped during a segment (the controller decides what follows). */
        void limitTripped();
    }

    static final double STEP = 0.001;

    private final SegmentBuffer buffer;
    private final Events events;
    /** The two plane axes (channel indices), -1 before VM. */
    int axis1 = -1;
    int axis2 = -1;
    /** Commanded positions of every axis (counts). */
    final double[] position;
    double vs = 25_000;
    double va = 256_000;
    double vd = 256_000;
    double vr = 1;

    private VectorSegment current;
    private double s;
    private double v;
    private boolean running;
    private int css;
    /**
     * The trip point of the last {@code AV} of the running sequence, counts of path from its start (0
     * at BGS): AV measures "from the start of a coordinated move sequence or from the last AV command"
     * (command reference AV), so the next one trips n counts past this.
     */
    private double avFrom;
    /** Whether the last sequence ran to its end (VE reached), not stopped, aborted or run dry. */
    private boolean ranToEnd;
    private int sequence;
    /** Nonzero while a stop decelerates the sequence: the stop code it will leave (4 ST, 2 limit). */
    private int stopping;
    int stopCode = 0;
    /** Segments executed since power-up, for the faults that name a segment. */
    private long executed;
    long stallAfter = -1;
    long limitAt = -1;
    private boolean stalled;
    /** End-speed caps of current and waiting, in deque order; recomputed when dirty. */
    private double[] caps = new double[0];
    private boolean dirty = true;

    VectorMotion(GalilModel model, Events events) {
        this.buffer = new SegmentBuffer(model);
        int axes = model.axes();
        this.events = events;
        this.position = new double[Math.max(axes, 2)];
    }

    /** Arms the segment faults of {@code faults} that name a segment ({@code stall}, {@code limit-at}). */
    void arm(java.util.List<InjectedFault> faults) {
        for (InjectedFault f : faults) {
            if (f.kind() == InjectedFault.Kind.STALL) {
                stallAfter = f.n();
            } else if (f.kind() == InjectedFault.Kind.LIMIT_AT) {
                limitAt = f.n();
            }
        }
    }

    boolean running() {
        return running;
    }

    /** {@code _LMS}: free slots. */
    int free() {
        return buffer.free();
    }

    /**
     * {@code _CSS}: the segment counter of the sequence, from zero: the segments it has finished, so
     * that it reads 0 during the first segment and 1 during the second (the DMC-40x0 User Manual's
     * example, p.86: "during the first segment ... _CS ... will be zero ... at the second segment ...
     * _CS equals 1"; the same in the DMC-2x00 and DMC-13X8 manuals). After the sequence ran to its end
     * it reads the number of its segments (every one finished); after a stop, the number of the
     * segment it stopped in, counted from zero. What it reads after the end the manuals do not say:
     * this is the reading of a counter of the segments processed (EPICS's {@code segprocessed}), and a
     * sender that clamps to the sequence's last segment reads either answer the same
     * (docs/virtual-controller.md).
     */
    int css() {
        return css;
    }

    double corner(int axis) {
        return axis == axis1 ? buffer.corner1() : axis == axis2 ? buffer.corner2() : position[axis];
    }

    /** Path speed now (counts/s), {@code _VPS}-like; used by the status of a test. */
    double speed() {
        return v;
    }

    /** Room for a segment: the plane set (VM), then the buffer's ({@link SegmentBuffer#room}). */
    private void room() throws GalilException {
        if (axis1 < 0) {
            throw new GalilException(Tc.S_OPERAND);
        }
        buffer.room();
    }

    /** {@code VP a,b <o >p}: o and p NaN when not given. */
    void vp(double a, double b, double o, double p) throws GalilException {
        room();
        buffer.vp(a, b, o, p, running, position[axis1], position[axis2]);
        dirty = true;
    }

    /** {@code CR r,start,sweep <o >p}, angles in degrees. */
    void cr(double r, double startDeg, double sweepDeg, double o, double p) throws GalilException {
        room();
        buffer.cr(r, startDeg, sweepDeg, o, p, running, position[axis1], position[axis2]);
        dirty = true;
    }

    /** {@code VE}: the end of the sequence; the profiler will stop on the last end point. */
    void ve() throws GalilException {
        if (axis1 < 0) {
            throw new GalilException(Tc.S_OPERAND);
        }
        if (buffer.ve(running)) {
            dirty = true;
        }
    }

    /** {@code BGS}. */
    void begin() throws GalilException {
        if (running) {
            throw new GalilException(Tc.BEGIN_WHILE_RUNNING);
        }
        if (buffer.isEmpty()) {
            throw new GalilException(Tc.NO_SEQUENCE);
        }
        running = true;
        stopping = 0;
        stalled = false;
        stopCode = 100;
        sequence++;
        css = 0;
        v = 0;
        current = null;
        doneLength = 0;
        avFrom = 0;
        ranToEnd = false;
    }

    /**
     * {@code AV n}: the trip point it waits for, counts of path from the sequence's start: the last AV's
     * trip point (the start for the first) plus n.
     */
    double afterVector(long n) {
        avFrom += n;
        return avFrom;
    }

    /**
     * Whether the last sequence ran to its end short of {@code trip}: an AV that will never trip. The
     * command reference does not say what the controller does then (AD and AR clear when "the motion
     * profiling on the axis is complete"; AV's entry has no such condition); the virtual controller
     * takes the reading a wrong program cannot pass: the thread waits there for ever.
     */
    boolean endedShortOf(double trip) {
        return !running && ranToEnd && doneLength < trip;
    }

    /** Whether an AV thread waits in vain and the sequence is over without reaching its end (a stop, an abort). */
    boolean cutShort() {
        return !running && !ranToEnd;
    }

    /** The path run so far in the sequence, counts: for {@code AV} (after vector distance). */
    double travelled() {
        return doneLength + (current == null ? 0 : s);
    }

    /** The length of the segments of the running sequence already finished. */
    private double doneLength;

    /** {@code CS S}: clears the buffer of a sequence that is not running. */
    void clear() throws GalilException {
        if (running) {
            throw new GalilException(Tc.WHILE_RUNNING);
        }
        buffer.clear();
        css = 0;
        dirty = true;
    }

    /** {@code ST S}: decelerate at VD and end the sequence where it stops. */
    void stop(int code) {
        if (running && stopping == 0) {
            stopping = code;
        }
    }

    /** {@code AB}, {@code MO}: the motion ends here and now. */
    void abort(int code, double time) {
        if (running) {
            v = 0;
            end(code, "abort", time);
        }
    }

    void changed() {
        dirty = true;
    }

    /** Runs {@code dt} seconds of controller time from {@code time}. */
    void advance(double dt, double time) {
        double t = time;
        double left = dt;
        while (running && left > 1e-12) {
            double h = Math.min(left, STEP);
            // a segment that ends within the step hands the rest of the step to the next one
            double used = h - step(h, t);
            t += used;
            left -= used;
        }
    }

    /** One step of at most {@code h} seconds; returns the part of it left unused when a segment ended in it. */
    private double step(double h, double time) {
        if (current == null && !next(time)) {
            return 0;
        }
        if (stalled) {
            if (stopping != 0) {
                end(stopping, "stop", time);
            }
            return 0;
        }
        if (dirty) {
            capsFor();
        }
        double cruise = stopping != 0 ? 0 : (Double.isNaN(current.o()) ? vs : current.o()) * vr;
        double remaining = current.length() - s;
        // the braking curve read where this step will end at the present speed, so that the profile comes
        // down to a segment's end speed on time instead of a step late
        double target = Math.min(cruise, Math.sqrt(caps[0] * caps[0] + 2 * vd * Math.max(0, remaining - v * h)));
        if (stopping != 0) {
            target = 0;
        }
        double next = v < target ? Math.min(target, v + va * h) : Math.max(target, v - vd * h);
        double ds = (v + next) / 2 * h;
        v = next;
        if (limitAt > 0 && current.global() == limitAt && stopping == 0 && s + ds >= current.length() / 2) {
            limitAt = -1;
            stopping = 2;
            events.limitTripped();
        }
        if (s + ds >= current.length()) {
            double average = ds / h;
            double used = average > 0 ? Math.min(h, remaining / average) : h;
            finishSegment(time + used);
            return h - used;
        }
        s += ds;
        position[axis1] = current.at1(s);
        position[axis2] = current.at2(s);
        if (stopping != 0 && v == 0) {
            end(stopping, "stop", time + h);
        }
        return 0;
    }

    /** Takes the next segment from the buffer; false when the sequence ended (VE reached or underrun). */
    private boolean next(double time) {
        VectorSegment seg = buffer.poll();
        if (seg == null) {
            end(101, buffer.ended() ? "end" : "underrun", time);
            return false;
        }
        executed++;
        current = new VectorSegment(seg.number(), seg.arc(), seg.from1(), seg.from2(), seg.end1(), seg.end2(),
                seg.centre1(), seg.centre2(), seg.radius(), seg.startRad(), seg.sweepRad(), seg.length(), seg.o(),
                seg.p(), executed);
        css = seg.number() - 1; // from zero: the segments finished before this one
        s = 0;
        dirty = true;
        return true;
    }

    private void finishSegment(double time) {
        VectorSegment done = current;
        doneLength += done.length();
        position[axis1] = done.end1();
        position[axis2] = done.end2();
        buffer.reached(done.end1(), done.end2());
        current = null;
        events.segmentDone(sequence, done.number(), done, free(), time);
        if (stopping != 0 && v == 0) {
            end(stopping, "stop", time);
            return;
        }
        if (stallAfter > 0 && done.global() == stallAfter) {
            stallAfter = -1;
            stalled = true;
            v = 0;
            current = done; // the profiler holds here: nothing more leaves the buffer
            s = done.length();
            return;
        }
        if (buffer.isEmpty() && !buffer.ended()) {
            // an underrun: no controlled deceleration, the axes stop on the last vector
            v = 0;
        }
        if (buffer.isEmpty()) {
            if (stopping == 0) {
                css = done.number(); // every segment finished: the counter reads how many
            }
            end(stopping != 0 ? stopping : 101, stopping != 0 ? "stop" : buffer.ended() ? "end" : "underrun", time);
        }
    }

    private void end(int code, String why, double time) {
        running = false;
        ranToEnd = why.equals("end");
        stopping = 0;
        stalled = false;
        stopCode = code;
        v = 0;
        current = null;
        buffer.clear();
        position[axis1] = Math.rint(position[axis1]);
        position[axis2] = Math.rint(position[axis2]);
        dirty = true;
        events.sequenceEnded(sequence, why, position[axis1], position[axis2], time);
    }

    /** The end-speed cap of the current segment and of every waiting one, from the last back (look-ahead). */
    private void capsFor() {
        caps = buffer.endSpeedCaps(current, vr, vd, caps);
        dirty = false;
    }
}
