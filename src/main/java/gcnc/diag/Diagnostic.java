package gcnc.diag;

import java.util.List;

/**
 * One finding: a stable code, where it is, and the values its message template needs.
 * The text is never built here; {@link Messages} renders it in the user's language.
 */
public record Diagnostic(Code code, Severity severity, Span span, List<String> args)
        implements Comparable<Diagnostic> {
    public Diagnostic {
        args = List.copyOf(args);
    }

    public static Diagnostic error(Code code, Span span, Object... args) {
        return new Diagnostic(code, Severity.ERROR, span, strings(args));
    }

    public static Diagnostic warning(Code code, Span span, Object... args) {
        return new Diagnostic(code, Severity.WARNING, span, strings(args));
    }

    private static List<String> strings(Object... args) {
        return java.util.Arrays.stream(args).map(String::valueOf).toList();
    }

    @Override
    public int compareTo(Diagnostic o) {
        return span.compareTo(o.span);
    }
}
