package gcnc.cli;

import gcnc.tables.TableException;
import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.ParameterException;
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
        return loaded(reporter, out, err, common, false, setup -> run(setup, out, err));
    }

    /** A command's work once the tables and the machine are loaded; returns the exit status. */
    @FunctionalInterface
    interface Loaded {
        int run(CommonOptions.Setup setup) throws TableException;
    }

    /**
     * Loads the tables and the machine through {@code common} ({@code newOffsets}: an offsets file
     * that may not exist yet, for the test cut that creates it), runs {@code body}, reports a broken
     * table or profile (status 2), then finishes the report and flushes both streams: the frame of
     * every command that works on programs for one machine (this class's, {@code gcnc path}'s,
     * {@code gcnc offsets wear}'s).
     */
    static int loaded(Reporter reporter, PrintWriter out, PrintWriter err, CommonOptions common, boolean newOffsets,
                      Loaded body) {
        int status;
        try {
            status = body.run(common.load(reporter, newOffsets));
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

    /**
     * An output the user sent to standard output ({@code given}: the option as written, {@code -o -}):
     * refused beside a JSON or SARIF report, which standard output carries too; else the summaries go
     * to standard error from here on, leaving standard output to that output alone.
     */
    void takeStandardOutput(String given, Reporter reporter) {
        if (reporter.format() != Reporter.Format.GNU) {
            throw new ParameterException(spec.commandLine(), given + " and --format "
                    + reporter.format().name().toLowerCase(Locale.ROOT) + " would both write standard output: name a file");
        }
        reporter.stdoutTaken();
    }

    /** The command's work; returns the exit status (see {@link ExitCode}). */
    abstract int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) throws TableException;
}
