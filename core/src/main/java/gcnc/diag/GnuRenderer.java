package gcnc.diag;

import java.util.List;

/**
 * Renders a finding the way GCC does, so editors and CI annotate the line:
 * {@code part.nc:12:7: error[E037]: spindle rotation must be set (M03/M04) before cutting}.
 * A finding in another file (a called program's own file) names that file instead of {@code path}.
 * A report ends, as rustc's does, with one line that names a code to read more about
 * ({@link #hint}).
 */
public final class GnuRenderer {
    private final Messages messages;

    public GnuRenderer(Messages messages) {
        this.messages = messages;
    }

    public String render(String path, Diagnostic d) {
        return render(path, d, PLAIN);
    }

    /**
     * How the pieces of a line are shown: as they are ({@link #PLAIN}), or escaped and coloured by
     * a front end on a terminal (the command line's colours; the line's text stays the same).
     */
    public interface Paint {
        String place(String text);

        String severity(Severity s, String label);

        String text(String text);
    }

    public static final Paint PLAIN = new Paint() {
        @Override
        public String place(String text) {
            return text;
        }

        @Override
        public String severity(Severity s, String label) {
            return label;
        }

        @Override
        public String text(String text) {
            return text;
        }
    };

    /**
     * A waived finding is a note that says so and gives the waiver's reason before its message:
     * {@code part.nc:12:7: note[E642] waived: the shop's G70 carries U: G70: U0.5 does nothing in a G70: ...}.
     */
    public String render(String path, Diagnostic d, Paint paint) {
        String file = d.origin().file() != null ? d.origin().file() : path;
        String message = messages.render(d.code(), d.args());
        Severity shown = d.waived() ? Severity.NOTE : d.severity();
        String text = d.waived() ? messages.arguments(List.of(Phrase.WAIVED.with(d.waiver(), message))).get(0) : message;
        return paint.place(file + ":" + d.span().line() + ":" + d.span().column() + ":") + " "
                + paint.severity(shown, shown.label())
                + paint.text("[" + d.code().id() + "]" + (d.waived() ? " " : ": ") + text);
    }

    /**
     * The report's last line, once per run: "For more information about this error try `gcnc
     * explain E037`." for the code {@link Hint} chose (the first error, else the first warning).
     */
    public String hint(Diagnostic chosen) {
        Phrase p = chosen.severity() == Severity.ERROR ? Phrase.EXPLAIN_HINT_ERROR : Phrase.EXPLAIN_HINT_WARNING;
        return messages.arguments(List.of(p.with(chosen.code().id()))).get(0);
    }

    /**
     * Which finding of a run the closing hint names: the first error reported, else the first
     * warning; notes never (they go with another finding). One per run, whatever the number of files.
     */
    public static final class Hint {
        private Diagnostic chosen;

        /** Takes note of a finding as it is reported. */
        public void saw(Diagnostic d) {
            if (d.severity() == Severity.NOTE || d.waived()) {
                return;
            }
            if (chosen == null || chosen.severity() != Severity.ERROR && d.severity() == Severity.ERROR) {
                chosen = d;
            }
        }

        /** The finding to name, if the run had an error or a warning. */
        public java.util.Optional<Diagnostic> chosen() {
            return java.util.Optional.ofNullable(chosen);
        }
    }
}
