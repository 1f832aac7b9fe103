package gcnc.controller;

/**
 * What a thread pass needs beside the vector motion (docs/virtual-controller.md, "Thread passes"):
 * the spindle encoder turning, electronic gearing of axes to it, and the independent moves that
 * settle a pass on its end counts.
 *
 * <ul>
 * <li><b>The spindle and its encoder.</b> An axis outside the vector plane, servoed ({@code SH}),
 * with an offset ({@code OF}) turns at {@code OF × rate} encoder counts a second, where {@code rate}
 * is the drive and encoder of the lathe the controller is wired to ({@code --spindle}: r/min per
 * volt and counts per revolution; with its gains zeroed, as gcnc's header sets the spindle's
 * channel, "the output equals OF", Offset.html). Its position ({@code _TPC}) is the encoder's count.
 * <li><b>Gearing</b> ({@code GA}, {@code GR}; COMALL GA/GR): {@code GA} names each axis's master,
 * {@code GR} engages the axes at their ratios from where they stand (a slave moves ratio × the
 * master's counts since, every sample), {@code GR} with other ratios changes them on the way, and
 * {@code GR 0,0} disengages.
 * <li><b>Independent moves</b> ({@code PA}, {@code BG}, {@code AM} on axes): each axis to its
 * target at {@code SP} (Galil's default 25,000 counts/s), accelerating at {@code AC} and
 * decelerating at {@code DC} (256,000 counts/s² by default), in whole samples.
 * </ul>
 * Stepped once a millisecond of controller time, after the vector motion and before the threads, as
 * {@link VectorMotion} is: a trippoint on a geared axis ({@code MF}/{@code MR}) is seen at the first
 * sample past it, as on the controller.
 */
final class Gearing {
    /** Galil's defaults (COMALL SP, AC, DC). */
    static final double SPEED = 25_000;
    static final double ACCELERATION = 256_000;

    /** Where a settling move ends; the trace and the test listen. */
    interface Events {
        void moveDone(int[] axes, double[] ends, double time);
    }

    private final double[] position;
    private final boolean[] servo;
    private final double[] offsets;
    private final Events events;
    /** Encoder counts a second per volt of OF on the spindle's channel. */
    double rate;
    /** The master of each axis ({@code GA}), -1 for none. */
    final int[] master;
    final double[] ratio;
    final boolean[] geared;
    /** The master's position when the present ratios took effect, and the slave's then. */
    private final double[] masterFrom;
    private final double[] slaveFrom;
    /** Independent moves: the target ({@code PA}), whether moving, the speed now. */
    final double[] target;
    final boolean[] moving;
    private final double[] speed;
    /** A geared slave's superimposed move ({@code IP}): done so far, its target, its speed now. */
    private final double[] extra;
    private final double[] extraTarget;
    private final double[] extraSpeed;

    Gearing(int axes, double[] position, boolean[] servo, double[] offsets, double rate, Events events) {
        this.position = position;
        this.servo = servo;
        this.offsets = offsets;
        this.rate = rate;
        this.events = events;
        this.master = new int[axes];
        java.util.Arrays.fill(master, -1);
        this.ratio = new double[axes];
        this.geared = new boolean[axes];
        this.masterFrom = new double[axes];
        this.slaveFrom = new double[axes];
        this.target = new double[axes];
        java.util.Arrays.fill(target, Double.NaN);
        this.moving = new boolean[axes];
        this.speed = new double[axes];
        this.extra = new double[axes];
        this.extraTarget = new double[axes];
        this.extraSpeed = new double[axes];
    }

    /** {@code GA}: axis {@code a} follows {@code m}'s encoder. */
    void master(int a, int m) throws GalilException {
        if (geared[a] || moving[a]) {
            throw new GalilException(Tc.WHILE_RUNNING);
        }
        master[a] = m;
    }

    /** {@code GR}: engage, change or (0) disengage axis {@code a}. */
    void ratio(int a, double r) throws GalilException {
        if (r == 0) {
            geared[a] = false; // a superimposed move left unfinished ends where it is
            ratio[a] = 0;
            extraTarget[a] = extra[a];
            return;
        }
        if (master[a] < 0) {
            throw new GalilException(Tc.OPERAND); // no GA: no master to follow
        }
        if (moving[a]) {
            throw new GalilException(Tc.WHILE_RUNNING);
        }
        // from here on the slave moves r x the master's counts; a change takes effect where both
        // stand (a superimposed IP goes on on top); the ratio as the controller holds it, 1/65,536
        masterFrom[a] = position[master[a]];
        slaveFrom[a] = position[a] - (geared[a] ? extra[a] : 0);
        if (!geared[a]) {
            extra[a] = 0;
            extraTarget[a] = 0;
            extraSpeed[a] = 0;
        }
        ratio[a] = Math.rint(r * 65_536) / 65_536;
        geared[a] = true;
    }

