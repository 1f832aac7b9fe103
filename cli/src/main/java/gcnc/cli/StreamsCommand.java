package gcnc.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
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

    /**
     * Serves until the JVM is stopped (Ctrl+C, a signal), which runs {@code close}: the end of a
     * server command (the virtual controller, the studio). {@code serving} says it is up, once the
     * hook that closes it is in place.
     */
    static void serveUntilStopped(Runnable close, Runnable serving) {
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            close.run();
            stopped.countDown();
        }));
        serving.run();
        try {
            stopped.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
