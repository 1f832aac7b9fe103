package gcnc.lsp;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Messages;
import gcnc.diag.Origin;
import gcnc.diag.Severity;
import gcnc.diag.Span;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Function;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.eclipse.lsp4j.DiagnosticCodeDescription;
import org.eclipse.lsp4j.DiagnosticRelatedInformation;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;

/**
 * gcnc's findings as the editor's diagnostics, one for one and in the order {@code gcnc check
 * --format json} lists them (file, line, column): the code (E107) linked to its explanation, the
 * rendered message, a range from the finding's column to its end, the message's arguments as the
 * diagnostic's data (the code actions read the suggested text from them), and related information
 * where the finding names another line: the later lines of an E115, the call of an E136.
 *
 * <p>A finding in a called program's own file ({@code O1000.nc}) is shown at the call in this
 * buffer (the outermost call written here), its message prefixed with the place in that file, which
 * is also its related information; the notes naming the calls (E136, E144, E145) are that same
 * information and are not repeated.
 */
final class Findings {
    /** A line number in an E115's list ("5, 7, 12, ..."). */
    private static final Pattern NUMBER = Pattern.compile("\\d+");

    private final Messages messages;
    /** Where each code's explanation is (a file the server wrote, or a page), or empty. */
    private final Function<Code, Optional<String>> explanation;

    Findings(Messages messages, Function<Code, Optional<String>> explanation) {
        this.messages = messages;
        this.explanation = explanation;
    }

    /** A finding and the diagnostic the editor is shown for it. */
    record Shown(Diagnostic finding, org.eclipse.lsp4j.Diagnostic diagnostic) {
    }

    /**
     * The diagnostics of one check of the buffer {@code uri} (its {@code text}; called files looked
     * for in {@code folder}), in the order of {@code sorted}.
     */
    List<Shown> of(List<Diagnostic> sorted, String uri, String text, Optional<Path> folder, Outline outline) {
        Lines lines = new Lines(text);
        List<Shown> out = new ArrayList<>();
        for (Diagnostic d : sorted) {
            String other = d.origin().file();
            if (other == null) {
                out.add(new Shown(d, own(d, uri, lines)));
            } else if (!callNote(d.code())) {
                out.add(new Shown(d, elsewhere(d, other, uri, lines, folder, outline)));
            }
        }
        return out;
    }

    private static boolean callNote(Code c) {
        return c == Code.E136_CALLED_FROM || c == Code.E144_CALLED_FROM_FILE || c == Code.E145_CALLED_FROM_PROGRAM_FILE;
    }

    private org.eclipse.lsp4j.Diagnostic own(Diagnostic d, String uri, Lines lines) {
        org.eclipse.lsp4j.Diagnostic o = base(d, lines.range(d.span()), messages.render(d.code(), d.args()));
        List<DiagnosticRelatedInformation> related = new ArrayList<>();
        if (d.code() == Code.E115_SAME_CAUSE && d.args().size() > 1) {
            Matcher m = NUMBER.matcher(d.args().get(1));
            while (m.find()) {
                int line = Integer.parseInt(m.group());
                related.add(new DiagnosticRelatedInformation(new Location(uri, lines.wholeLine(line)),
                        "the same cause at line " + line));
            }
        }
        if (d.code() == Code.E136_CALLED_FROM && d.args().size() > 1) {
            int line = parse(d.args().get(1));
            if (line > 0) {
                related.add(new DiagnosticRelatedInformation(new Location(uri, lines.wholeLine(line)),
                        "the call: " + (d.args().size() > 2 ? d.args().get(2) : "")));
            }
        }
        if (!related.isEmpty()) {
            o.setRelatedInformation(related);
        }
        return o;
    }

