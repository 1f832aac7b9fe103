package gcnc.send;

import gcnc.dmc.Command;
import gcnc.dmc.CommandKind;

/**
 * What a command of the lines a resume skips sets that the resume must set again before the program
 * goes on ({@link Resume}, docs/run.md "Resume"): each command is decided here, so that a new command
 * that holds state on the controller does not compile until it is placed.
 */
enum Restore {
    /** {@code OF} of the spindle's channel, or {@code AO} of an analog drive: the spindle's speed. */
    SPINDLE,
    /** {@code TOOL=n}: the tool in the cutting position. */
    TOOL,
    /** {@code SB}/{@code CB}: an output bit (the spindle's direction, the coolant, the chuck). */
    OUTPUT,
    /** {@code name=n}: a DMC variable of gcnc's ({@code gline}, {@code gstop}). */
    VARIABLE,
    /**
     * Nothing: motion and its settings (each sequence and move writes its own, the header's are sent
     * again), waits, jumps and marks; a thread's gearing, sync point and deadlines, which its own block
     * sets anew; the thesis dialect's pseudo-commands, which no controller runs.
     */
    NOTHING;

    static Restore of(Command c) {
        return switch (CommandKind.of(c)) {
            case OFFSET, ANALOG_OUT -> SPINDLE;
            case TOOL_NUMBER -> TOOL;
            case OUTPUT -> OUTPUT;
            case SET_VARIABLE -> VARIABLE;
            case LABEL, SERVO_HERE, VECTOR_MODE, VECTOR_ACCELERATION, VECTOR_DECELERATION, STOCK, FEED_MARK,
                    SOURCE_MARK, REMARK, VECTOR_SPEED, VECTOR_POSITION, CIRCULAR_ARC, VECTOR_END, BEGIN_SEQUENCE,
                    AWAIT_SEQUENCE, AFTER_VECTOR, WAIT, REVOLVER, PASS_THROUGH_M, GEAR_MASTER, SYNC_POINT,
                    WAIT_PAST, GEAR_RATIO, PHASE_ERROR, INCREMENT_POSITION, DEFINE_POSITION, POSITION_ABSOLUTE, BEGIN,
                    AFTER_MOTION, END, AXIS_SETTING, SOFT_LIMIT, JUMP, CALL, MESSAGE, STOP, ABORT, CLEAR_STACK,
                    SET_DEADLINE -> NOTHING;
        };
    }
}
