package gcnc;

import gcnc.check.ModalState;
import gcnc.diag.Origin;
import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import gcnc.sim.Sequence;
import gcnc.sim.SimReport;
import java.util.List;

/**
 * What a check or a compile saw, published as it sees it, so that a front end builds its views (the
 * sender's block table and timing, the hover's modal states, the setup sheet) from the one pass that
 * judged the program instead of reading, parsing, checking or timing it again (issue 32, item 1;
 * docs/architecture.md, "The compile's observer"). Every method has an empty default: a view takes
 * what it needs.
 *
 * <p>{@link #placed} and {@link #block} are called on the caller's thread, in program order;
 * {@link #replayed} on the simulator's thread, in program order, each DMC line after it was replayed
 * (the same order the output is handed its lines); {@link #sequence} likewise, after the line that
 * waits for it; {@link #simulated} once, after every other call, on the caller's thread. A view read after {@code Session.compile} returns sees all of them.
 */
public interface CompileObserver {
    /** Observes nothing. */
    CompileObserver NONE = new CompileObserver() {
    };

    /**
     * The machine the program is judged on: the profile with its work offsets moved to the face of
     * the blank given for the run ({@code work.G54 = 0, face}), else the profile as loaded. Called
     * once, before the first block.
     */
    default void placed(MachineProfile onBlank) {
    }

    /**
     * One block as the control runs it: the block read ({@code from}: the file it was read from, a
     * called program's, or {@link Origin#PROGRAM}), what the checker made of it (cycles expanded,
     * corners inserted; empty for a block it refused or one that does nothing) and the modal state
     * after it.
     */
    default void block(RawBlock raw, Origin from, List<CheckedBlock> checked, ModalState after) {
    }

    /**
     * One DMC line the simulator replayed: the simulator's cycle clock (the one {@link SimReport#cycleSeconds}
     * ends on) before and after it. A sequence's time falls on the line that starts it ({@code BGS},
     * a thread pass's {@code BG}), a dwell's on its {@code WT}.
     */
    default void replayed(Instruction line, double secondsBefore, double secondsAfter) {
    }

    /**
     * One motion the simulator ran ({@link Sequence}: the DMC lines it spans, its pieces in the Galil
     * plane, its start, end and speed), called on the simulator's thread after {@link #replayed} of the
     * line that waits for it; the sender's sequences are these (gcnc.send.CompiledRun).
     */
    default void sequence(Sequence s) {
    }

    /** The simulator's summary of a translated program (not called when nothing was simulated or an error stopped the output). */
    default void simulated(SimReport report) {
    }

    /** Both observers, {@code this} first. */
    default CompileObserver and(CompileObserver other) {
        CompileObserver first = this;
        return new CompileObserver() {
            @Override
            public void placed(MachineProfile onBlank) {
                first.placed(onBlank);
                other.placed(onBlank);
            }

            @Override
            public void block(RawBlock raw, Origin from, List<CheckedBlock> checked, ModalState after) {
                first.block(raw, from, checked, after);
                other.block(raw, from, checked, after);
            }

            @Override
            public void replayed(Instruction line, double secondsBefore, double secondsAfter) {
                first.replayed(line, secondsBefore, secondsAfter);
                other.replayed(line, secondsBefore, secondsAfter);
            }

            @Override
            public void sequence(Sequence s) {
                first.sequence(s);
                other.sequence(s);
            }

            @Override
            public void simulated(SimReport report) {
                first.simulated(report);
                other.simulated(report);
            }
        };
    }
}
