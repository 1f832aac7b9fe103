package gcnc.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * A command that is not about one machine's programs (those are {@link RunCommand}s): its picocli
 * spec (for usage errors), and its work given the command line's standard output and error.
 */
abstract class StreamsCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Override
    public final Integer call() throws Exception {
        return call(spec.commandLine().getOut(), spec.commandLine().getErr());
    }

    /** The command's work; returns the exit status. */
    abstract Integer call(PrintWriter out, PrintWriter err) throws Exception;
}
