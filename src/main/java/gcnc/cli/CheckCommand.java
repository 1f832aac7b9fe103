package gcnc.cli;

import gcnc.Compiler;
import gcnc.machine.MachineProfile;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;

@Command(name = "check", mixinStandardHelpOptions = true,
        description = "Check programs and report every error with line and column. Writes nothing.")
final class CheckCommand extends RunCommand {
    @Parameters(arity = "1..*", paramLabel = "FILE", description = "G-code programs to check.")
    List<Path> files;

    @Override
    int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) {
        Tables tables = setup.tables();
        MachineProfile profile = setup.profile();
        Reporter reporter = setup.reporter();
        int status = ExitCode.CLEAN;
        for (Path file : files) {
            try (Reader in = SourceFiles.open(file)) {
                Compiler.Result r = Compiler.check(in, new Compiler.Settings(tables, profile, "galil", Optional.empty())
                        .withPrograms(SourceFiles.folder(file)));
                int errors = reporter.report(file.toString(), r.diagnostics());
                out.println(file + ": " + Reporter.plural(r.blocks(), "block") + ", "
                        + (errors == 0 ? "no errors" : Reporter.plural(errors, "error")));
                if (errors > 0) {
                    status = Math.max(status, ExitCode.PROGRAM_ERRORS);
                }
            } catch (IOException e) {
                status = reporter.ioFault(file, "cannot read", e);
            }
        }
        return status;
    }
}
