package gcnc.sim;

import gcnc.diag.Code;
import gcnc.dmc.Command;
import gcnc.dmc.CommandKind;
import gcnc.dmc.Instruction;

/**
 * The program's course in the replay, the half of the commands that do not act on the machine:
 * the program's end (EN, and the routines after it, which the replay does not run), labels,
 * marks and remarks, jumps (not taken), and the commands the replay takes as having no effect.
 * It holds the instruction being run, whose line places the findings about it, and keeps every
 * command that orders the machine from running after the program's end ({@link #run}), so that
 * neither half asks.
 */
abstract class FlowCommands implements Command.Visitor<Void> {
    final ReplayListener out;
    /** The instruction being run: its source places the findings about it. */
    private Instruction instruction;
    private boolean ended;
    /** A label after EN has been met: what follows is a routine, not run in the replay. */
    private boolean routine;

    FlowCommands(ReplayListener out) {
        this.out = out;
    }

    /** The instruction the commands after this refer to (the one being run): its source places their findings. */
    final void at(Instruction i) {
        this.instruction = i;
    }

    /**
     * Runs {@code i}, which becomes the instruction being run. After {@code EN} only what is not an
     * order to the machine is taken (a label, the stock, a mark, a remark); anything else is E312 and
     * does nothing. A label after {@code EN} starts a routine the main program reaches only by a jump or
     * a fault (the homing refusal, the waits, the error handlers: docs/galil.md): its commands are not
     * run by the replay, and not reported.
     */
    final void run(Instruction i) {
        at(i);
        if (ended && !takenAfterEnd(CommandKind.of(i.command()))) {
            if (!routine) {
                out.report(Code.E312_SIM_AFTER_END, source(), text());
            }
            return;
        }
        i.command().accept(this);
    }

    /** Whether a command of this kind is taken after {@code EN} (it orders the machine nothing). */
    private static boolean takenAfterEnd(CommandKind kind) {
        return switch (kind) {
            case LABEL, STOCK, FEED_MARK, SOURCE_MARK, REMARK -> true;
            case SERVO_HERE, VECTOR_MODE, VECTOR_ACCELERATION, VECTOR_DECELERATION, VECTOR_SPEED, VECTOR_POSITION,
                    CIRCULAR_ARC, VECTOR_END, BEGIN_SEQUENCE, AWAIT_SEQUENCE, AFTER_VECTOR, OFFSET, WAIT, TOOL_NUMBER,
                    REVOLVER, PASS_THROUGH_M, OUTPUT, GEAR_MASTER, SYNC_POINT, WAIT_PAST, GEAR_RATIO, PHASE_ERROR,
                    INCREMENT_POSITION, DEFINE_POSITION, POSITION_ABSOLUTE, BEGIN, AFTER_MOTION, END, ANALOG_OUT,
                    AXIS_SETTING, SOFT_LIMIT, JUMP, CALL, MESSAGE, STOP, ABORT, CLEAR_STACK, SET_VARIABLE,
                    SET_DEADLINE -> false;
        };
    }

    final Instruction instruction() {
        return instruction;
    }

    /** Where the instruction being run comes from: where the findings about it are. */
    final gcnc.dmc.Source source() {
        return instruction.source();
    }

    /** The G-code line of the instruction being run. */
    final int line() {
        return instruction.source().line();
    }

    final String text() {
        return instruction.text();
    }

    public Void label(Command.Label c) {
        routine |= ended;
        return null;
    }

    public Void stock(Command.Stock c) {
        return null;
    }

    public Void sourceMark(Command.SourceMark c) {
        return null;
    }

    public Void remark(Command.Remark c) {
        return null;
    }

    public Void end(Command.End c) {
        ended = true;
        return null;
    }

    /**
     * A conditional jump leaves for a routine when the machine is not ready (not at home, the
     * spindle not at speed, the turret not in position): the replay's machine is ready, so the
     * jump is not taken. An unconditional jump in the main program is not followed: E301.
     */
    public Void jump(Command.Jump c) {
        if (c.when().isEmpty()) {
            out.report(Code.E301_SIM_BAD_ARGUMENTS, source(), "JP", text());
        }
        return null;
    }

    /** The thesis's pass-through: no output, no effect. */
    public Void passThroughM(Command.PassThroughM c) {
        return null;
    }

    // a message, a stop or abort of the program, the stack cleared, a variable or deadline set: no
    // effect on the replay's machine, which is always ready (the routines they serve are not run)
    public Void message(Command.Message c) {
        return null;
    }

    public Void stop(Command.Stop c) {
        return null;
    }

    public Void abort(Command.Abort c) {
        return null;
    }

    public Void clearStack(Command.ClearStack c) {
        return null;
    }

    public Void setVariable(Command.SetVariable c) {
        return null;
    }

    public Void setDeadline(Command.SetDeadline c) {
        return null;
    }
}
