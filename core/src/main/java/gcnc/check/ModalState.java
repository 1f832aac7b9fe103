package gcnc.check;

import gcnc.ir.Point;
import gcnc.machine.Control;
import gcnc.machine.GFunction;
import gcnc.machine.GRole;
import gcnc.machine.MRole;
import gcnc.machine.MachineProfile;
import gcnc.machine.Units;

/**
 * What the control remembers between blocks (thesis §9 of the reading). A new value per accepted
 * block; a block with an error leaves it as it was (Grbl's atomic commit). NaN means "never set".
 * What nearly every block changes (its motion G, position, N and, under G96, its rpm) is kept here;
 * the modes, which change seldom, are one {@link Modes} value that consecutive states share until
 * one of them changes (a whole state per block was the largest allocation of a check after the
 * words: bench/HISTORY.md, issue 23). Each mode has its accessor here as well.
 *
 * @param motion       modal motion G (0-3), or -1 before the first one (thesis: coordinates then give 44)
 * @param position     machine counts
 * @param lastN        last N number, -1 before the first
 * @param rpm          spindle speed commanded (G97 S or the last CSS speed)
 * @param modes        the rest
 */
public record ModalState(int motion, Point position, long lastN, double rpm, Modes modes) {

    /**
     * The modes of a {@link ModalState}.
     *
     * @param units        G20/G21
     * @param incremental  G91 in force
     * @param workOffset   54..59
     * @param tool         tool number of the last T word (thesis default 1)
     * @param toolOffset   tool offset number in force, 0 = none (thesis default 1)
     * @param feed         F as programmed
     * @param feedPerRev   G95/G99 in force (else G94/G98 per minute)
     * @param css          G96 constant surface speed in force
     * @param surfaceSpeed G96 S (m/min or ft/min)
     * @param rpmClamp     G50 S maximum spindle speed
     * @param spindle      the last spindle M by thesis number (3, 4, 5, 19), -1 if none yet, UNKNOWN
     *                     after an M gcnc could not read
     * @param chuck        10 open, 11 closed (thesis numbers), -1 not closed yet, UNKNOWN as spindle
     * @param shift        G50/G92 position-register shift of the work coordinates, counts
     * @param g28          intermediate point of the last G28, or null
     * @param named        an O word was given
     * @param ended        M30 was given
     * @param nose         G40/G41/G42: tool nose radius compensation in force
     * @param returnToR    Fanuc B/C G99 in force: a drilling or tapping cycle returns to the R point
     *                     (else, G98, to the initial level where it started)
     * @param exactStopMode G61 in force (until G64): every move ends at rest
     */
    public record Modes(Units units, boolean incremental, int workOffset, int tool, int toolOffset, double feed,
                        boolean feedPerRev, boolean css, double surfaceSpeed, double rpmClamp, int spindle, int chuck,
                        Point shift, Point g28, boolean named, boolean ended, NoseSide nose, boolean returnToR,
                        boolean exactStopMode) {
    }

    public Units units() {
        return modes.units;
    }

    public boolean incremental() {
        return modes.incremental;
    }

    public int workOffset() {
        return modes.workOffset;
    }

    public int tool() {
        return modes.tool;
    }

    public int toolOffset() {
        return modes.toolOffset;
    }

    public double feed() {
        return modes.feed;
    }

    public boolean feedPerRev() {
        return modes.feedPerRev;
    }

    public boolean css() {
        return modes.css;
    }

    public double surfaceSpeed() {
        return modes.surfaceSpeed;
    }

    public double rpmClamp() {
        return modes.rpmClamp;
    }

    public int spindle() {
        return modes.spindle;
    }

    public int chuck() {
        return modes.chuck;
    }

    public Point shift() {
        return modes.shift;
    }

    public Point g28() {
        return modes.g28;
    }

    public boolean named() {
        return modes.named;
    }

    public boolean ended() {
        return modes.ended;
    }

    public NoseSide nose() {
        return modes.nose;
    }

    public boolean returnToR() {
        return modes.returnToR;
    }

    public boolean exactStopMode() {
        return modes.exactStopMode;
    }

    /**
     * The state at cycle start: at home, with the control's power-up G codes, tool and offset,
     * the machine's power-up units, and the chuck closed unless the program must close it
     * (thesis-2004: no motion G, G21 G90 G54, tool 1 offset 1, chuck unknown: IniVariablesPrg).
     */
    public static ModalState initial(MachineProfile p) {
        Control c = p.control();
        Next n = new ModalState(-1, p.home(), -1, Double.NaN, new Modes(p.units(), false, 54, c.powerUpTool(),
                c.powerUpOffset(), Double.NaN, false, false, Double.NaN, Double.NaN, -1, p.chuckByProgram() ? -1 : 11,
                Point.ORIGIN, null, false, false, NoseSide.OFF, false, false)).next();
        for (GFunction f : c.powerUp()) {
            n.set(f.role());
        }
        n.units = p.units(); // the machine's setting, over the control's (Haas setting 9)
        return n.build();
    }

