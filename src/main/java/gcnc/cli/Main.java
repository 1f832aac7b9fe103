package gcnc.cli;

import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code java -jar gcnc.jar}: the only place that calls System.exit. */
@Command(name = "gcnc", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = "Checks lathe G-code completely, translates it for a Galil controller and verifies it in a simulator.",
        subcommands = {CheckCommand.class, CompileCommand.class, SimulateCommand.class, TablesCommand.class,
                CommandLine.HelpCommand.class})
public final class Main implements Runnable {
    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "name a command: check, compile, simulate or tables");
    }

    public static void main(String[] args) {
        System.exit(commandLine().execute(args));
    }

    /** The command line with gcnc's exit codes: 0 clean, 1 the program has errors, 2 usage or I/O problem. */
    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new Main());
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        cl.setExitCodeExceptionMapper(e -> ExitCode.USAGE);
        cl.setParameterExceptionHandler((e, args) -> {
            e.getCommandLine().getErr().println("gcnc: " + e.getMessage());
            e.getCommandLine().getErr().println("Try 'gcnc --help' or 'gcnc help <command>'.");
            return ExitCode.USAGE;
        });
        return cl;
    }

    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = Main.class.getPackage().getImplementationVersion();
            return new String[] {"gcnc " + (v == null ? "(development build)" : v)};
        }
    }
}
