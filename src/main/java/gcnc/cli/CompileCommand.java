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
        if (toStdout && reporter.format() != Reporter.Format.GNU) {
            throw new ParameterException(spec.commandLine(), "-o - and --format "
                    + reporter.format().name().toLowerCase(java.util.Locale.ROOT) + " would both write standard output: name an output file");
        }
        if (output == null && SourceFiles.isStdin(file)) {
            throw new ParameterException(spec.commandLine(),
                    "the program comes from standard input: name the output with -o (- for standard output)");
        }
        boolean simulate = !noSimulate && dialect.simulatedByDefault();
        Optional<SimOptions> sim;
        try {
            sim = simulate ? Optional.of(stock.options(profile)) : Optional.empty();
        } catch (StockOptions.BadStock e) {
            throw new ParameterException(spec.commandLine(), e.getMessage());
        }
        if (noSimulate) {
            err.println("gcnc: warning: --no-simulate: travel limits, collisions and path conformance were NOT verified");
        } else if (!simulate) {
            err.println("gcnc: note: the thesis dialect is a record of the thesis's Table 5.2, not a program for a real"
                    + " controller; it is not simulated (see why: gcnc simulate --dialect thesis)");
        }
        if (toStdout) {
            reporter.stdoutTaken();
        }
        Path target = output != null ? output : defaultOutput(file);
        String name = SourceFiles.display(file);
        String targetName = toStdout ? "<stdout>" : target.toString();
        AtomicOutput dmc = null;
        AtomicOutput map = null;
        try {
            if (!toStdout) {
                AtomicOutput.refuseInput(SourceFiles.fileOf(file), target);
                AtomicOutput.refuseInput(SourceFiles.fileOf(file), mapFile(target));
            }
            dmc = toStdout ? AtomicOutput.toStream(streams().out()) : new AtomicOutput(target);
            if (!sourceMap && dmc.replacesFile()) {
                try {
                    map = new AtomicOutput(mapFile(target));
                } catch (IOException e) {
                    return reporter.ioFault(mapFile(target).toString(), "cannot write", e);
                }
            }
            SourceMap mapper = new SourceMap(map == null ? line -> { } : map::line);
            AtomicOutput dmcOut = dmc;
            Compiler.Result r;
            try (Reader in = SourceFiles.open(file, streams().in())) {
                r = Compiler.compile(in, new Compiler.Settings(setup.tables(), profile, dialect.name(), sim, sourceMap),
                        mapper.wrap(line -> dmcOut.line(line.text())));
            } catch (IOException e) {
                return reporter.ioFault(name, "cannot read", e);
            }
            reporter.report(name, r.diagnostics());
            if (!r.ok()) {
                reporter.say(name + ": " + Reporter.plural(r.diagnostics().errorCount(), "error") + "; no output written");
                return ExitCode.PROGRAM_ERRORS;
            }
            out.flush();
            if (map != null) {
                AtomicOutput.commitAll(dmc, map);
            } else {
                dmc.commit();
            }
            reporter.say(name + ": " + Reporter.plural(r.blocks(), "block") + " -> " + targetName
                    + " (" + Reporter.plural(mapper.lines(), "line") + ", dialect " + dialect.name() + ")");
            r.simulation().ifPresent(s -> reporter.say(SimSummary.format(s)));
            return ExitCode.CLEAN;
        } catch (IOException e) {
            return reporter.ioFault(targetName, "cannot write", e);
        } finally {
            discard(map);
            discard(dmc);
        }
    }

    /** Removes what was not committed; a temporary file that cannot be removed is no reason to fail the run. */
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
