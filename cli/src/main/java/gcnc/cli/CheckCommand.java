package gcnc.cli;

import gcnc.Compiler;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.nio.file.Path;
import java.util.List;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

@Command(name = "check", mixinStandardHelpOptions = true,
        description = "Check programs and report every error with line and column. Writes nothing.",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:no errors", "1:a program has errors", "2:usage, unreadable file, broken table or profile"})
final class CheckCommand extends RunCommand {
    @Parameters(arity = "1..*", paramLabel = "FILE", description = "G-code programs to check; - reads standard input.")
    List<Path> files;

    @Override
    int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) {
        Reporter reporter = setup.reporter();
        if (files.stream().filter(SourceFiles::isStdin).count() > 1) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "- names standard input, which can be read once: give it once");
        }
        int status = ExitCode.CLEAN;
        for (Path file : files) {
            String name = SourceFiles.display(file);
            try (Reader in = SourceFiles.open(file, streams().in())) {
                Compiler.Result r = setup.session().withPrograms(SourceFiles.programsFolder(file)).check(in);
                int errors = reporter.report(name, r.diagnostics());
                Phrases say = reporter.phrases();
                reporter.say(say.get("check.summary", name, say.count(r.blocks(), "block"),
                        errors == 0 ? say.get("no_errors") : say.count(errors, "error")));
                if (errors > 0) {
                    status = Math.max(status, ExitCode.PROGRAM_ERRORS);
                }
            } catch (IOException e) {
                status = reporter.ioFault(name, "cannot read", e);
            }
        }
        return status;
    }
}
