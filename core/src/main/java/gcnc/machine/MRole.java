package gcnc.machine;

/**
 * What an M code does, in gcnc's terms: the {@code function} column of a control's m_codes.csv.
 * {@link #number()} is the code the thesis's Table 4 gives it, the checker's number for it
 * (Haas's M10 clamps the chuck: it is {@link #CHUCK_CLOSE}, the thesis's M11).
 */
public enum MRole {
    STOP(0), OPTIONAL_STOP(1), SPINDLE_CW(3), SPINDLE_CCW(4), SPINDLE_STOP(5), SPINDLE_ORIENT(19),
    CHUCK_OPEN(10), CHUCK_CLOSE(11), END(30),
    /** Anything else the machine does through its outputs (coolant, tailstock, conveyor, gears). */
    OUTPUT(-1),
    /** M98: call a program by its number (P), L times; followed by gcnc.flow, not by the checker. */
    CALL(-3),
    /** Haas M97: call the blocks of the same program from the N label P on, L times; followed by gcnc.flow. */
    LOCAL_CALL(-5),
    /** M99: the end of a called program (return to the caller); in the main program, its end. */
    RETURN(-4),
    /**
     * Haas M23/M24: the chamfered pull-out at the end of each G76/G92 thread pass on (in force at
     * power-up) or off (a straight pull-out). The chamfer is the profile's
     * {@code thread.chamfer_leads} and {@code thread.chamfer_angle} (docs/threading.md).
     */
    THREAD_CHAMFER_ON(-6), THREAD_CHAMFER_OFF(-7),
    /**
     * A C-axis or live-tool code (Haas M154/M155, M133-M135) that a two-axis program carries without
     * using it: the control runs it and gcnc drives nothing (note E649); a C word after one is E650.
     */
    AXIS_OPTION(-8),
    /**
     * Fanuc M29 (before G84): rigid tapping, the control gears the tap's feed to the spindle. gcnc's
     * G84 feeds the tap at the F in force with the spindle reversed at the bottom, as a floating
     * holder would be tapped: accepted with note E720, nothing driven for it.
     */
    RIGID_TAP(-9),
    /** A function gcnc cannot follow yet (Haas M97, live tooling): using it is E110. */
    UNSUPPORTED(-2);

    private final int number;

    MRole(int number) {
        this.number = number;
    }

    public int number() {
        return number;
    }

    /** Program flow that gcnc.flow follows: a call. */
    public boolean call() {
        return this == CALL || this == LOCAL_CALL;
    }

    public boolean spindleGroup() {
        return this == SPINDLE_CW || this == SPINDLE_CCW || this == SPINDLE_STOP || this == SPINDLE_ORIENT;
    }

    public static MRole named(String s) {
        for (MRole r : values()) {
            if (r.name().equalsIgnoreCase(s)) {
                return r;
            }
        }
        return null;
    }
}
