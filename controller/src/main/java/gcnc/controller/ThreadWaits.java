package gcnc.controller;

import java.util.List;
import java.util.Locale;
import java.util.function.BooleanSupplier;

/**
 * The trippoints of a program thread: what {@link ProgramThread#waitingFor} waits on after {@code AM},
 * {@code MC}, {@code AV}, {@code MF}/{@code MR}, {@code WT} and {@code AI}, read off the controller at each
 * step of its clock. The commands ({@link DmcCommands}, {@link OwnCommands}) check that they run in a
 * thread first.
 */
final class ThreadWaits {
    private ThreadWaits() {
    }

    /** {@code AM S}, {@code MC}: until the vector sequence no longer runs. */
    static BooleanSupplier sequenceStill(VectorMotion mo) {
        return () -> !mo.running();
    }

    /** {@code AM XY}: until these axes' moves are complete (the vector sequence's too for its axes). */
    static BooleanSupplier axesStill(VirtualGalil c, List<Integer> axes) {
        VectorMotion mo = c.motion;
        Gearing g = c.gearing;
        return () -> {
            for (int a : axes) {
                if (g.moving[a] || mo.running() && (a == mo.axis1 || a == mo.axis2)) {
                    return false;
                }
            }
            return true;
        };
    }

    /**
     * {@code AV n}: until the sequence has run n counts past the last AV's trip point (past its start for
     * the first: command reference AV, "measured from the start of a coordinated move sequence or from the
     * last AV command"), or was cut short (a stop, an abort). A sequence that ran to its end short of the
     * trip point never trips it: the thread waits there (the reference is silent; docs/virtual-controller.md),
     * and the trace says so once.
     */
    static BooleanSupplier afterVector(VirtualGalil c, long n) {
        VectorMotion mo = c.motion;
        double trip = mo.afterVector(n);
        boolean[] told = new boolean[1];
        return () -> {
            if (mo.travelled() >= trip) {
                c.traceEvent(String.format(Locale.ROOT, "av %d tripped at %.0f of path (trip point %.0f)",
                        n, Math.floor(mo.travelled()), trip));
                return true;
            }
            if (mo.endedShortOf(trip) && !told[0]) {
                told[0] = true;
                c.traceEvent(String.format(Locale.ROOT, "av %d never reached: trip point %.0f past the path's"
                        + " end %.0f, the thread waits", n, trip, Math.floor(mo.travelled())));
            }
            return mo.cutShort();
        };
    }

    /**
     * {@code MF}/{@code MR}: until axis {@code a} has passed count {@code at} forward (backward). "The
     * accuracy of the MF command is the number of counts that occur in 2*TM" (COMALL MF, MR): the trip is
     * seen 0, 1 or 2 samples after the first sample past the count, at the controller's seeded trip phase
     * (VirtualGalil.tripPhase), so passes do not start alike.
     */
    static BooleanSupplier past(VirtualGalil c, int a, double at, boolean reverse) {
        double[] position = c.motion.position;
        BooleanSupplier past = reverse ? () -> position[a] <= at : () -> position[a] >= at;
        int[] late = {-1};
        return () -> {
            if (late[0] < 0) {
                if (!past.getAsBoolean()) {
                    return false;
                }
                late[0] = c.tripPhase.nextInt(3);
            }
            return late[0]-- == 0;
        };
    }

    /** {@code WT}: until the controller's time {@code until} (seconds). */
    static BooleanSupplier until(VirtualGalil c, double until) {
        return () -> c.time() >= until - 1e-9;
    }

    /** {@code AI}: until input {@code bit} reads high ({@code high}) or low. */
    static BooleanSupplier input(VirtualGalil c, int bit, boolean high) {
        return () -> ((c.inputs >> (bit - 1) & 1) != 0) == high;
    }
}
