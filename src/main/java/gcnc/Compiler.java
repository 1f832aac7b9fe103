package gcnc;

import gcnc.check.Checker;
import gcnc.diag.Diagnostics;
import gcnc.galil.Dialect;
import gcnc.galil.GalilLine;
import gcnc.galil.LineSink;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import gcnc.parse.BlockReader;
import gcnc.sim.SimOptions;
import gcnc.sim.SimReport;
import gcnc.sim.SimulatorThread;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.Reader;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;

/**
 * The pipeline, one block at a time: parse, check, emit Galil code, replay it in the simulator.
 * Memory stays flat whatever the program's length. Once any error is found the program is only
 * checked further (every error is still reported) and nothing more is emitted or simulated;
 * the caller writes the output only for a clean result.
 */
public final class Compiler {
    /** What a run needs besides the source. {@code simulation} empty = do not simulate. */
    public record Settings(Tables tables, MachineProfile profile, String dialect, Optional<SimOptions> simulation,
                           boolean inlineSourceMap) {
        public Settings(Tables tables, MachineProfile profile, String dialect, Optional<SimOptions> simulation) {
            this(tables, profile, dialect, simulation, false);
        }
    }

    /** What a run found: every diagnostic, how many blocks, and the simulator's summary if it ran to the end. */
    public record Result(Diagnostics diagnostics, long blocks, Optional<SimReport> simulation) {
        public boolean ok() {
            return !diagnostics.hasErrors();
        }
    }

    private Compiler() {
    }

    /** Checks a program: parse and every thesis check and semantic rule, no output. */
    public static Result check(Reader source, Settings settings) throws IOException {
        Diagnostics diags = new Diagnostics();
        BlockReader reader = new BlockReader(source, diags);
        Checker checker = new Checker(settings.tables(), settings.profile(), diags);
        long blocks = 0;
        for (RawBlock raw = reader.next(); raw != null; raw = reader.next()) {
            checker.check(raw);
            blocks++;
        }
        checker.finish(reader.lines());
        return new Result(diags, blocks, Optional.empty());
    }

    /**
     * Checks, translates and (if asked) simulates; Galil lines go to {@code out}. Emission and
     * simulation stop at the first error of the checker or the backend (the output is void then),
     * while the simulator's own findings do not stop it: every one of them is reported. The
     * simulator runs on a thread of its own, a few blocks behind.
     */
    public static Result compile(Reader source, Settings settings, LineSink out) throws IOException {
        Diagnostics diags = new Diagnostics();
        BlockReader reader = new BlockReader(source, diags);
        Checker checker = new Checker(settings.tables(), settings.profile(), diags);
        Dialect dialect = Dialect.create(settings.dialect(), settings.profile(), diags, settings.inlineSourceMap());
        List<GalilLine> lines = new ArrayList<>();
        LineSink collect = lines::add;
        long blocks = 0;
        Optional<SimOptions> simulate = settings.simulation();
        try (SimulatorThread sim = simulate.isPresent() ? new SimulatorThread(settings.profile(), simulate.get()) : null) {
            dialect.begin(collect);
            if (sim != null) {
                sim.begin(List.copyOf(lines));
            }
            flush(lines, out);
            for (RawBlock raw = reader.next(); raw != null; raw = reader.next()) {
                blocks++;
                Optional<CheckedBlock> checked = checker.check(raw);
                if (checked.isEmpty() || diags.hasErrors()) {
                    continue;
                }
                dialect.block(checked.get(), collect);
                if (sim != null && !diags.hasErrors()) {
                    sim.block(checked.get(), List.copyOf(lines));
                }
                flush(lines, out);
            }
            checker.finish(reader.lines());
            boolean translated = !diags.hasErrors();
            if (translated) {
                dialect.end(collect);
                if (sim != null) {
                    sim.end(List.copyOf(lines));
                }
                flush(lines, out);
            }
            Optional<SimReport> report = Optional.empty();
            if (sim != null) {
                diags.addAll(sim.finish());
                report = translated ? Optional.of(sim.report()) : Optional.empty();
            }
            return new Result(diags, blocks, report);
        }
    }

    private static void flush(List<GalilLine> lines, LineSink out) {
        for (GalilLine l : lines) {
            out.accept(l);
        }
        lines.clear();
    }
}