    /**
     * {@code IP n} on a geared slave: n counts "superimposed on top of the existing gearing motion"
     * with "the predefined AC,DC,SP values" (COMALL IP; Galil's defaults, gcnc sets none).
     */
    void increment(int a, double counts) throws GalilException {
        if (!geared[a]) {
            throw new GalilException(Tc.WHILE_RUNNING); // not modelled: gcnc writes IP on a geared slave only
        }
        extraTarget[a] += counts;
    }

    /** {@code PA}: the absolute target of axis {@code a}. */
    void target(int a, double counts) throws GalilException {
        if (moving[a]) {
            throw new GalilException(Tc.WHILE_RUNNING);
        }
        target[a] = counts;
    }

    /** {@code BG} on axis {@code a}: move to its target (none given: to where it stands). */
    void begin(int a) throws GalilException {
        if (moving[a]) {
            throw new GalilException(Tc.BEGIN_WHILE_RUNNING);
        }
        if (geared[a]) {
            throw new GalilException(Tc.WHILE_RUNNING);
        }
        if (!servo[a]) {
            throw new GalilException(Tc.MOTOR_OFF);
        }
        if (Double.isNaN(target[a])) {
            target[a] = position[a];
        }
        moving[a] = true;
        speed[a] = 0;
    }

    /** Is any axis geared or in a settling move (the controller is not at rest)? */
    boolean anyMoving() {
        for (int a = 0; a < master.length; a++) {
            if (moving[a] || geared[a]) {
                return true;
            }
        }
        return false;
    }

    /** {@code ST}, {@code AB}, {@code MO}: gearing off and the moves end where the axes are. */
    void stop() {
        for (int a = 0; a < moving.length; a++) {
            geared[a] = false;
            ratio[a] = 0;
            if (moving[a]) {
                moving[a] = false;
                position[a] = Math.rint(position[a]);
            }
            target[a] = Double.NaN;
        }
    }

    /** The superimposed IP move of geared axis {@code a} one step on: the same trapezoid as a PA move. */
    private void superimposed(int a, double h) {
        double left = extraTarget[a] - extra[a];
        if (left == 0) {
            return;
        }
        double v = Math.min(Math.min(SPEED, extraSpeed[a] + ACCELERATION * h), Math.sqrt(2 * ACCELERATION * Math.abs(left)));
        double step = v * h;
        if (Math.abs(left) <= Math.max(step, 0.5)) {
            extra[a] = extraTarget[a];
            extraSpeed[a] = 0;
        } else {
            extra[a] += Math.signum(left) * step;
            extraSpeed[a] = v;
        }
    }

    /** One step of {@code h} seconds: the spindle turns, the geared axes follow it, the moves go on. */
    void advance(double h, double time, int plane1, int plane2) {
        for (int a = 0; a < master.length; a++) {
            if (a != plane1 && a != plane2 && servo[a] && offsets[a] != 0 && !geared[a] && !moving[a]) {
                position[a] += offsets[a] * rate * h;
            }
        }
        for (int a = 0; a < master.length; a++) {
            if (geared[a]) {
                superimposed(a, h);
                position[a] = slaveFrom[a] + ratio[a] * (position[master[a]] - masterFrom[a]) + extra[a];
            }
        }
        int[] done = new int[master.length];
        int n = 0;
        for (int a = 0; a < master.length; a++) {
            if (!moving[a]) {
                continue;
            }
            double left = target[a] - position[a];
            double dir = Math.signum(left);
            // a trapezoid: down to 0 at DC over what is left, else up to SP at AC
            double v = Math.min(Math.min(SPEED, speed[a] + ACCELERATION * h),
                    Math.sqrt(2 * ACCELERATION * Math.abs(left)));
            double step = v * h;
            if (Math.abs(left) <= Math.max(step, 0.5)) {
                position[a] = target[a];
                moving[a] = false;
                speed[a] = 0;
                target[a] = Double.NaN;
                done[n++] = a;
            } else {
                position[a] += dir * step;
                speed[a] = v;
            }
        }
        if (n > 0) {
            int[] axes = java.util.Arrays.copyOf(done, n);
            double[] ends = new double[n];
            for (int i = 0; i < n; i++) {
                ends[i] = position[axes[i]];
            }
            events.moveDone(axes, ends, time + h);
        }
    }
}