    /** A finding in another file, shown at the call of that file in this buffer. */
    private org.eclipse.lsp4j.Diagnostic elsewhere(Diagnostic d, String file, String uri, Lines lines,
                                                  Optional<Path> folder, Outline outline) {
        int callLine = 0;
        String callWords = null;
        List<Origin.Call> calls = d.origin().calls();
        for (int i = calls.size() - 1; i >= 0; i--) { // innermost first: the outermost written in this buffer
            if (calls.get(i).file() == null) {
                callLine = calls.get(i).line();
                callWords = calls.get(i).words();
                break;
            }
        }
        Path path = folder.map(f -> f.resolve(file)).orElse(Path.of(file));
        if (callLine == 0) { // the parser's findings in a called file carry no call: a block of this buffer that calls it
            for (Outline.Reference r : outline.references()) {
                if (r.target() == Outline.Target.PROGRAM && folder.isPresent()
                        && gcnc.flow.Library.fileFor(folder.get(), r.number()).map(p -> p.equals(path)).orElse(false)) {
                    callLine = r.block().line();
                    break;
                }
            }
        }
        String place = path.getFileName() + ":" + d.span().line() + ":" + d.span().column();
        Range at = callLine > 0 ? lines.wholeLine(callLine) : lines.range(Span.of(1, 1));
        org.eclipse.lsp4j.Diagnostic o = base(d, at, place + ": " + messages.render(d.code(), d.args())
                + (callWords != null ? " (" + callWords + ")" : ""));
        Range there = new Range(new Position(d.span().line() - 1, d.span().column() - 1),
                new Position(d.span().line() - 1, (d.span().hasEnd() ? d.span().endColumn() : d.span().column() + 1) - 1));
        o.setRelatedInformation(List.of(new DiagnosticRelatedInformation(
                new Location(path.toUri().toString(), there), messages.render(d.code(), d.args()))));
        return o;
    }

    private org.eclipse.lsp4j.Diagnostic base(Diagnostic d, Range range, String message) {
        org.eclipse.lsp4j.Diagnostic o = new org.eclipse.lsp4j.Diagnostic(range, message, severity(d.severity()), "gcnc",
                d.code().id());
        explanation.apply(d.code()).ifPresent(href -> o.setCodeDescription(new DiagnosticCodeDescription(href)));
        o.setData(messages.arguments(d.args()));
        return o;
    }

    static DiagnosticSeverity severity(Severity s) {
        return switch (s) {
            case ERROR -> DiagnosticSeverity.Error;
            case WARNING -> DiagnosticSeverity.Warning;
            case NOTE -> DiagnosticSeverity.Information;
        };
    }

    private static int parse(String s) {
        try {
            return Integer.parseInt(s.strip());
        } catch (NumberFormatException e) {
            return 0;
        }
    }

    /** The buffer's lines, for ranges: a finding without an end covers its word (up to a blank or the line's end). */
    static final class Lines {
        private final String text;
        private final List<Integer> starts = new ArrayList<>();

        Lines(String text) {
            this.text = text;
            starts.add(0);
            for (int i = 0; i < text.length(); i++) {
                char c = text.charAt(i);
                if (c == '\n' || c == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n')) {
                    starts.add(i + 1);
                }
            }
        }

        /** Line {@code n} (1-based) without its line end, or "" past the text. */
        String line(int n) {
            if (n < 1 || n > starts.size()) {
                return "";
            }
            int from = starts.get(n - 1);
            int to = n < starts.size() ? starts.get(n) : text.length();
            while (to > from && (text.charAt(to - 1) == '\n' || text.charAt(to - 1) == '\r')) {
                to--;
            }
            return text.substring(from, to);
        }

        Range range(Span s) {
            int line = s.line() - 1;
            int start = s.column() - 1;
            int end;
            if (s.hasEnd()) {
                end = s.endColumn() - 1;
            } else {
                String t = line(s.line());
                end = start;
                while (end < t.length() && !Character.isWhitespace(t.charAt(end))) {
                    end++;
                }
                end = Math.max(end, start + 1);
            }
            return new Range(new Position(line, start), new Position(line, end));
        }

        Range wholeLine(int n) {
            return new Range(new Position(n - 1, 0), new Position(n - 1, line(n).length()));
        }
    }
}
