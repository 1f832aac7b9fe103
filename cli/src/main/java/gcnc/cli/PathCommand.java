package gcnc.cli;

import gcnc.Compiler;
import gcnc.output.AtomicOutput;
import gcnc.path.InterpretedPath;
import gcnc.path.PathFormat;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.nio.file.Path;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code gcnc path FILE}: the interpreted path, every move as the control makes it (docs/path.md),
 * from the blocks the checker hands on through gcnc.Session#path. Its {@code --format} is the
 * path's (csv, json); the findings are always GCC-style on standard error, so it is no
 * {@link RunCommand} (whose {@code --format} is the report's).
 */
@Command(name = "path", mixinStandardHelpOptions = true,
        description = {"Print the interpreted path of a program: every move as the control makes it, after cycles,"
                + " chamfers, nose compensation, subprograms and macros, in program and machine coordinates"
                + " (docs/path.md). Written only when the program has no error."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:no errors; the path was written", "1:the program has errors; nothing was written",
                "2:usage, unreadable input, unwritable or refused output, broken table or profile"})
final class PathCommand extends StreamsCommand {
    @Mixin
    CommonOptions common;

    @Parameters(paramLabel = "FILE", description = "The G-code program; - reads standard input.")
    Path file;

    @Option(names = "--format", paramLabel = "csv|json", defaultValue = "csv",
            description = {"csv (default): a header row, then one row per move.",
                    "json: JSON Lines, one object per move with the CSV's column names."})
    String format;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT",
            description = "Output file (default: standard output); never the program itself; written whole or not at all.")
    Path output;

    @Option(names = {"-q", "--quiet"}, description = "Print the findings only: no summary line.")
    boolean quiet;

    @Override
    Integer call(PrintWriter out, PrintWriter err) {
        PathFormat chosen = switch (format.toLowerCase(java.util.Locale.ROOT)) {
            case "csv" -> PathFormat.CSV;
            case "json" -> PathFormat.JSON;
            default -> throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "--format is csv or json, not '" + format + "'");
        };
        Reporter reporter = new Reporter(Reporter.Format.GNU, quiet, out, err, common.language());
        boolean toStdout = output == null || SourceFiles.isStdin(output);
        reporter.stdoutTaken();
        return RunCommand.loaded(reporter, out, err, common, false, setup -> run(setup, chosen, toStdout));
    }

    private int run(CommonOptions.Setup setup, PathFormat chosen, boolean toStdout) {
        Reporter reporter = setup.reporter();
        String name = SourceFiles.display(file);
        String targetName = toStdout ? "<stdout>" : output.toString();
        Main.Streams streams = ((Main) spec.root().userObject()).streams();
        try (AtomicOutput o = toStdout ? AtomicOutput.toStream(streams.out()) : AtomicOutput.open(output, AtomicOutput.Name.GIVEN)) {
            if (!toStdout && !SourceFiles.isStdin(file)) {
                AtomicOutput.refuseInput(SourceFiles.fileOf(file), output);
            }
            if (chosen.header() != null) {
                o.line(chosen.header());
            }
            long[] moves = {0};
            InterpretedPath path = new InterpretedPath(setup.profile(), name, m -> {
                o.line(chosen.line(m));
                moves[0]++;
            });
            Compiler.Result r;
            try (Reader in = SourceFiles.open(file, streams.in())) {
                r = setup.session().withPrograms(SourceFiles.programsFolder(file)).path(in, path);
            } catch (IOException e) {
                return reporter.ioFault(name, gcnc.diag.Phrase.IO_CANNOT_READ, e);
            }
            reporter.report(name, r.diagnostics());
            Phrases say = reporter.phrases();
            if (!r.ok()) {
                reporter.say(say.get("compile.failed", name, say.count(r.diagnostics().errorCount(), "error")));
                return ExitCode.PROGRAM_ERRORS;
            }
            o.commit();
            reporter.say(say.get("path.written", name, say.count(r.blocks(), "block"), targetName,
                    say.count(moves[0], "move")));
            return ExitCode.CLEAN;
        } catch (IOException e) {
            return reporter.ioFault(targetName, gcnc.diag.Phrase.IO_CANNOT_WRITE, e);
        }
    }
}
