package gcnc.cli;

import java.io.InputStream;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code java -jar gcnc.jar}: the only place that calls System.exit. */
@Command(name = "gcnc", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = "Checks lathe G-code completely, translates it for a Galil controller and verifies it in a simulator.",
        subcommands = {CheckCommand.class, CompileCommand.class, SimulateCommand.class, TablesCommand.class,
                ExplainCommand.class, MachinesCommand.class, CompletionCommand.class, CommandLine.HelpCommand.class},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:no errors (warnings and notes may have been printed)",
            "1:a program has errors (each one printed with its line and column)",
            "2:usage, a file that cannot be read or written, or a broken table or machine profile"})
public final class Main implements Runnable {
    /** Standard input and output as bytes: a program read from {@code -}, a DMC written to {@code -o -}. */
    record Streams(InputStream in, OutputStream out) {
    }

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    private final Streams streams;

    private Main(Streams streams) {
        this.streams = streams;
    }

    Streams streams() {
        return streams;
    }

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "name a command: check, compile, simulate, tables, explain, machines or completion");
    }

    public static void main(String[] args) {
        CommandLine cl = commandLine();
        // Messages are UTF-8 whatever the locale: in LANG=C Java would print every 'é' or 'ñ' as '?'.
        cl.setOut(new PrintWriter(new OutputStreamWriter(System.out, StandardCharsets.UTF_8), true));
        cl.setErr(new PrintWriter(new OutputStreamWriter(System.err, StandardCharsets.UTF_8), true));
        System.exit(cl.execute(args));
    }

    /** The command line with gcnc's exit codes: 0 clean, 1 the program has errors, 2 usage or I/O problem. */
    public static CommandLine commandLine() {
        return commandLine(new Streams(System.in, System.out));
    }

    /** The command line reading {@code -} from, and writing {@code -o -} to, the given streams. */
    static CommandLine commandLine(Streams streams) {
        CommandLine cl = new CommandLine(new Main(streams));
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        cl.registerConverter(Path.class, Main::path);
        cl.setExitCodeExceptionMapper(e -> ExitCode.USAGE);
        cl.setParameterExceptionHandler((e, args) -> {
            e.getCommandLine().getErr().println("gcnc: " + Printable.escape(e.getMessage()));
            CommandLine.UnmatchedArgumentException.printSuggestions(e, e.getCommandLine().getErr());
            e.getCommandLine().getErr().println("Try 'gcnc --help' or 'gcnc help <command>'.");
            return ExitCode.USAGE;
        });
        return cl;
    }

    /**
     * A file name from the command line. Java decodes names with the locale's character set, and in
     * the C locale (ASCII) a name with 'é' cannot be a path at all: say so, and how to run instead.
     */
    static Path path(String name) {
        try {
            return Path.of(name);
        } catch (InvalidPathException e) {
            throw new CommandLine.TypeConversionException("'" + Printable.escape(name) + "' cannot be a file name ("
                    + e.getReason() + "; names are read in " + System.getProperty("sun.jnu.encoding")
                    + "): a name with letters outside ASCII needs a UTF-8 locale, e.g. LC_ALL=C.UTF-8, which"
                    + " scripts/gcnc sets");
        }
    }

    static String version() {
        String v = Main.class.getPackage().getImplementationVersion();
        return v == null ? "development" : v;
    }

    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = Main.class.getPackage().getImplementationVersion();
            return new String[] {"gcnc " + (v == null ? "(development build)" : v)};
        }
    }
}
