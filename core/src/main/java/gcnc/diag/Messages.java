package gcnc.diag;

import java.util.List;

/** Turns a code and its arguments into a sentence in the user's language (tables/errors.csv). */
public interface Messages {
    String render(Code code, List<String> args);

    /** The arguments as the sentence shows them (a {@link Phrase} as its text in the language). */
    default List<String> arguments(List<String> args) {
        return args;
    }
}
