package gcnc.diag;

/**
 * Renders a finding the way GCC does, so editors and CI annotate the line:
 * {@code part.nc:12:7: error[E037]: spindle rotation must be set (M03/M04) before cutting}.
 * A finding in another file (a called program's own file) names that file instead of {@code path}.
 */
public final class GnuRenderer {
    private final Messages messages;

    public GnuRenderer(Messages messages) {
        this.messages = messages;
    }

    public String render(String path, Diagnostic d) {
        String file = d.origin().file() != null ? d.origin().file() : path;
        return file + ":" + d.span().line() + ":" + d.span().column() + ": " + d.severity().label()
                + "[" + d.code().id() + "]: " + messages.render(d.code(), d.args());
    }
}
