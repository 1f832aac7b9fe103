package gcnc.galil;

import gcnc.dmc.Command;
import gcnc.dmc.DmcReader;
import gcnc.ir.CheckedBlock;
import gcnc.ir.MCall;
import gcnc.machine.MachineProfile;
import java.util.List;
import java.util.Map;

/**
 * What the M functions write in the galil dialect (docs/galil.md): each one's output directives from the
 * profile and what it does to the spindle ({@link MachineCode#afterM}), and a program stop with what it
 * turns off and puts back afterwards (docs/galil.md, "Program stops").
 */
final class MFunctions {
    private final MachineProfile profile;
    private final MachineCode machine;

    MFunctions(MachineProfile profile, MachineCode machine) {
        this.profile = profile;
        this.machine = machine;
    }

    /** The profile's output directives of each M code, read once. */
    private final Map<Integer, List<Command>> outputs = new java.util.HashMap<>();

    /**
     * The M functions' output directives and what they do to the spindle (also on the way,
     * GroupWriter); a program stop among them (M00, M01 with the switch on) comes after the others.
     */
    void outputs(CheckedBlock b, List<MCall> calls, BlockWriter out) {
        boolean stop = false;
        for (MCall m : calls) {
            if (profile.control().stopsProgram(m.code())) {
                stop = true;
            } else {
                apply(b, m.code(), out);
            }
        }
        if (stop) {
            programStop(b, out);
        }
    }

    /** The last M code applied in each of the control's M groups: what a program stop puts back. */
    private final Map<Integer, Integer> lastInGroup = new java.util.HashMap<>();

    /** One M code's output directives and what it does to the spindle. */
    private void apply(CheckedBlock b, int code, BlockWriter out) {
        for (Command directive : outputs.computeIfAbsent(code, this::directives)) {
            out.emit(directive);
        }
        machine.afterM(b, new MCall(code), out);
        gcnc.machine.MFunction f = profile.control().m().get(code);
        if (f != null && f.group() > 0) {
            lastInGroup.put(f.group(), code);
        }
    }

    /**
     * A program stop (docs/galil.md, "Program stops"), the axes at rest (the planner ended the
     * sequence): the control's {@code stop.off} codes that change something (Haas: M05 when the
     * spindle turns, M09 when the coolant is on), the wait for the operator ({@code gstop=1},
     * {@code JS #PSTOP}), then what they changed put back as the program had it (M03 with its
     * speed, and the wait for speed before the next feed, as after any M03; M08).
     */
    private void programStop(CheckedBlock b, BlockWriter out) {
        List<Integer> restore = new java.util.ArrayList<>();
        for (int off : profile.control().stop().off()) {
            gcnc.machine.MFunction f = profile.control().m().get(off);
            Integer last = f.group() > 0 ? lastInGroup.get(f.group()) : null;
            if (f.group() > 0 && (last == null || last == off || !restorable(last))) {
                continue; // nothing of that group is on: the stop changes nothing there
            }
            apply(b, off, out);
            if (last != null) {
                restore.add(last);
            }
        }
        machine.programStop(out);
        for (int code : restore) {
            apply(b, code, out);
        }
    }

    /** Whether M code {@code code} is a state a stop can put back: a spindle start or an output (not M19's orientation). */
    private boolean restorable(int code) {
        gcnc.machine.MFunction f = profile.control().m().get(code);
        gcnc.machine.MRole r = f == null ? null : f.role();
        return r == gcnc.machine.MRole.SPINDLE_CW || r == gcnc.machine.MRole.SPINDLE_CCW
                || r == gcnc.machine.MRole.OUTPUT;
    }

    /** The profile's output directives of M code {@code m} as commands (the loader has checked their form). */
    private List<Command> directives(int m) {
        return directives(profile, m);
    }

    static List<Command> directives(MachineProfile profile, int m) {
        List<Command> commands = new java.util.ArrayList<>();
        for (String d : profile.outputsFor(m)) {
            commands.add(java.util.Objects.requireNonNull(DmcReader.read(d, (code, args) -> {
                throw new IllegalStateException("profile output directive " + d + " is not SB/CB n");
            })));
        }
        return List.copyOf(commands);
    }
}
