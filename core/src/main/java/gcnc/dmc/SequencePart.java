package gcnc.dmc;

/**
 * What a command is to the vector sequence it stands in (docs/galil.md, "Continuous contouring"):
 * gcnc writes a sequence as {@code VS}, its segments, {@code VE} and {@code BGS} (BGS before VE and a
 * wait for room when it is fed while it runs), its trip points, then {@code AMS}. The sender's split of
 * a sequence, its replan on a resume, the stream form's feed and the replay each read a sequence by
 * these parts; deciding them here, for every command, is what keeps a new command from being taken
 * silently for none of them.
 */
public enum SequencePart {
    /** {@code VS}: the speed, the first command of a sequence as gcnc writes it. */
    SPEED,
    /** {@code VP}, {@code CR}: a segment, one slot of the vector buffer. */
    SEGMENT,
    /** {@code VE}: no more segments. */
    VECTOR_END,
    /** {@code BGS}: the sequence begins. */
    BEGIN,
    /** {@code JS #LMWAIT} ({@link StreamSplit#BUFFER_WAIT}): the wait for room of a sequence fed while it runs. */
    ROOM_WAIT,
    /** {@code AV n}: a trip point along the path; what follows it happens there. */
    TRIP,
    /** {@code AMS}: the wait until the sequence's motion is complete. */
    AWAIT,
    /**
     * {@code AM}, {@code EN}: a command no sequence has between its {@code VS} and its {@code AMS}, the
     * wait of the independent axes and the end of the program or of a routine: whatever comes after is
     * in no sequence begun before it.
     */
    OUTSIDE,
    /** Anything else: a setting or an output between a sequence's commands, or a command outside any. */
    NONE;

    /** The part {@code c} is. */
    public static SequencePart of(Command c) {
        return switch (CommandKind.of(c)) {
            case VECTOR_SPEED -> SPEED;
            case VECTOR_POSITION, CIRCULAR_ARC -> SEGMENT;
            case VECTOR_END -> VECTOR_END;
            case BEGIN_SEQUENCE -> BEGIN;
            case CALL -> ((Command.Call) c).label().equals(StreamSplit.BUFFER_WAIT) ? ROOM_WAIT : NONE;
            case AFTER_VECTOR -> TRIP;
            case AWAIT_SEQUENCE -> AWAIT;
            case AFTER_MOTION, END -> OUTSIDE;
            case LABEL, SERVO_HERE, VECTOR_MODE, VECTOR_ACCELERATION, VECTOR_DECELERATION, STOCK, FEED_MARK,
                    SOURCE_MARK, REMARK, OFFSET, WAIT, TOOL_NUMBER, REVOLVER, PASS_THROUGH_M, OUTPUT, GEAR_MASTER,
                    SYNC_POINT, WAIT_PAST, GEAR_RATIO, PHASE_ERROR, INCREMENT_POSITION, DEFINE_POSITION,
                    POSITION_ABSOLUTE, BEGIN, ANALOG_OUT, AXIS_SETTING, SOFT_LIMIT, JUMP, MESSAGE, STOP, ABORT,
                    CLEAR_STACK, SET_VARIABLE, SET_DEADLINE -> NONE;
        };
    }
}