    /** Spindle or chuck after a block gcnc could not read that may have changed it: not judged. */
    public static final int UNKNOWN = -2;

    public Next next() {
        return new Next(this);
    }

    /** The state being built by one block; {@link #build()} commits it. */
    public static final class Next {
        public int motion;
        public Units units;
        public boolean incremental;
        public int workOffset;
        public int tool;
        public int toolOffset;
        public double feed;
        public boolean feedPerRev;
        public boolean css;
        public double surfaceSpeed;
        public double rpm;
        public double rpmClamp;
        public int spindle;
        public int chuck;
        public Point position;
        public Point shift;
        public Point g28;
        public long lastN;
        public boolean named;
        public boolean ended;
        public NoseSide nose;
        public boolean returnToR;
        public boolean exactStopMode;
        /** The modes of the state loaded, kept by {@link #build} when none of them changed. */
        private Modes loaded;

        Next(ModalState s) {
            load(s);
        }

        /** A state to {@link #load}: a checker's draft keeps one and loads it for each block. */
        Next() {
        }

        /** Takes every field of {@code s}, as a new block starts from it. */
        void load(ModalState s) {
            motion = s.motion;
            position = s.position;
            lastN = s.lastN;
            rpm = s.rpm;
            Modes m = s.modes;
            loaded = m;
            units = m.units;
            incremental = m.incremental;
            workOffset = m.workOffset;
            tool = m.tool;
            toolOffset = m.toolOffset;
            feed = m.feed;
            feedPerRev = m.feedPerRev;
            css = m.css;
            surfaceSpeed = m.surfaceSpeed;
            rpmClamp = m.rpmClamp;
            spindle = m.spindle;
            chuck = m.chuck;
            shift = m.shift;
            g28 = m.g28;
            named = m.named;
            ended = m.ended;
            nose = m.nose;
            returnToR = m.returnToR;
            exactStopMode = m.exactStopMode;
        }

        /**
         * What a modal G does to the state, whatever its number in the control: the one place the
         * syntax actions, the power-up state and the salvage of a rejected block all use.
         */
        public void set(GRole r) {
            switch (r) {
                case RAPID, LINEAR, ARC_CW, ARC_CCW -> motion = r.number();
                case INCH -> units = Units.INCH;
                case METRIC -> units = Units.MM;
                case ABSOLUTE, INCREMENTAL -> incremental = r == GRole.INCREMENTAL;
                case FEED_PER_MINUTE, FEED_PER_REV -> feedPerRev = r == GRole.FEED_PER_REV;
                case CSS, RPM -> css = r == GRole.CSS;
                case WORK_1, WORK_2, WORK_3, WORK_4, WORK_5, WORK_6 -> workOffset = r.number();
                case NOSE_COMP_CANCEL -> nose = NoseSide.OFF;
                case NOSE_COMP_LEFT -> nose = NoseSide.LEFT;
                case NOSE_COMP_RIGHT -> nose = NoseSide.RIGHT;
                case CYCLE_RETURN_INITIAL, CYCLE_RETURN_R -> returnToR = r == GRole.CYCLE_RETURN_R;
                case EXACT_STOP_MODE, CUTTING_MODE -> exactStopMode = r == GRole.EXACT_STOP_MODE;
                default -> {
                }
            }
        }

        /** What a spindle or chuck M does to the state (Haas's M10 closes the chuck, the thesis's M11). */
        public void set(MRole r) {
            if (r.spindleGroup()) {
                spindle = r.number();
            } else if (r == MRole.CHUCK_OPEN || r == MRole.CHUCK_CLOSE) {
                chuck = r.number();
            }
        }

        public ModalState build() {
            return new ModalState(motion, position, lastN, rpm, modes());
        }

        /** The modes as set: the loaded state's own when none changed (most blocks), else a new value. */
        private Modes modes() {
            Modes m = loaded;
            if (m != null && m.units == units && m.incremental == incremental && m.workOffset == workOffset
                    && m.tool == tool && m.toolOffset == toolOffset && same(m.feed, feed) && m.feedPerRev == feedPerRev
                    && m.css == css && same(m.surfaceSpeed, surfaceSpeed) && same(m.rpmClamp, rpmClamp)
                    && m.spindle == spindle && m.chuck == chuck && m.shift == shift && m.g28 == g28
                    && m.named == named && m.ended == ended && m.nose == nose && m.returnToR == returnToR
                    && m.exactStopMode == exactStopMode) {
                return m;
            }
            return new Modes(units, incremental, workOffset, tool, toolOffset, feed, feedPerRev, css, surfaceSpeed,
                    rpmClamp, spindle, chuck, shift, g28, named, ended, nose, returnToR, exactStopMode);
        }

        /** The same double as a record compares it (NaN equals NaN). */
        private static boolean same(double a, double b) {
            return Double.compare(a, b) == 0;
        }
    }
}
