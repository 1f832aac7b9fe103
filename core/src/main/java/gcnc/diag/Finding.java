package gcnc.diag;

/**
 * A finding as a report prints it: the file it is in (as the user named it), the diagnostic, and its
 * message and arguments already rendered in the user's language (a {@link Phrase} argument as its
 * text). Renderers that write one document for a whole run (JSON, SARIF) collect these.
 */
public record Finding(String file, Diagnostic diagnostic, String message, java.util.List<String> arguments) {
    public Finding {
        java.util.Objects.requireNonNull(file);
        java.util.Objects.requireNonNull(diagnostic);
        java.util.Objects.requireNonNull(message);
        arguments = java.util.List.copyOf(arguments);
    }

    /** The finding of {@code d} in {@code file}, rendered by {@code messages}. */
    public static Finding of(String file, Diagnostic d, Messages messages) {
        return new Finding(file, d, messages.render(d.code(), d.args()), messages.arguments(d.args()));
    }
}
