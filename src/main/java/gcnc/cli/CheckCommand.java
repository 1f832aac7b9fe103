package gcnc.cli;

import gcnc.Compiler;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Span;
import gcnc.machine.MachineProfile;
import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

@Command(name = "check", mixinStandardHelpOptions = true,
        description = "Check programs and report every error with line and column. Writes nothing.")
final class CheckCommand implements Callable<Integer> {
    @Mixin
    CommonOptions common;

    @Parameters(arity = "1..*", paramLabel = "FILE", description = "G-code programs to check.")
    List<Path> files;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Tables tables;
        MachineProfile profile;
        try {
            tables = common.loadTables();
            profile = common.loadProfile(tables);
        } catch (TableException e) {
            return Reporter.tableFault(err, e, common.language());
        }
        Reporter reporter = new Reporter(err, tables, common.language());
        int status = ExitCode.CLEAN;
        for (Path file : files) {
            try (Reader in = SourceFiles.open(file)) {
                Compiler.Result r = Compiler.check(in, new Compiler.Settings(tables, profile, "galil", Optional.empty()));
                int errors = reporter.report(file.toString(), r.diagnostics());
                out.println(file + ": " + Reporter.plural(r.blocks(), "block") + ", "
                        + (errors == 0 ? "no errors" : Reporter.plural(errors, "error")));
                if (errors > 0) {
                    status = Math.max(status, ExitCode.PROGRAM_ERRORS);
                }
            } catch (IOException e) {
                reporter.report(file.toString(), Diagnostic.error(Code.E500_IO, Span.of(1, 1), "cannot read: " + SourceFiles.reason(e)));
                status = ExitCode.USAGE;
            }
        }
        out.flush();
        err.flush();
        return status;
    }
}
