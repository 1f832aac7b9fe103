package gcnc.diag;

import java.util.List;

/** Turns a code and its arguments into a sentence in the user's language (tables/errors.csv). */
public interface Messages {
    String render(Code code, List<String> args);
}
