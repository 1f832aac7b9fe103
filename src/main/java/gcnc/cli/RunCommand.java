package gcnc.cli;

import gcnc.tables.TableException;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * A command that works on programs for one machine: it loads the tables and the profile (a
 * broken one ends the run with status 2 and a located message), then runs.
 */
abstract class RunCommand implements Callable<Integer> {
    @Mixin
    CommonOptions common;

    @Spec
    CommandSpec spec;

    @Override
    public final Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        int status;
        try {
            status = run(common.load(err), out, err);
        } catch (TableException e) {
            status = Reporter.tableFault(err, e, common.language());
        }
        out.flush();
        err.flush();
        return status;
    }

    /** The command's work; returns the exit status (see {@link ExitCode}). */
    abstract int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) throws TableException;
}
