package gcnc.cli;

import gcnc.tables.ErrorMessages;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ResourceBundle;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/** {@code java -jar gcnc.jar}: the only place that calls System.exit. */
@Command(name = "gcnc", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        description = "Checks lathe G-code completely, translates it for a Galil controller and verifies it in a simulator.",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {
            "0:no errors (warnings and notes may have been printed)",
            "1:a program has errors (each one printed with its line and column)",
            "2:usage, a file that cannot be read or written, a broken table or machine profile, or out of memory (E506)"})
public final class Main implements Runnable {
    static {
        // picocli registers converters for java.time and java.sql types by reflection when it builds a
        // command line, loading some eighty classes no gcnc option uses (20 ms of every run's start)
        if (System.getProperty("picocli.converters.excludes") == null) {
            System.setProperty("picocli.converters.excludes", "java\\.time\\..*,java\\.sql\\..*");
        }
    }

    /**
     * What a run is given besides its arguments: standard input and output as bytes (a program read
     * from {@code -}, a DMC written to {@code -o -}), the environment (the language of the messages),
     * whether it runs on a terminal (carets under findings) and which file is its standard output
     * ({@code -o log > log}). A cold run takes this JVM's own; the resident checker (gcnc.daemon) its
     * client's, so that both print the same bytes.
     */
    record Streams(InputStream in, OutputStream out, java.util.Map<String, String> env, boolean console,
                   java.util.function.Predicate<Path> isStandardOutput) {
        /** This JVM's standard input and output, environment and terminal. */
        Streams(InputStream in, OutputStream out) {
            this(in, out, System.getenv(), System.console() != null, SourceFiles::isStandardOutput);
        }
    }

    /**
     * A run as the resident checker makes one for a client: the client's standard input, output and
     * error, its environment, whether its standard input and output are a terminal, and which file its
     * standard output is.
     */
    public record Invocation(InputStream in, OutputStream out, OutputStream err, java.util.Map<String, String> env,
                             boolean console, java.util.function.Predicate<Path> isStandardOutput) {
    }

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    /**
     * {@code gcnc --lang es check ...}: the language for every command after it that has no {@code --lang}
     * of its own (see {@link CommonOptions#language}). Hidden: the commands' help lists their own.
     */
    @CommandLine.Option(names = "--lang", paramLabel = "en|es", hidden = true,
            description = "Language of the help, messages and summaries of the command that follows.")
    ErrorMessages.Lang lang;

    private final Streams streams;

    private Main(Streams streams) {
        this.streams = streams;
    }

    Streams streams() {
        return streams;
    }

    /**
     * The commands, in the order the help lists them. They are added when the command line is made
     * ({@link #commandLine(Streams, ErrorMessages.Lang, String[])}), not named in the annotation, so
     * that a run of one command builds only that command's model: picocli reads every option of every
     * command it is given, and doing that for all of them was a fifth of a short run's time.
     */
    private static final java.util.Map<String, Class<?>> COMMANDS = commands();

    private static java.util.Map<String, Class<?>> commands() {
        java.util.Map<String, Class<?>> m = new java.util.LinkedHashMap<>();
        m.put("check", CheckCommand.class);
        m.put("compile", CompileCommand.class);
        m.put("simulate", SimulateCommand.class);
        m.put("sheet", SheetCommand.class);
        m.put("path", PathCommand.class);
        m.put("run", SendCommand.class);
        m.put("offsets", OffsetsCommand.class);
        m.put("tables", TablesCommand.class);
        m.put("explain", ExplainCommand.class);
        m.put("machines", MachinesCommand.class);
        m.put("studio", StudioCommand.class);
        m.put("lsp", LspCommand.class);
        m.put("daemon", DaemonCommand.class);
        m.put("controller", ControllerCommand.class);
        m.put("completion", CompletionCommand.class);
        m.put("help", CommandLine.HelpCommand.class);
        return java.util.Collections.unmodifiableMap(m);
    }

