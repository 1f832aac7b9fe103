package gcnc.cli;

import gcnc.tables.ErrorMessages;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.ResourceBundle;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import picocli.CommandLine;

/**
 * The language of the usage help and of the usage errors. The help comes from picocli's resource-bundle
 * internationalisation: {@code gcnc/cli/Help.properties} (empty: the annotations' English is the text) and
 * {@code Help_es.properties}, keys qualified by the command ({@code gcnc.check.usage.description},
 * {@code gcnc.compile.output}) or not (picocli's own headings, options every command shares). The
 * language must be known before picocli builds the command model, so it is read from the raw arguments
 * ({@code --lang es}, {@code --lang=es}), else from the environment as {@link LanguageOption#fromEnvironment}
 * reads it. Picocli's usage errors are English sentences; {@link #usageError} puts the common ones into
 * Spanish.
 */
final class HelpLanguage {
    static final String BUNDLE = "gcnc.cli.Help";

    private HelpLanguage() {
    }

    /** The language of {@code --lang} among {@code args} (before a {@code --}), else of the environment. */
    static ErrorMessages.Lang of(String[] args, Map<String, String> env) {
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a == null || a.equals("--")) {
                break;
            }
            String value = null;
            if (a.equals("--lang") && i + 1 < args.length) {
                value = args[i + 1];
            } else if (a.startsWith("--lang=")) {
                value = a.substring("--lang=".length());
            }
            if (value != null) {
                for (ErrorMessages.Lang l : ErrorMessages.Lang.values()) {
                    if (l.name().equalsIgnoreCase(value)) {
                        return l;
                    }
                }
            }
        }
        return LanguageOption.fromEnvironment(env);
    }

    /**
     * The help bundle for {@code lang}, or null for English: the annotations are the English text, and
     * without a bundle picocli prints them exactly as before. Loaded without falling back to the JVM's
     * default locale, so {@code --lang en} in a Spanish locale (or the reverse) gets what it asked for.
     */
    static ResourceBundle bundle(ErrorMessages.Lang lang) {
        if (lang == ErrorMessages.Lang.EN) {
            return null;
        }
        return ResourceBundle.getBundle(BUNDLE, Locale.forLanguageTag(lang.name().toLowerCase(Locale.ROOT)),
                HelpLanguage.class.getClassLoader(),
                ResourceBundle.Control.getNoFallbackControl(ResourceBundle.Control.FORMAT_PROPERTIES));
    }

    /** "Did you mean" and "possible solutions" after an unknown command or option, in the phrases' language. */
    static void printSuggestions(CommandLine.ParameterException e, Phrases phrases, PrintWriter err) {
        if (!(e instanceof CommandLine.UnmatchedArgumentException u)) {
            return;
        }
        List<String> suggestions = u.getSuggestions();
        if (suggestions.isEmpty()) {
            return;
        }
        if (u.isUnknownOption()) {
            err.println(phrases.get("usage.possible", String.join(", ", suggestions)));
            return;
        }
        List<String> commands = new ArrayList<>();
        String name = u.getCommandLine().getCommandSpec().qualifiedName();
        for (String s : suggestions) {
            commands.add(name + " " + s);
        }
        String last = commands.remove(commands.size() - 1);
        String list = commands.isEmpty() ? last : String.join(", ", commands) + phrases.get("usage.or") + last;
        err.println(phrases.get("usage.did_you_mean", list));
    }

    /** An option or a positional parameter as picocli names it in its messages. */
    private static final String WHAT = "(option '[^']*'(?: at index \\d+)?(?: \\([^)]*\\))?"
            + "|positional parameter at index \\S+ \\([^)]*\\))";

    private record Rule(Pattern pattern, Function<Matcher, String> spanish) {
        Rule(String regex, Function<Matcher, String> spanish) {
            this(Pattern.compile(regex, Pattern.DOTALL), spanish);
        }
    }

    /** The Spanish of usage errors: made when the first one is put into Spanish, not at every run's start. */
    private static final class Spanish {
        static final List<Rule> RULES = List.of(
                new Rule("Unknown option: (.*)", m -> "opción desconocida: " + m.group(1)),
                new Rule("Unknown options: (.*)", m -> "opciones desconocidas: " + m.group(1)),
                new Rule("Unmatched argument at index (\\d+): (.*)",
                        m -> "argumento que sobra en la posición " + m.group(1) + ": " + m.group(2)),
                new Rule("Unmatched arguments from index (\\d+): (.*)",
                        m -> "argumentos que sobran desde la posición " + m.group(1) + ": " + m.group(2)),
                new Rule("Missing required parameter: (.*)", m -> "falta un parámetro obligatorio: " + m.group(1)),
                new Rule("Missing required parameters: (.*)", m -> "faltan parámetros obligatorios: " + m.group(1)),
                new Rule("Missing required options?: (.*)", m -> "falta una opción obligatoria: " + m.group(1)),
                new Rule("Missing required subcommand", m -> "falta el comando"),
                new Rule("Missing required parameter for " + WHAT, m -> "falta el valor de " + what(m.group(1))),
                new Rule(WHAT + " should be specified only once", m -> what(m.group(1)) + " solo puede darse una vez"),
                new Rule("Invalid value for " + WHAT + ": expected one of \\[(.*)\\] \\(case-insensitive\\) but was '(.*)'",
                        m -> "valor no válido para " + what(m.group(1)) + ": se esperaba uno de [" + m.group(2)
                                + "] (en mayúsculas o minúsculas), no '" + m.group(3) + "'"),
                new Rule("Invalid value for " + WHAT + ": (.*)",
                        m -> "valor no válido para " + what(m.group(1)) + ": " + m.group(2)),
                new Rule("Unknown subcommand '(.*)'\\.", m -> "comando desconocido: '" + m.group(1) + "'"),
                // gcnc's own usage errors
                new Rule("name a command: check, compile, simulate, tables, explain, machines or completion",
                        m -> "indique un comando: check, compile, simulate, tables, explain, machines o completion"),
                new Rule("- names standard input, which can be read once: give it once",
                        m -> "- es la entrada estándar, que solo se puede leer una vez: indíquela una sola vez"),
                new Rule("(.+) and --format (\\w+) would both write standard output: name a file",
                        m -> m.group(1) + " y --format " + m.group(2) + " escribirían los dos en la salida estándar:"
                                + " indique un archivo"),
                new Rule("the program comes from standard input: name the output with -o \\(- for standard output\\)",
                        m -> "el programa llega por la entrada estándar: indique la salida con -o (- para la salida estándar)"),
                new Rule("(\\S+) has no row in errors\\.csv", m -> m.group(1) + " no tiene fila en errors.csv"),
                new Rule("'(.*)' is not a diagnostic code of this gcnc \\(gcnc tables lists them all\\)",
                        m -> "'" + m.group(1) + "' no es un código de diagnóstico de este gcnc (gcnc tables los muestra todos)"));
    }

    /** A usage error's message in {@code lang}; one no rule knows stays as picocli or gcnc wrote it. */
    static String usageError(String message, ErrorMessages.Lang lang) {
        if (lang == ErrorMessages.Lang.EN || message == null) {
            return message;
        }
        for (Rule r : Spanish.RULES) {
            Matcher m = r.pattern().matcher(message);
            if (m.matches()) {
                return r.spanish().apply(m);
            }
        }
        return message;
    }

    private static final Pattern OPTION = Pattern.compile("option '([^']*)'(?: at index \\d+)?(?: \\(([^)]*)\\))?");
    private static final Pattern POSITIONAL = Pattern.compile("positional parameter at index \\S+ \\(([^)]*)\\)");

    /** "option '--lang' (en|es)" as "la opción '--lang' (en|es)"; "positional parameter at index 0 (FILE)" as "el parámetro FILE". */
    private static String what(String english) {
        Matcher o = OPTION.matcher(english);
        if (o.matches()) {
            return "la opción '" + o.group(1) + "'" + (o.group(2) == null ? "" : " (" + o.group(2) + ")");
        }
        Matcher p = POSITIONAL.matcher(english);
        if (p.matches()) {
            return "el parámetro " + p.group(1);
        }
        return english;
    }
}
