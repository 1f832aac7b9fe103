package gcnc.galil;

import gcnc.dmc.Command;
import java.util.List;
import java.util.Optional;

/**
 * The DMC subroutines {@link MachineCode} writes after the program's EN (docs/galil.md): a timed wait on
 * an input (the spindle at speed, the turret in position), the program stop's {@code #PSTOP}, and the
 * automatic error handlers, each ending in the common stop {@code #FAULT}.
 */
final class Subroutines {
    private Subroutines() {
    }

    /**
     * A wait for {@code input} with a timeout: {@code twt=TIME+ms}, a loop on the input and the
     * clock, and on timeout {@code then}, the message and the stop ({@code JP #FAULT}).
     */
    static void waitFor(List<Command> c, String label, String loop, int input, double seconds,
                                List<Command> then, String message) {
        String ok = label.substring(0, 2) + "OK";
        c.add(new Command.Label(label));
        c.add(new Command.SetDeadline(MachineCode.DEADLINE, GalilNumbers.round(seconds * 1000)));
        c.add(new Command.Label(loop));
        c.add(new Command.Jump(ok, Optional.of(new Command.Condition.InputIs(input, true))));
        c.add(new Command.Jump(loop, Optional.of(new Command.Condition.Before(MachineCode.DEADLINE))));
        c.addAll(then);
        c.add(new Command.Message(message + gcnc.dmc.FaultMessage.AT, List.of(MachineCode.LINE)));
        c.add(new Command.Jump(MachineCode.FAULT, Optional.empty()));
        c.add(new Command.Label(ok));
        c.addAll(then);
        c.add(new Command.End());
    }

    /**
     * {@code #PSTOP}: the message, then the wait. With a cycle start input the button must first be
     * seen released ({@code #PSR}: a button held, or an input that reads on unwired, does not end
     * the stop at once), then pressed ({@code #PSW}); the host's {@code gstop=0} ends either loop.
     * The routine leaves {@code gstop} at 0.
     */
    static void stopRoutine(List<Command> c, java.util.OptionalInt cycleStart) {
        Command.Condition waiting = new Command.Condition.VariableIs(MachineCode.STOP_FLAG, 1);
        c.add(new Command.Label(MachineCode.PROGRAM_STOP));
        c.add(new Command.Message(gcnc.dmc.FaultMessage.PROGRAM_STOP + gcnc.dmc.FaultMessage.AT, List.of(MachineCode.LINE)));
        if (cycleStart.isPresent()) {
            Command.Condition pressed = new Command.Condition.InputIs(cycleStart.getAsInt(), true);
            c.add(new Command.Label("PSR"));
            c.add(new Command.Jump("PSOK", Optional.of(new Command.Condition.VariableIs(MachineCode.STOP_FLAG, 0))));
            c.add(new Command.Jump("PSR", Optional.of(pressed)));
            c.add(new Command.Label("PSW"));
            c.add(new Command.Jump("PSOK", Optional.of(pressed)));
            c.add(new Command.Jump("PSW", Optional.of(waiting)));
            c.add(new Command.Label("PSOK"));
            c.add(new Command.SetVariable(MachineCode.STOP_FLAG, 0));
        } else {
            c.add(new Command.Label("PSW"));
            c.add(new Command.Jump("PSW", Optional.of(waiting)));
        }
        c.add(new Command.End());
    }

    /** An automatic error subroutine: an abort for a following or amplifier fault, the message, the common stop. */
    static void handler(List<Command> c, String label, boolean abort, String message, String... operands) {
        c.add(new Command.Label(label));
        if (abort) {
            c.add(new Command.Abort());
        }
        c.add(new Command.Message(message + gcnc.dmc.FaultMessage.AT, List.of(operands)));
        c.add(new Command.Jump(MachineCode.FAULT, Optional.empty()));
    }
}
