package gcnc.controller;

import java.util.Locale;

/**
 * What the virtual controller makes of its motion's events: a line of the trace for each segment done,
 * each sequence's end and each thread pass once both plane axes have settled, and the limit switch that a
 * fault trips during a segment (#LIMSWI), released when the stop it causes ends.
 */
final class MotionEvents implements VectorMotion.Events, Gearing.Events {
    private final VirtualGalil c;
    /** The controller's trace, or null. */
    private final SegmentTrace trace;
    private int passes;

    MotionEvents(VirtualGalil c, SegmentTrace trace) {
        this.c = c;
        this.trace = trace;
    }

    @Override
    public void segmentDone(int sequence, int number, VectorSegment s, int free, double t) {
        if (trace != null) {
            trace.segment(sequence, number, s, free, t);
        }
    }

    @Override
    public void sequenceEnded(int sequence, String why, double p1, double p2, double t) {
        c.limitTripped = false;
        c.event(String.format(Locale.ROOT, "%s %d at %d,%d", why, sequence, (long) p1, (long) p2), t);
    }

    /** The limit fault: the switch is active until the stop it causes ends, and #LIMSWI runs if there is one. */
    @Override
    public void limitTripped() {
        c.limitTripped = true;
        c.traceEvent("limit switch tripped");
        int line = c.program.label("LIMSWI");
        if (line >= 0) {
            c.threads[0].interrupt(line);
        }
    }

    /** A thread pass ends when both plane axes have settled (PA, BG, AM): one line of the trace. */
    @Override
    public void moveDone(int[] axes, double[] ends, double t) {
        VectorMotion mo = c.motion;
        boolean plane = false;
        for (int a : axes) {
            plane |= a == mo.axis1 || a == mo.axis2;
        }
        if (plane && mo.axis1 >= 0 && !c.gearing.moving[mo.axis1] && !c.gearing.moving[mo.axis2]) {
            passes++;
            if (trace != null) {
                trace.pass(passes, mo.position[mo.axis1], mo.position[mo.axis2], mo.free(), t);
            }
            c.event(String.format(Locale.ROOT, "pass %d at %d,%d", passes, (long) Math.rint(mo.position[mo.axis1]),
                    (long) Math.rint(mo.position[mo.axis2])), t);
        }
    }
}
