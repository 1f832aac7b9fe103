package gcnc.cli;

import gcnc.daemon.DaemonControl;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code gcnc daemon start|stop|status}: the resident checker (gcnc.daemon.DaemonServer), a warm JVM that
 * the launcher scripts/gcnc hands check, compile and simulate to (docs/command-line.md, "Resident
 * checker").
 */
@Command(name = "daemon", mixinStandardHelpOptions = true,
        description = {"Start, stop or ask about the resident checker: a warm JVM on 127.0.0.1 that runs check, compile"
                + " and simulate for the gcnc command in the folder it was started in, printing what a cold run prints.",
                "The gcnc command uses it when it runs and its jar is the one installed; otherwise gcnc runs as always."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:done; for status: running", "2:usage, or the daemon could not start",
            "3:status: not running"})
final class DaemonCommand implements Callable<Integer> {
    /** What {@code gcnc daemon} is asked to do. */
    enum Action { START, STOP, STATUS }

    @Parameters(paramLabel = "start|stop|status",
            description = "start: in this folder (one daemon per user: one serving another folder is stopped first);"
                    + " stop; status: running or not (exit 3).")
    Action action;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        DaemonControl control = new DaemonControl(((Main) spec.root().userObject()).streams().env());
        DaemonControl.Outcome o = switch (action) {
            case START -> control.start(ProcessHandle.current().info().command().orElse("java"),
                    Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI()),
                    Path.of("").toAbsolutePath());
            case STOP -> control.stop();
            case STATUS -> control.status();
        };
        (o.status() == 0 || o.status() == DaemonControl.NOT_RUNNING ? spec.commandLine().getOut() : spec.commandLine().getErr())
                .println(o.line());
        return o.status();
    }
}
