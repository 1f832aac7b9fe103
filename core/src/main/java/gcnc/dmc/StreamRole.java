package gcnc.dmc;

/**
 * Who carries out a command of the stream form (docs/galil.md, "The stream form"). The host can
 * only send what the controller takes from its command line; Galil's command reference marks the
 * trippoints ({@code AM}, {@code AV}, {@code WT}, {@code AD}, {@code MF} ...), labels, jumps and
 * calls as valid in a program only.
 */
public enum StreamRole {
    /** Sent as it is: the controller takes it from the command line. */
    SEND,
    /**
     * A wait the host carries out itself, by polling: {@code AMS} (until {@code _BGS} is 0),
     * {@code WT n} (n ms after the previous command was taken), {@code AV n} (until {@code _AVS}
     * reaches the sum of the sequence's AVs so far: AV is relative, _AVS from the sequence's start) and {@code JS #L} (the resident routine run with {@code XQ #L,0}, until {@code _XQ0}
     * is -1).
     */
    HOST,
    /**
     * Only valid inside a program, and too tight in time for a host to poll (the thread's
     * {@code AD}/{@code MF} on the spindle encoder): the block's commands go into a routine of the
     * resident program, called from the stream.
     */
    EMBED;

    /** The role of {@code c}. */
    public static StreamRole of(Command c) {
        return switch (CommandKind.of(c)) {
            case SERVO_HERE, VECTOR_MODE, VECTOR_ACCELERATION, VECTOR_DECELERATION, STOCK, FEED_MARK, SOURCE_MARK,
                    REMARK, VECTOR_SPEED, VECTOR_POSITION, CIRCULAR_ARC, VECTOR_END, BEGIN_SEQUENCE, OFFSET,
                    TOOL_NUMBER, OUTPUT, GEAR_MASTER, SYNC_POINT, GEAR_RATIO, PHASE_ERROR, INCREMENT_POSITION,
                    DEFINE_POSITION, POSITION_ABSOLUTE, BEGIN, ANALOG_OUT, AXIS_SETTING, SOFT_LIMIT, MESSAGE, STOP,
                    ABORT, SET_VARIABLE, SET_DEADLINE -> SEND;
            case AWAIT_SEQUENCE, AFTER_VECTOR, WAIT, CALL -> HOST;
            // Revolver and the pass-through M are the thesis's Delphi pseudo-commands: no controller takes them
            case LABEL, REVOLVER, PASS_THROUGH_M, WAIT_PAST, AFTER_MOTION, END, JUMP, CLEAR_STACK -> EMBED;
        };
    }
}
