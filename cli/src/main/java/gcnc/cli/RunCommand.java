package gcnc.cli;

import gcnc.tables.TableException;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * A command that works on programs for one machine: it loads the tables and the profile (a
 * broken one ends the run with status 2 and a located message), then runs, then writes the
 * report (JSON and SARIF are one document for the whole run).
 */
abstract class RunCommand implements Callable<Integer> {
    @Mixin
    CommonOptions common;

    @Mixin
    ReportOptions report;

    @Spec
    CommandSpec spec;

    @Override
    public final Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        Reporter reporter = new Reporter(report.format, report.quiet, out, err, common.language());
        if (report.carets(streams().console())) {
            reporter.showSource();
        }
        if (report.format == Reporter.Format.GNU) {
            reporter.colour(report.colour());
        }
        int status;
        try {
            status = run(common.load(reporter), out, err);
        } catch (TableException e) {
            status = reporter.tableFault(e);
        }
        reporter.finish();
        out.flush();
        err.flush();
        return status;
    }

    /** Standard input and output as bytes ({@code -} as a program, {@code -o -}). */
    Main.Streams streams() {
        return ((Main) spec.root().userObject()).streams();
    }

    /** The command's work; returns the exit status (see {@link ExitCode}). */
    abstract int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) throws TableException;
}
