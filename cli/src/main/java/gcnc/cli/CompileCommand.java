package gcnc.cli;

import gcnc.Compiler;
import gcnc.dmc.Form;
import gcnc.machine.MachineProfile;
import gcnc.output.AtomicOutput;
import gcnc.output.DmcOutputs;
import gcnc.output.FormOutputs;
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
                "2:usage, unreadable input, unwritable or refused output, broken table or profile, out of memory (E506)"})
final class CompileCommand extends RunCommand {
    @Mixin
    DialectOptions dialect;

    @Parameters(paramLabel = "FILE", description = "The G-code program; - reads standard input (then give -o).")
    Path file;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT",
            description = "Output file (default: FILE with extension .dmc); - writes standard output. Never the program"
                    + " itself; a device or named pipe is written through, not replaced.")
    Path output;

    @Option(names = "--form", paramLabel = "program|stream", converter = FormConverter.class,
            description = "program: one program downloaded whole (it must fit the controller's memory); stream: a resident"
                    + " program (OUT) and a segment stream (OUT with extension .stream) a sender feeds the controller."
                    + " Default: program when it fits the profile's Galil model, else stream.")
    gcnc.dmc.Form form;

    @Option(names = "--source-map", description = "Put a Galil comment (NO L<line>) naming the G-code line before each block's directives.")
    boolean sourceMap;

    @Option(names = "--no-simulate", description = "Skip the simulation (travel, collisions, path conformance are then NOT verified).")
    boolean noSimulate;

    @Mixin
    StockOptions stock;

    @Mixin
    CornerOptions corners;

    @Override
    int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) throws TableException {
        MachineProfile profile = setup.profile();
        Reporter reporter = setup.reporter();
        boolean toStdout = output != null && SourceFiles.isStdin(output);
        // -o /dev/stdout (or the file stdout goes to) is standard output too: the DMC alone on it
        boolean stdoutTaken = output != null && (SourceFiles.isStdin(output) || streams().isStandardOutput().test(output));
        refuseUsage(reporter, stdoutTaken);
        Optional<SimOptions> sim = simulation(profile, err, reporter.phrases());
        Path target = output != null ? output : DmcOutputs.defaultOutput(file);
        String name = SourceFiles.display(file);
        String targetName = toStdout ? "<stdout>" : target.toString();
        Optional<Form> asked = form(toStdout);
        FormOutputs outputs;
        try {
            outputs = toStdout ? FormOutputs.toStream(streams().out())
                    : FormOutputs.open(SourceFiles.fileOf(file), target, !sourceMap,
                            output != null ? AtomicOutput.Name.GIVEN : AtomicOutput.Name.DERIVED);
        } catch (DmcOutputs.Failed e) {
            return reporter.ioFault(e.path(), gcnc.diag.Phrase.IO_CANNOT_WRITE, e.problem());
        }
        try (outputs) {
            Compiler.Result r;
            try (Reader in = SourceFiles.open(file, streams().in())) {
                // the form decided when clean; what does not fit is an error here
                r = setup.session().withDialect(dialect.kind()).withPrograms(SourceFiles.programsFolder(file)).compileInto(outputs,
                        SourceFiles.isStdin(file) ? name : file.getFileName().toString(), SourceFiles.fileOf(file), in, sim,
                        sourceMap, asked, false, gcnc.CompileObserver.NONE);
            } catch (IOException e) {
                return reporter.ioFault(name, gcnc.diag.Phrase.IO_CANNOT_READ, e);
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
                return reporter.ioFault(targetName, gcnc.diag.Phrase.IO_CANNOT_WRITE, e);
            }
            Phrases say = reporter.phrases();
            if (outputs.form() == Form.STREAM) {
                reporter.say(say.get("compile.written_stream", name, say.count(r.blocks(), "block"), targetName,
                        say.count(outputs.dmcLines(), "line"), outputs.streamPath().orElseThrow().toString(),
                        say.count(outputs.streamLines(), "line"), dialect.name()));
            } else {
                reporter.say(say.get("compile.written", name, say.count(r.blocks(), "block"), targetName,
                        say.count(outputs.dmcLines(), "line"), dialect.name()));
            }
            r.simulation().ifPresent(s -> {
                reporter.say(SimSummary.format(s, reporter.phrases()));
                corners.say(s, name, reporter);
                reporter.simulation(name, corners.kept(s));
            });
            return ExitCode.CLEAN;
        }
    }

    /** The form asked for with --form; none when it is left to the program's size. */
    private Optional<Form> form(boolean toStdout) {
        if (form == null) {
            return Optional.empty();
        }
        Form f = form;
        if (f == Form.STREAM && toStdout) {
            throw new ParameterException(spec.commandLine(),
                    "--form stream writes two files (the resident program and the stream): name the output with -o");
        }
        if (f == Form.STREAM && dialect.kind() == gcnc.galil.Dialect.Kind.THESIS) {
            throw new ParameterException(spec.commandLine(), "--form stream is a Galil program's form: the thesis dialect has none");
        }
        return Optional.of(f);
    }

    /** Combinations that cannot work, refused before anything is read or written; standard output taken by -o. */
    private void refuseUsage(Reporter reporter, boolean stdoutTaken) {
        if (stdoutTaken) {
            takeStandardOutput("-o " + output, reporter);
        }
        if (output == null && SourceFiles.isStdin(file)) {
            throw new ParameterException(spec.commandLine(),
                    "the program comes from standard input: name the output with -o (- for standard output)");
        }
    }

    /** The simulation to run (none for --no-simulate and the thesis dialect), said on standard error. */
    private Optional<SimOptions> simulation(MachineProfile profile, PrintWriter err, Phrases phrases) {
        boolean simulate = !noSimulate && dialect.simulatedByDefault();
        Optional<SimOptions> sim = simulate ? Optional.of(stock.options(profile, file, phrases, spec, err::println)) : Optional.empty();
        if (noSimulate) {
            err.println(phrases.get("compile.no_simulate"));
        } else if (!simulate) {
            err.println(phrases.get("compile.thesis_not_simulated"));
        }
        return sim;
    }
}
