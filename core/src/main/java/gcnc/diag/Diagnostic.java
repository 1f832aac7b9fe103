package gcnc.diag;

import java.util.List;

/**
 * One finding: a stable code, where it is, and the values its message template needs.
 * The text is never built here; {@link Messages} renders it in the user's language.
 * {@code origin} says which file and which subprogram calls the span belongs to when that is not
 * the program file as written ({@link Origin#PROGRAM}). {@code waiver} is the reason of the shop's
 * waiver that accepts it ({@code (GCNC ALLOW E642: reason)}, {@link Waivers}), or null: a waived
 * finding is still reported, as waived, and counts as neither an error nor a warning.
 */
public record Diagnostic(Code code, Severity severity, Span span, List<String> args, Origin origin, String waiver)
        implements Comparable<Diagnostic> {
    public Diagnostic {
        args = List.copyOf(args);
        java.util.Objects.requireNonNull(origin);
    }

    /** A finding no waiver accepts. */
    public Diagnostic(Code code, Severity severity, Span span, List<String> args, Origin origin) {
        this(code, severity, span, args, origin, null);
    }

    /** Whether a waiver accepts it (then {@link #waiver} is its reason). */
    public boolean waived() {
        return waiver != null;
    }

    /** The same finding accepted by a waiver that gives {@code reason}. */
    public Diagnostic waivedFor(String reason) {
        return new Diagnostic(code, severity, span, args, origin, java.util.Objects.requireNonNull(reason));
    }

    /** A finding not yet placed: the collection it is reported to says where it is ({@link Diagnostics#report}). */
    public Diagnostic(Code code, Severity severity, Span span, List<String> args) {
        this(code, severity, span, args, Origin.UNPLACED);
    }

    public static Diagnostic error(Code code, Span span, Object... args) {
        return new Diagnostic(code, Severity.ERROR, span, strings(args));
    }

    public static Diagnostic warning(Code code, Span span, Object... args) {
        return new Diagnostic(code, Severity.WARNING, span, strings(args));
    }

    /** The same finding placed in {@code o}. */
    public Diagnostic in(Origin o) {
        return new Diagnostic(code, severity, span, args, o, waiver);
    }

    private static List<String> strings(Object... args) {
        return java.util.Arrays.stream(args).map(String::valueOf).toList();
    }

    /** The program file first, then other files by name; in a file, by position. */
    @Override
    public int compareTo(Diagnostic o) {
        String a = origin.file();
        String b = o.origin.file();
        if (a == null ? b != null : !a.equals(b)) {
            return a == null ? -1 : b == null ? 1 : a.compareTo(b);
        }
        return span.compareTo(o.span);
    }
}
