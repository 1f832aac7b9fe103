package gcnc.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * A command with a frame of its own (not a {@link RunCommand}'s: the controller, the studio, machines,
 * tables, explain, path, offsets, probe): its picocli spec (for usage errors), and its work given the
 * command line's standard output and error.
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
