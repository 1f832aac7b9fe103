package gcnc.cli;

import gcnc.tables.ErrorMessages;
import java.util.Map;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;

/**
 * {@code --lang}: the language of what a command says, one option for every command that takes it
 * ({@link CommonOptions}' commands and the virtual controller), with one rule for its default.
 */
final class LanguageOption {
    @Option(names = "--lang", paramLabel = "en|es",
            description = "Language of the messages and summaries: en or es (default: es when LANG or LC_ALL"
                    + " starts with es, else en).")
    ErrorMessages.Lang lang;

    /**
     * This command's {@code --lang}, else one before the command ({@code gcnc --lang es check}), else the
     * locale's; {@code command} is the command holding the option, whose root holds the one before it.
     */
    ErrorMessages.Lang language(CommandSpec command) {
        if (lang != null) {
            return lang;
        }
        if (command != null && command.root().userObject() instanceof Main m) {
            // the one before the command, else the client's environment (under the resident checker)
            return m.lang != null ? m.lang : fromEnvironment(m.streams().env());
        }
        return fromEnvironment(System.getenv());
    }

    /** Spanish when the user's locale is Spanish (LC_ALL, then LC_MESSAGES, then LANG, as POSIX orders them), else English. */
    static ErrorMessages.Lang fromEnvironment(Map<String, String> env) {
        for (String name : new String[] {"LC_ALL", "LC_MESSAGES", "LANG"}) {
            String v = env.get(name);
            if (v != null && !v.isEmpty()) {
                return v.startsWith("es") ? ErrorMessages.Lang.ES : ErrorMessages.Lang.EN;
            }
        }
        return ErrorMessages.Lang.EN;
    }
}
