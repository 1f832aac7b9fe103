package gcnc.diag;

/**
 * A finding as a report prints it: the file it is in (as the user named it), the diagnostic, and its
 * message already rendered in the user's language. Renderers that write one document for a whole
 * run (JSON, SARIF) collect these.
 */
public record Finding(String file, Diagnostic diagnostic, String message) {
    public Finding {
        java.util.Objects.requireNonNull(file);
        java.util.Objects.requireNonNull(diagnostic);
        java.util.Objects.requireNonNull(message);
    }
}
