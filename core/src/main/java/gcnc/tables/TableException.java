package gcnc.tables;

import gcnc.diag.Diagnostic;

/** A table or machine-profile file that cannot be used, with the place of the fault in that file. */
public final class TableException extends Exception {
    private final String path;
    private final transient Diagnostic diagnostic;

    public TableException(String path, Diagnostic diagnostic) {
        super(path + ":" + diagnostic.span().line() + ":" + diagnostic.span().column() + ": " + diagnostic.args());
        this.path = path;
        this.diagnostic = diagnostic;
    }

    public String path() {
        return path;
    }

    public Diagnostic diagnostic() {
        return diagnostic;
    }
}
