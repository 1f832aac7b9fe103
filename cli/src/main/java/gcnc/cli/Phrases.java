package gcnc.cli;

import gcnc.tables.ErrorMessages;
import gcnc.tables.Plurals;
import java.text.MessageFormat;
import java.util.Locale;
import java.util.ResourceBundle;

/**
 * The command line's own sentences (summaries, warnings about the run) in the language of
 * {@code --lang}: {@code gcnc/cli/Phrases.properties} and {@code Phrases_es.properties}, read as
 * UTF-8. The diagnostics' texts come from {@code tables/errors.csv}, not from here.
 */
final class Phrases {
    private final ResourceBundle bundle;
    private final Locale locale;

    Phrases(ErrorMessages.Lang lang) {
        this.locale = lang == ErrorMessages.Lang.ES ? Locale.forLanguageTag("es") : Locale.ROOT;
        this.bundle = ResourceBundle.getBundle("gcnc.cli.Phrases", locale, Phrases.class.getClassLoader(),
                ResourceBundle.Control.getNoFallbackControl(ResourceBundle.Control.FORMAT_PROPERTIES));
    }

    /** The sentence {@code key} with its arguments, each shown as text (a number as 1234, never 1,234). */
    String get(String key, Object... args) {
        Object[] text = new Object[args.length];
        for (int i = 0; i < args.length; i++) {
            text[i] = String.valueOf(args[i]);
        }
        java.util.List<String> shown = java.util.Arrays.stream(text).map(String::valueOf).toList();
        return new MessageFormat(Plurals.choose(bundle.getString(key), shown), Locale.ROOT).format(text);
    }

    /** "0 blocks", "1 block", "5 blocks": the form the key's ChoiceFormat picks for {@code n}. */
    String count(long n, String what) {
        return get(what, n);
    }
}
