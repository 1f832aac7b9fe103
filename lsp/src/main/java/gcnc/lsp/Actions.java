package gcnc.lsp;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionKind;
import org.eclipse.lsp4j.Command;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.TextEdit;
import org.eclipse.lsp4j.WorkspaceEdit;
import org.eclipse.lsp4j.jsonrpc.messages.Either;

/**
 * The code actions on gcnc's diagnostics: "Explain E107" for every one (a command, {@value #EXPLAIN}
 * with the code; it opens {@code gcnc explain E107}'s text), and the fix a
 * finding's own message suggests, with the suggested text from the finding's arguments:
 * E107 "X50 has no decimal point (write X50. ...)" writes the point, E120 "TO303: the letter O in a
 * number (did you mean T0303?)" and E121 "X10,5: a decimal comma (write X10.5)" write the suggestion.
 * A fix is offered only where the buffer still holds the word the finding names, at its place.
 */
final class Actions {
    /** The command that shows a code's explanation: arguments [code]. */
    static final String EXPLAIN = "gcnc.explain";

    private Actions() {
    }

    static List<Either<Command, CodeAction>> of(String uri, List<org.eclipse.lsp4j.Diagnostic> asked, Checks.Published last,
                                                Findings.Lines lines) {
        List<Either<Command, CodeAction>> out = new ArrayList<>();
        List<String> explained = new ArrayList<>();
        for (org.eclipse.lsp4j.Diagnostic shown : asked) {
            if (!"gcnc".equals(shown.getSource()) || shown.getCode() == null || !shown.getCode().isLeft()) {
                continue;
            }
            String code = shown.getCode().getLeft();
            if (!explained.contains(code)) {
                explained.add(code);
                // a bare Command (as the protocol allows): a CodeAction that only holds a command is
                // read as a Command by some clients' libraries (lsprotocol's), which then lose it
                out.add(Either.forLeft(new Command("Explain " + code, EXPLAIN, List.of(code))));
            }
            if (last != null) {
                finding(last, shown).flatMap(d -> fix(d, lines)).ifPresent(edit -> {
                    CodeAction a = new CodeAction(edit.title);
                    a.setKind(CodeActionKind.QuickFix);
                    a.setDiagnostics(List.of(shown));
                    a.setIsPreferred(true);
                    a.setEdit(new WorkspaceEdit(Map.of(uri, List.of(edit.edit))));
                    out.add(Either.forRight(a));
                });
            }
        }
        return out;
    }

    /** The published finding a diagnostic of the client's stands for (the same code at the same place). */
    private static Optional<Diagnostic> finding(Checks.Published last, org.eclipse.lsp4j.Diagnostic shown) {
        for (Findings.Shown s : last.shown()) {
            org.eclipse.lsp4j.Diagnostic o = s.diagnostic();
            if (o.getCode().equals(shown.getCode()) && o.getRange().getStart().equals(shown.getRange().getStart())
                    && s.finding().origin().file() == null) {
                return Optional.of(s.finding());
            }
        }
        return Optional.empty();
    }

    private record Fix(String title, TextEdit edit) {
    }

    /** The fix the finding's message suggests, if the buffer still holds the word it names. */
    private static Optional<Fix> fix(Diagnostic d, Findings.Lines lines) {
        List<String> a = d.args();
        String with;
        if (d.code() == Code.E107_NO_DECIMAL_POINT && !a.isEmpty()) {
            with = a.get(0) + ".";
        } else if ((d.code() == Code.E120_LETTER_O_IN_NUMBER || d.code() == Code.E121_DECIMAL_COMMA) && a.size() > 1) {
            with = a.get(1);
        } else {
            return Optional.empty();
        }
        String word = a.get(0);
        String line = lines.line(d.span().line());
        int from = d.span().column() - 1;
        if (!line.startsWith(word, from)) {
            return Optional.empty();
        }
        Range r = new Range(new Position(d.span().line() - 1, from), new Position(d.span().line() - 1, from + word.length()));
        return Optional.of(new Fix("Write " + with + " (" + d.code().id() + ")", new TextEdit(r, with)));
    }
}
