package gcnc.send;

import gcnc.CompileObserver;
import gcnc.check.ModalState;
import gcnc.diag.Origin;
import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import gcnc.sim.Sequence;
import gcnc.sim.SimReport;
import java.io.IOException;
import java.io.Reader;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;

/**
 * What {@code gcnc run} and the studio's Run take from the compile that judged the program, as it
 * publishes it ({@link CompileObserver}): the DMC lines in the order the simulator replayed them with
 * its cycle clock around each and the motions it ran (the program sent, its sequences and its time
 * left: {@link DmcProgram}), the checker's
 * state at each block ({@link BlockTable}) and the machine on the blank. Nothing is read, parsed,
 * checked or timed a second time, so the run's estimated time is the compile's cycle time.
 */
public final class CompiledRun implements CompileObserver {
    private final BlockTable.View table = new BlockTable.View();
    private final List<Instruction> lines = new ArrayList<>();
    private final List<Sequence> sequences = new ArrayList<>();
    private double[] before = new double[256];
    private double[] after = new double[256];
    private MachineProfile onBlank;
    private SimReport report;

    /** A program's text read whole, once (the compile reads it from a {@link java.io.StringReader}; the comments from it). */
    public static String text(Reader in) throws IOException {
        StringWriter all = new StringWriter();
        in.transferTo(all);
        return all.toString();
    }

    @Override
    public void placed(MachineProfile profile) {
        onBlank = profile;
    }

    @Override
    public void block(RawBlock raw, Origin from, List<CheckedBlock> checked, ModalState state) {
        table.block(raw, from, checked, state);
    }

    @Override
    public void replayed(Instruction line, double secondsBefore, double secondsAfter) {
        int i = lines.size();
        if (i == before.length) {
            before = Arrays.copyOf(before, 2 * i);
            after = Arrays.copyOf(after, 2 * i);
        }
        before[i] = secondsBefore;
        after[i] = secondsAfter;
        lines.add(line);
    }

    @Override
    public void sequence(Sequence s) {
        sequences.add(s);
    }

    @Override
    public void simulated(SimReport r) {
        report = r;
    }

    /** The simulator's summary, empty when nothing was simulated (the program was not clean). */
    public Optional<SimReport> simulation() {
        return Optional.ofNullable(report);
    }

    /** The machine the program was judged on: the work offsets on the blank's face when a blank was given. */
    public MachineProfile onBlank() {
        return onBlank;
    }

    /**
     * The program as sent: the lines replayed, each with the cycle clock; its total is the simulation's
     * cycle time ({@code profile}: the machine it was compiled for).
     */
    public DmcProgram program(MachineProfile profile) {
        int n = lines.size();
        double total = report != null ? report.cycleSeconds() : n == 0 ? 0 : after[n - 1];
        return DmcProgram.of(lines, new DmcProgram.Clock(Arrays.copyOf(before, n), Arrays.copyOf(after, n), total),
                sequences, profile);
    }

    /** The checker's state at each main-program line, with the comments of {@code text} (the program as compiled). */
    public BlockTable blocks(String text) {
        return table.table(text);
    }
}
