package gcnc;

import gcnc.check.Checker;
import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.flow.ProgramFlow;
import gcnc.galil.Dialect;
import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.ir.ShortLists;
import gcnc.machine.MachineProfile;
import gcnc.parse.BlockReader;
import gcnc.parse.BlockSource;
import gcnc.sim.SimOptions;
import gcnc.sim.SimReport;
import gcnc.sim.SimulatorThread;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.Reader;
import java.nio.file.Path;
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
    /**
     * What a run needs besides the source. {@code simulation} empty = do not simulate.
     * {@code programs}: the folder where programs the source calls (M98) and does not hold itself
     * are looked for, as {@code O1000.nc} or {@code 1000.nc} (the source file's folder); empty =
     * only the source itself.
     */
    public record Settings(Tables tables, MachineProfile profile, gcnc.galil.Dialect.Kind dialect, Optional<SimOptions> simulation,
                           boolean inlineSourceMap, Optional<Path> programs, boolean exactStop) {
        /** Blending as the profile says ({@code plan.blend}). */
        public Settings(Tables tables, MachineProfile profile, gcnc.galil.Dialect.Kind dialect, Optional<SimOptions> simulation,
                        boolean inlineSourceMap, Optional<Path> programs) {
            this(tables, profile, dialect, simulation, inlineSourceMap, programs, false);
        }

        /** The same settings with every motion stopped at its end, whatever the profile says (gcnc run, for now). */
        public Settings withExactStop() {
            return new Settings(tables, profile, dialect, simulation, inlineSourceMap, programs, true);
        }

        public Settings(Tables tables, MachineProfile profile, gcnc.galil.Dialect.Kind dialect, Optional<SimOptions> simulation) {
            this(tables, profile, dialect, simulation, false);
        }

        public Settings(Tables tables, MachineProfile profile, gcnc.galil.Dialect.Kind dialect, Optional<SimOptions> simulation,
                        boolean inlineSourceMap) {
            this(tables, profile, dialect, simulation, inlineSourceMap, Optional.empty());
        }

        /** The same settings with called programs looked for in {@code folder} too. */
        public Settings withPrograms(Path folder) {
            return new Settings(tables, profile, dialect, simulation, inlineSourceMap, Optional.of(folder), exactStop);
        }
    }

    /**
     * What a run found: every diagnostic, how many blocks, the simulator's summary if it ran to the
     * end, and every file beside the program that its calls looked for, found or not ({@code
     * O1000.nc}, {@code 1000.nc}; with the folder of {@link Settings#programs}): the verdict can
     * change when one of them changes.
     */
    public record Result(Diagnostics diagnostics, long blocks, Optional<SimReport> simulation, List<Path> calledFiles) {
        public Result {
            calledFiles = List.copyOf(calledFiles);
        }

        public Result(Diagnostics diagnostics, long blocks, Optional<SimReport> simulation) {
            this(diagnostics, blocks, simulation, List.of());
        }

        public boolean ok() {
            return !diagnostics.hasErrors();
        }
    }

    private Compiler() {
    }

    /** Checks a program: parse and every thesis check and semantic rule, no output. */
    public static Result check(Reader source, Settings settings) throws IOException {
        return check(source, settings, null);
    }

    /**
     * Checks a program and hands each checked block to {@code each} (null: none), in the order the
     * control runs them: cycles expanded, corners inserted, the nose compensation applied, calls and
     * macros followed (gcnc path). After an error the blocks that follow are still handed on.
     */
    public static Result check(Reader source, Settings settings, java.util.function.Consumer<CheckedBlock> each)
            throws IOException {
        return check(source, settings, each, CompileObserver.NONE);
    }

    /** {@link #check(Reader, Settings, java.util.function.Consumer)}, publishing what it saw to {@code observer}. */
    public static Result check(Reader source, Settings settings, java.util.function.Consumer<CheckedBlock> each,
                               CompileObserver observer) throws IOException {
        Diagnostics diags = new Diagnostics();
        // check does not simulate; a blank in its settings only places the work zero (work.G54 = face)
        settings = StockSettings.onTheBlank(settings);
        observer.placed(settings.profile());
        WorkZeroNotes.report(settings.profile(), settings.simulation().flatMap(SimOptions::stock), diags);
        BlockSource reader = blocks(source, settings, diags);
        Checker checker = new Checker(settings.tables(), settings.profile(), diags);
        // the arcs the galil dialect could not write within the replay's tolerance: compile's E202/E308 (one verdict)
        gcnc.sim.ArcVerdict arcs = arcVerdict(settings, diags);
        long blocks = 0;
        boolean observed = observer != CompileObserver.NONE;
        for (RawBlock raw = reader.next(); raw != null; raw = reader.next()) {
            List<CheckedBlock> checked = checker.check(raw);
            if (observed) {
                observer.block(raw, raw.origin(), checked, checker.state());
            }
            if (each != null) {
                for (int i = 0; i < checked.size(); i++) {
                    each.accept(checked.get(i));
                }
            }
            if (arcs != null) {
                // a plain loop: checked.forEach(arcs::block) made a bound method reference per block
                for (int i = 0; i < checked.size(); i++) {
                    arcs.block(checked.get(i));
                }
            }
            blocks++;
        }
        checker.finish(reader.lines());
        return new Result(diags, blocks, Optional.empty(), calledFiles(reader));
    }

    /**
     * Checks, translates and (if asked) simulates; the DMC instructions go to {@code out}. Emission and
     * simulation stop at the first error of the checker or the backend (the output is void then),
     * while the simulator's own findings do not stop it: every one of them is reported. The
     * simulator runs on a thread of its own, a few blocks behind.
     */
    public static Result compile(Reader source, Settings settings, java.util.function.Consumer<Instruction> out) throws IOException {
        return compile(source, settings, out, CompileObserver.NONE);
    }

    /**
     * {@link #compile(Reader, Settings, java.util.function.Consumer)}, publishing what it saw to
     * {@code observer}: the machine on the blank, each block with its checked blocks and modal state,
     * each DMC line replayed with the cycle clock around it, the simulator's summary.
     */
    public static Result compile(Reader source, Settings settings, java.util.function.Consumer<Instruction> out,
                                 CompileObserver observer) throws IOException {
        Diagnostics diags = new Diagnostics();
        java.io.BufferedReader buffered = new java.io.BufferedReader(source, StockSettings.HEADER_PEEK);
        // the blank given for the run sets the work zero; a header's blank does not (the program's
        // DMC does not change with its first comment)
        settings = StockSettings.onTheBlank(settings);
        Optional<gcnc.sim.StockSize> given = settings.simulation().flatMap(SimOptions::stock);
        settings = StockSettings.withStockHeader(buffered, settings);
        WorkZeroNotes.report(settings.profile(), given, diags);
        observer.placed(settings.profile());
        boolean observed = observer != CompileObserver.NONE;
        BlockSource reader = blocks(buffered, settings, diags);
        Checker checker = new Checker(settings.tables(), settings.profile(), diags);
        Dialect dialect = Dialect.create(settings.dialect(), settings.profile(), diags, settings.inlineSourceMap());
        List<Instruction> lines = new ArrayList<>();
        // every number the galil dialect writes is held against the controller's limits on its way out
        gcnc.galil.LimitCheck limits = settings.dialect() == gcnc.galil.Dialect.Kind.GALIL
                ? new gcnc.galil.LimitCheck(settings.profile().controllerLimits(), diags, lines::add) : null;
        java.util.function.Consumer<Instruction> collect = limits != null ? limits : lines::add;
        long blocks = 0;
        Optional<SimOptions> simulate = settings.simulation();
        // with a simulation, the simulator's thread writes the lines after replaying them (see SimulatorThread)
        try (SimulatorThread sim = simulate.isPresent() ? new SimulatorThread(settings.profile(), simulate.get(), out,
                observed ? replay(observer) : null) : null) {
            header(dialect, simulate, collect);
            handOn(lines, sim, SimulatorThread::begin, out);
            gcnc.plan.Planner planner = planner(settings);
            // after the first error nothing is written: the arcs are then judged as check judges them (E202,
            // E224/E225 where the writer would have found them), so that both report the same errors
            gcnc.sim.ArcVerdict arcs = arcVerdict(settings, diags);
            java.util.function.Consumer<gcnc.plan.Step> lower = step -> dialect.lower(step, collect);
            boolean heldJudged = false;
            for (RawBlock raw = reader.next(); raw != null; raw = reader.next()) {
                blocks++;
                List<CheckedBlock> checked = checker.check(raw);
                if (observed) {
                    observer.block(raw, raw.origin(), checked, checker.state());
                }
                translate(checked, planner, lower, diags, lines, sim, out, arcs);
                heldJudged = heldJudged || judgeHeld(planner, diags, arcs);
            }
            if (!diags.hasErrors()) {
                // the motions the planner still holds are of blocks already checked: replayed before the
                // end-of-program checks, as each block's own sequences are
                planner.finish(lower);
                handOn(lines, sim, SimulatorThread::held, out);
            }
            checker.finish(reader.lines());
            boolean translated = !diags.hasErrors();
            if (translated) {
                dialect.end(collect);
                if (limits != null) {
                    limits.finish(); // the whole program against the controller's memory
                }
                handOn(lines, sim, SimulatorThread::end, out);
            }
            Optional<SimReport> report = sim == null ? Optional.empty() : simulated(sim, diags, translated);
            report.ifPresent(observer::simulated);
            return new Result(diags, blocks, report, calledFiles(reader));
        }
    }

    /**
     * Translates the checked blocks of one source block and hands their lines on: to the simulator,
     * which writes them after replaying them, or else straight to {@code out}. Nothing is translated
     * after an error; the arcs of the blocks after it are judged as check judges them. (A method of its own, so that the JIT compiles it once rather than within a
     * large on-stack replacement of the loop in {@link #compile}.)
     */
    private static void translate(List<CheckedBlock> checkedBlocks, gcnc.plan.Planner planner,
                                  java.util.function.Consumer<gcnc.plan.Step> lower, Diagnostics diags,
                                  List<Instruction> lines, SimulatorThread sim, java.util.function.Consumer<Instruction> out,
                                  gcnc.sim.ArcVerdict arcs) throws IOException {
        for (CheckedBlock checked : checkedBlocks) {
            if (diags.hasErrors()) {
                if (arcs != null) {
                    arcs.block(checked);
                }
                continue;
            }
            planner.accept(checked, lower); // into lines: this block's, or a sequence of the blocks before it
            if (sim != null) {
                List<Instruction> own = ShortLists.copyOf(lines); // the simulator's thread takes it as it is
                if (diags.hasErrors()) {
                    sim.outputOnly(own);
                } else {
                    sim.block(checked, own, !planner.holding());
                }
                lines.clear();
            } else {
                flush(lines, out);
            }
        }
    }

    /**
     * Once there is an error, the blocks the planner still holds are never written: their arcs are
     * judged as check judges them (E202, E224/E225), as those of the blocks after the error are.
     * Returns whether it judged them (then it is not asked again).
     */
    private static boolean judgeHeld(gcnc.plan.Planner planner, Diagnostics diags, gcnc.sim.ArcVerdict arcs) {
        if (!diags.hasErrors()) {
            return false;
        }
        if (arcs != null) {
            planner.held().forEach(arcs::block);
        }
        return true;
    }

    /** The judge of the arcs the galil dialect writes (E202, E224/E225, E308), or null for the thesis's format. */
    private static gcnc.sim.ArcVerdict arcVerdict(Settings settings, Diagnostics diags) {
        return settings.dialect() == gcnc.galil.Dialect.Kind.GALIL ? new gcnc.sim.ArcVerdict(settings.profile(), diags) : null;
    }

    /**
     * The blocks of a program as the control would run them: the one place where the stages
     * between the parser and the checker are put together, for check and compile alike. The
     * parser's blocks go through the program flow (subprogram calls, macro statements), which
     * keeps a program without calls or macro statements streaming. ({@link ModalStates} reads a
     * program's blocks through it too, for the front ends' hover.)
     */
    static BlockSource blocks(Reader text, Settings settings, Diagnostics diags) {
        // no line and no text past the input limits (E503, E504): bounded memory and time whatever is read
        Reader source = new gcnc.parse.BoundedReader(text, diags, gcnc.diag.Origin.PROGRAM);
        gcnc.machine.Control control = settings.profile().control();
        if (!control.hasProgramFlow()) {
            // no calls, no macros
            return BlockReader.forControl(source, diags, false, control.lineComments());
        }
        return new ProgramFlow(BlockReader.forControl(source, diags, control.macros(), control.lineComments()), settings.profile(),
                diags, settings.programs());
    }

    /** The files beside the program its calls looked for (none without program flow). */
    private static List<Path> calledFiles(BlockSource reader) {
        return reader instanceof ProgramFlow flow ? flow.calledFiles() : List.of();
    }

    /**
     * The planner between the checker and the emitter (docs/galil.md): the thesis's format stops at
     * every motion; the galil dialect blends as the profile says ({@code plan.blend}).
     */
    private static gcnc.plan.Planner planner(Settings settings) {
        // the studio's scrub follows the stock sequence by sequence: every block its own (the path and the
        // stock a block leaves are the same whether the machine blends through it or stops)
        boolean scrub = settings.simulation().map(o -> o.scrubLine() != 0).orElse(false);
        return settings.dialect() == gcnc.galil.Dialect.Kind.THESIS ? new gcnc.plan.ExactStop()
                : scrub || settings.exactStop() ? new gcnc.plan.ExactStop(settings.profile())
                : gcnc.plan.Planner.forProfile(settings.profile());
    }

    /**
     * {@code options} with the blank of a program's first line if it is a stock header, the
     * options have no blank yet and the profile reads headers ({@code stock.header = use}); else
     * {@code options} as they are.
     */
    public static SimOptions withStockHeader(String firstLine, MachineProfile profile, SimOptions options) {
        if (options.stock().isPresent() || options.noBlank()) {
            return options;
        }
        if (!profile.model().stockHeader()) {
            return options;
        }
        double stickout = profile.model().stock().map(gcnc.machine.MachineModel.Blank::stickout).orElse(0.0);
        return gcnc.sim.StockHeader.parse(firstLine, stickout).map(options::withStock).orElse(options);
    }

    /** The program's header, and its blank (or the note that it has none) when the run gives one. */
    private static void header(Dialect dialect, Optional<SimOptions> simulate, java.util.function.Consumer<Instruction> collect) {
        dialect.begin(collect);
        if (simulate.isPresent() && simulate.get().noBlank()) {
            dialect.blank(Optional.empty(), collect);
        }
        simulate.flatMap(SimOptions::stock).ifPresent(b -> dialect.blank(Optional.of(
                new gcnc.machine.MachineModel.Blank(b.diameter(), b.length(), b.stickout(), b.bore())), collect));
    }

    /** One stage of the simulator's run: the header, the motions the planner held to the end, the footer. */
    private interface Stage {
        void take(SimulatorThread sim, List<Instruction> lines) throws java.io.InterruptedIOException;
    }

    /** Hands the lines written so far on: to the simulator's {@code stage}, which writes them after replaying them, or else to {@code out}. */
    private static void handOn(List<Instruction> lines, SimulatorThread sim, Stage stage,
                               java.util.function.Consumer<Instruction> out) throws java.io.InterruptedIOException {
        if (sim != null) {
            stage.take(sim, List.copyOf(lines));
            lines.clear();
        } else {
            flush(lines, out);
        }
    }

    /**
     * The simulator's findings joined to the compile's, and its summary when the program was translated.
     * A simulation that cut the blank judged every feed check left open (E306/E307 where one really took
     * material), so the checker's "compile decides" warnings (E660, E661) are settled and withdrawn.
     */
    private static Optional<SimReport> simulated(SimulatorThread sim, Diagnostics diags, boolean translated)
            throws java.io.InterruptedIOException {
        diags.addAll(sim.finish());
        if (!translated) {
            return Optional.empty();
        }
        if (diags.sorted().stream().noneMatch(d -> d.code() == Code.E316_SIM_NO_STOCK)) {
            diags.withdraw(d -> d.code() == Code.E660_FEED_SPINDLE_STOPPED_NOT_JUDGED
                    || d.code() == Code.E661_PULL_NOT_JUDGED);
        }
        return Optional.of(sim.report());
    }

    private static void flush(List<Instruction> lines, java.util.function.Consumer<Instruction> out) {
        for (Instruction l : lines) {
            out.accept(l);
        }
        lines.clear();
    }

    /** The simulator's hook that tells {@code observer} of each line replayed and each motion run. */
    private static gcnc.sim.Simulator.Replayed replay(CompileObserver observer) {
        return new gcnc.sim.Simulator.Replayed() {
            @Override
            public void line(Instruction line, double secondsBefore, double secondsAfter) {
                observer.replayed(line, secondsBefore, secondsAfter);
            }

            @Override
            public void sequence(gcnc.sim.Sequence s) {
                observer.sequence(s);
            }
        };
    }
}
