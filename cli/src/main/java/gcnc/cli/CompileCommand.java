package gcnc.cli;

import gcnc.Compiler;
import gcnc.galil.SourceMap;
import gcnc.machine.MachineProfile;
import gcnc.sim.SimOptions;
import gcnc.tables.TableException;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.nio.file.Path;
import java.util.Optional;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;

@Command(name = "compile", mixinStandardHelpOptions = true,
        description = {"Check a program, translate it to a Galil DMC program and verify that in the simulator.",
                "Writes the output (and its .map) only when there is no error; never a half-written one."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:no errors; the output was written", "1:the program has errors; nothing was written",
                "2:usage, unreadable input, unwritable or refused output, broken table or profile"})
final class CompileCommand extends RunCommand {
    @Mixin
    DialectOptions dialect;

    @Parameters(paramLabel = "FILE", description = "The G-code program; - reads standard input (then give -o).")
    Path file;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT",
            description = "Output file (default: FILE with extension .dmc); - writes standard output. Never the program"
                    + " itself; a device or named pipe is written through, not replaced.")
    Path output;

    @Option(names = "--source-map", description = "Put a Galil comment (NO L<line>) naming the G-code line before each block's directives.")
    boolean sourceMap;

    @Option(names = "--no-simulate", description = "Skip the simulation (travel, collisions, path conformance are then NOT verified).")
    boolean noSimulate;

    @Mixin
    StockOptions stock;

    @Override
    int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) throws TableException {
        MachineProfile profile = setup.profile();
        Reporter reporter = setup.reporter();
        boolean toStdout = output != null && SourceFiles.isStdin(output);
        refuseUsage(reporter.format(), toStdout);
        Optional<SimOptions> sim = simulation(profile, err, reporter.phrases());
        if (toStdout) {
            reporter.stdoutTaken();
        }
        Path target = output != null ? output : defaultOutput(file);
        String name = SourceFiles.display(file);
        String targetName = toStdout ? "<stdout>" : target.toString();
        Outputs outputs;
        try {
            outputs = toStdout ? Outputs.toStream(streams().out())
                    : Outputs.open(SourceFiles.fileOf(file), target, !sourceMap);
        } catch (Outputs.Failed e) {
            return reporter.ioFault(e.path, "cannot write", e.problem);
        }
        try (outputs) {
            SourceMap mapper = new SourceMap(outputs.map == null ? line -> { } : outputs.map::line);
            if (outputs.map != null) {
                outputs.map.line(SourceMap.sourceLine(SourceFiles.isStdin(file) ? name : file.getFileName().toString()));
            }
            Compiler.Result r;
            try (Reader in = SourceFiles.open(file, streams().in())) {
                r = setup.session().withDialect(dialect.name()).withPrograms(SourceFiles.programsFolder(file)).compile(in, sim, sourceMap,
                        mapper.wrap(line -> outputs.dmc.line(line.text())));
            } catch (IOException e) {
                return reporter.ioFault(name, "cannot read", e);
            }
            reporter.report(name, r.diagnostics());
            if (!r.ok()) {
                reporter.say(reporter.phrases().get("compile.failed", name,
                        reporter.phrases().count(r.diagnostics().errorCount(), "error")));
                return ExitCode.PROGRAM_ERRORS;
            }
            out.flush();
            try {
                outputs.commit();
            } catch (IOException e) {
                return reporter.ioFault(targetName, "cannot write", e);
            }
            Phrases say = reporter.phrases();
            reporter.say(say.get("compile.written", name, say.count(r.blocks(), "block"), targetName,
                    say.count(mapper.lines(), "line"), dialect.name()));
            r.simulation().ifPresent(s -> reporter.say(SimSummary.format(s, reporter.phrases())));
            return ExitCode.CLEAN;
        }
    }

    /** Combinations that cannot work, refused before anything is read or written. */
    private void refuseUsage(Reporter.Format format, boolean toStdout) {
        if (toStdout && format != Reporter.Format.GNU) {
            throw new ParameterException(spec.commandLine(), "-o - and --format "
                    + format.name().toLowerCase(java.util.Locale.ROOT) + " would both write standard output: name an output file");
        }
        if (output == null && SourceFiles.isStdin(file)) {
            throw new ParameterException(spec.commandLine(),
                    "the program comes from standard input: name the output with -o (- for standard output)");
        }
    }

    /** The simulation to run (none for --no-simulate and the thesis dialect), said on standard error. */
    private Optional<SimOptions> simulation(MachineProfile profile, PrintWriter err, Phrases phrases) {
        boolean simulate = !noSimulate && dialect.simulatedByDefault();
        Optional<SimOptions> sim;
        try {
            sim = simulate ? Optional.of(stock.options(profile)) : Optional.empty();
        } catch (StockOptions.BadStock e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        if (noSimulate) {
            err.println(phrases.get("compile.no_simulate"));
        } else if (!simulate) {
            err.println(phrases.get("compile.thesis_not_simulated"));
        }
        return sim;
    }

    /** The DMC and, beside a regular file, its map: opened together, committed together, discarded together. */
    private static final class Outputs implements AutoCloseable {
        /** An output that could not be opened, and which one. */
        static final class Failed extends Exception {
            final String path;
            final IOException problem;

            Failed(Object path, IOException cause) {
                super(cause);
                this.path = path.toString();
                this.problem = cause;
            }
        }

        final AtomicOutput dmc;
        final AtomicOutput map;

        Outputs(AtomicOutput dmc, AtomicOutput map) {
            this.dmc = dmc;
            this.map = map;
        }

        /** {@code -o -}: the DMC alone, to standard output once committed. */
        static Outputs toStream(java.io.OutputStream stdout) throws Failed {
            try {
                return new Outputs(AtomicOutput.toStream(stdout), null);
            } catch (IOException e) {
                throw new Failed("<stdout>", e);
            }
        }

        /** Refuses the program itself as either file (E501), then opens both. */
        static Outputs open(Path input, Path target, boolean withMap) throws Failed {
            Path mapPath = mapFile(target);
            AtomicOutput dmc;
            try {
                AtomicOutput.refuseInput(input, target);
                if (withMap) {
                    AtomicOutput.refuseInput(input, mapPath);
                }
                dmc = new AtomicOutput(target);
            } catch (IOException e) {
                throw new Failed(target, e);
            }
            if (!withMap || !dmc.replacesFile()) {
                return new Outputs(dmc, null);
            }
            try {
                return new Outputs(dmc, new AtomicOutput(mapPath));
            } catch (IOException e) {
                discard(dmc);
                throw new Failed(mapPath, e);
            }
        }

        void commit() throws IOException {
            if (map != null) {
                AtomicOutput.commitAll(dmc, map);
            } else {
                dmc.commit();
            }
        }

        /** Removes what was not committed; a temporary file that cannot be removed is no reason to fail the run. */
        @Override
        public void close() {
            discard(map);
            discard(dmc);
        }

        private static void discard(AtomicOutput o) {
            if (o == null) {
                return;
            }
            try {
                o.close();
            } catch (IOException e) {
                // The shutdown hook (TempFiles) tries once more at exit.
            }
        }
    }

    static Path defaultOutput(Path file) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return file.resolveSibling((dot > 0 ? name.substring(0, dot) : name) + ".dmc");
    }

    static Path mapFile(Path target) {
        Path name = target.getFileName();
        return target.resolveSibling((name == null ? "" : name.toString()) + ".map");
    }
}