    /**
     * The command {@code args} run when it needs no other (check, compile, simulate, tables, explain,
     * machines), else null: {@code help}, {@code completion}, a misspelt name (for "did you mean"), or
     * no command need them all.
     */
    static String onlyCommand(String[] args) {
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a == null || a.equals("--")) {
                return null;
            }
            if (a.equals("--lang")) {
                i++;
            } else if (!a.startsWith("-")) {
                return COMMANDS.containsKey(a) && !a.equals("help") && !a.equals("completion") ? a : null;
            }
        }
        return null;
    }

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "name a command: check, compile, simulate, tables, explain, machines or completion");
    }

    public static void main(String[] args) {
        int status;
        try {
            status = execute(args, new Invocation(System.in, System.out, System.err, System.getenv(),
                    System.console() != null, SourceFiles::isStandardOutput));
        } catch (OutOfMemoryError e) {
            status = outOfMemory(args);
        }
        System.exit(status);
    }

    /**
     * The heap ran out (issue 23): one line, E506, and the usage/I-O status 2, not the JVM's stack trace
     * and status 1, which would read as "the program has errors". By now the run's objects are
     * unreachable, so the message can be made; if even that fails, it is printed in English as is.
     */
    static int outOfMemory(String[] args) {
        System.err.print(outOfMemoryLine(args, System.getenv()));
        System.err.flush();
        return ExitCode.USAGE;
    }

    /** The one line an out-of-memory prints (E506, in the run's language), with its line end: cold and resident alike. */
    public static String outOfMemoryLine(String[] args, java.util.Map<String, String> env) {
        String mib = Long.toString(Runtime.getRuntime().maxMemory() >> 20);
        String text;
        try {
            text = gcnc.tables.Tables.builtIn().messages().render(gcnc.diag.Code.E506_OUT_OF_MEMORY,
                    java.util.List.of(mib), HelpLanguage.of(args, env));
        } catch (OutOfMemoryError | RuntimeException again) {
            text = "out of memory: the Java heap of " + mib + " MiB was not enough";
        }
        return "gcnc: error[E506]: " + text + System.lineSeparator();
    }

    /**
     * Runs one command line and returns its exit status: what {@link #main} does in a JVM of its own,
     * and the resident checker in a warm one (the same code for both, so the same bytes).
     * {@code onError} gets what a command threw, which picocli would otherwise print with a stack trace
     * (the resident checker then hands the run to a cold JVM).
     */
    public static int execute(String[] args, Invocation run) {
        return execute(args, run, null);
    }

    public static int execute(String[] args, Invocation run, CommandLine.IExecutionExceptionHandler onError) {
        if (isVersionAlone(args) && plain(new Version().getVersion())) {
            return printVersion(run.out());
        }
        CommandLine cl = commandLine(new Streams(run.in(), run.out(), run.env(), run.console(), run.isStandardOutput()),
                HelpLanguage.of(args, run.env()), args);
        // Messages are UTF-8 whatever the locale: in LANG=C Java would print every 'é' or 'ñ' as '?'.
        cl.setOut(new PrintWriter(new OutputStreamWriter(run.out(), StandardCharsets.UTF_8), true));
        cl.setErr(new PrintWriter(new OutputStreamWriter(run.err(), StandardCharsets.UTF_8), true));
        if (onError != null) {
            cl.setExecutionExceptionHandler(onError);
        }
        return cl.execute(args);
    }

    /**
     * The command line with gcnc's exit codes: 0 clean, 1 the program has errors, 2 usage or I/O problem;
     * its help and usage errors in the language of the environment (LC_ALL, LC_MESSAGES, LANG).
     */
    public static CommandLine commandLine() {
        return commandLine(new Streams(System.in, System.out), HelpLanguage.of(new String[0], System.getenv()));
    }

    /**
     * The command line that will run {@code args}: its help and usage errors in the language of their
     * {@code --lang}, else of the environment. The language is chosen before picocli builds the model.
     */
    public static CommandLine commandLine(String... args) {
        return commandLine(new Streams(System.in, System.out), HelpLanguage.of(args, System.getenv()), args);
    }

    /** The command line reading {@code -} from, and writing {@code -o -} to, the given streams. */
    static CommandLine commandLine(Streams streams) {
        return commandLine(streams, HelpLanguage.of(new String[0], System.getenv()));
    }

    /** The command line with every command, its usage help, picocli's headings and usage errors in {@code lang}. */
    static CommandLine commandLine(Streams streams, ErrorMessages.Lang lang) {
        return commandLine(streams, lang, new String[0]);
    }

    /** The same, with only the command {@code args} run when it needs no other ({@link #onlyCommand}). */
    static CommandLine commandLine(Streams streams, ErrorMessages.Lang lang, String[] args) {
        CommandLine cl = new CommandLine(new Main(streams));
        String only = onlyCommand(args);
        for (java.util.Map.Entry<String, Class<?>> c : COMMANDS.entrySet()) {
            if (only == null || only.equals(c.getKey())) {
                cl.addSubcommand(c.getKey(), c.getValue());
            }
        }
        cl.setCaseInsensitiveEnumValuesAllowed(true);
        cl.registerConverter(Path.class, Main::path);
        cl.setExitCodeExceptionMapper(e -> ExitCode.USAGE);
        ResourceBundle help = HelpLanguage.bundle(lang);
        if (help != null) {
            cl.setResourceBundle(help); // every subcommand's help, and picocli's own headings, in that language
        }
        Phrases phrases = new Phrases(lang);
        cl.setParameterExceptionHandler((e, unused) -> {
            PrintWriter err = e.getCommandLine().getErr();
            err.println("gcnc: " + Printable.escape(HelpLanguage.usageError(e.getMessage(), lang)));
            if (lang == ErrorMessages.Lang.EN) {
                CommandLine.UnmatchedArgumentException.printSuggestions(e, err);
            } else {
                HelpLanguage.printSuggestions(e, phrases, err);
            }
            err.println(phrases.get("usage.try"));
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

    /**
     * {@code gcnc --version} (or {@code -V}) and nothing else: what picocli would print, without building
     * the model of all sixteen commands by reflection first (issue 35: that cost 0.4 s of CPU to print
     * one line). Anything else with it ({@code --version check}, {@code --lang es --version}) goes to
     * picocli as before. MainFastPathTest holds the two to the same bytes.
     */
    static boolean isVersionAlone(String[] args) {
        return args.length == 1 && ("--version".equals(args[0]) || "-V".equals(args[0]));
    }

    /** Lines picocli prints as they are: no {@code %} for its format, no {@code @|} for its colours. */
    static boolean plain(String[] lines) {
        for (String l : lines) {
            if (l.contains("%") || l.contains("@|")) {
                return false;
            }
        }
        return true;
    }

    /** The version lines as picocli's {@code printVersionHelp} writes them (no markup or {@code %} in them), status 0. */
    static int printVersion(OutputStream to) {
        PrintWriter out = new PrintWriter(new OutputStreamWriter(to, StandardCharsets.UTF_8), true);
        for (String line : new Version().getVersion()) {
            out.println(line);
        }
        out.flush();
        return ExitCode.CLEAN;
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
