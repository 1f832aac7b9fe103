package gcnc.tables;

import gcnc.diag.Diagnostic;

/** A table or machine-profile file that cannot be used, with the place of the fault in that file. */
public final class TableException extends Exception {
    private final String path;
    private final transient Diagnostic diagnostic;

    public TableException(String path, Diagnostic diagnostic) {
        this.path = path;
        this.diagnostic = diagnostic;
    }

    /** The place and the fault in English (the built-in messages), for logs and assertions. */
    @Override
    public String getMessage() {
        return path + ":" + diagnostic.span().line() + ":" + diagnostic.span().column() + ": " + english();
    }

    /**
     * The fault in English, as {@code gcnc} prints it without {@code --lang es}: the diagnostic's
     * phrase rendered with the messages built into gcnc.jar (never failing: see {@link ErrorMessages#english}).
     */
    public String english() {
        return ErrorMessages.english(diagnostic.code(), diagnostic.args());
    }

    public String path() {
        return path;
    }

    public Diagnostic diagnostic() {
        return diagnostic;
    }
}
