package gcnc.plan;

import gcnc.ir.CheckedBlock;
import gcnc.machine.Blending;
import gcnc.machine.MachineProfile;
import java.util.function.Consumer;

/**
 * The stage between the checker and the emitter: checked blocks in, {@link Step}s out, in program
 * order. A planner may hold back a bounded number of motions (its own Javadoc says how many) and
 * hands everything on by {@link #finish}.
 */
public interface Planner {
    void accept(CheckedBlock block, Consumer<Step> out);

    void finish(Consumer<Step> out);

    /** Whether motions of the blocks given so far are still held back (not yet handed on). */
    boolean holding();

    /** The blocks whose motions are still held back, in program order, each once (none when not {@link #holding}). */
    java.util.List<CheckedBlock> held();

    /** The planner a profile asks for: contouring ({@code plan.blend = on}, the default) or exact stop. */
    static Planner forProfile(MachineProfile profile) {
        Blending b = Blending.of(profile);
        return b.on() ? new Contouring(profile, b) : new ExactStop(profile);
    }
}
