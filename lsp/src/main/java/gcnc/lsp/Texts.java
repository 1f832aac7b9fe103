package gcnc.lsp;

import gcnc.ModalStates;
import gcnc.Session;
import gcnc.ir.Word;
import java.io.IOException;
import java.io.StringReader;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import org.eclipse.lsp4j.CodeAction;
import org.eclipse.lsp4j.CodeActionParams;
import org.eclipse.lsp4j.Command;
import org.eclipse.lsp4j.DefinitionParams;
import org.eclipse.lsp4j.DidChangeTextDocumentParams;
import org.eclipse.lsp4j.DidCloseTextDocumentParams;
import org.eclipse.lsp4j.DidOpenTextDocumentParams;
import org.eclipse.lsp4j.DidSaveTextDocumentParams;
import org.eclipse.lsp4j.DocumentSymbol;
import org.eclipse.lsp4j.DocumentSymbolParams;
import org.eclipse.lsp4j.Hover;
import org.eclipse.lsp4j.HoverParams;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.LocationLink;
import org.eclipse.lsp4j.MarkupContent;
import org.eclipse.lsp4j.MarkupKind;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.ReferenceParams;
import org.eclipse.lsp4j.SymbolInformation;
import org.eclipse.lsp4j.TextDocumentContentChangeEvent;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.TextDocumentService;

/**
 * The buffers (opened, changed as a whole text, closed) and what the editor asks about them: hover,
 * definition, references, symbols, code actions. Each answer is made from the buffer's text as the
 * client last sent it, with the session its check uses.
 */
final class Texts implements TextDocumentService {
    private final Map<String, Doc> docs;
    /** The checks in force (initialize replaces them with the client's language). */
    private final java.util.function.Supplier<Checks> checks;
    private final Config config;
    /** The modal states of the last buffer hovered before its check was done, kept while its text is the same. */
    private Doc statesOf;
    private Map<Integer, ModalStates.Snapshot> states = Map.of();

    Texts(Map<String, Doc> docs, java.util.function.Supplier<Checks> checks, Config config) {
        this.docs = docs;
        this.checks = checks;
        this.config = config;
    }

    @Override
    public void didOpen(DidOpenTextDocumentParams params) {
        var t = params.getTextDocument();
        docs.put(t.getUri(), Doc.of(t.getUri(), t.getText() == null ? "" : t.getText(), t.getVersion()));
        checks.get().changed(t.getUri());
    }

    @Override
    public void didChange(DidChangeTextDocumentParams params) {
        String uri = params.getTextDocument().getUri();
        Doc d = docs.get(uri);
        List<TextDocumentContentChangeEvent> changes = params.getContentChanges();
        if (d == null || changes.isEmpty()) {
            return;
        }
        // full synchronisation (the capability this server announces): the last change is the whole text
        TextDocumentContentChangeEvent last = changes.get(changes.size() - 1);
        Integer version = params.getTextDocument().getVersion();
        docs.put(uri, d.edited(last.getText() == null ? "" : last.getText(), version == null ? d.version() : version));
        checks.get().changed(uri);
    }

    @Override
    public void didClose(DidCloseTextDocumentParams params) {
        String uri = params.getTextDocument().getUri();
        docs.remove(uri);
        checks.get().closed(uri);
    }

    @Override
    public void didSave(DidSaveTextDocumentParams params) {
        // the buffer's text is already what was checked; a called file saved changes what its callers find
        for (String uri : docs.keySet()) {
            if (!uri.equals(params.getTextDocument().getUri())) {
                checks.get().changed(uri);
            }
        }
    }

    /** The session and outline a buffer's answers use; empty when the buffer is not open or its profile is broken. */
    private Optional<Answering> answering(String uri) throws IOException {
        Doc d = docs.get(uri);
        if (d == null || d.text().length() > Checks.MAX_TEXT) {
            return Optional.empty();
        }
        Config.Resolved r = config.resolve(d.folder());
        if (r.session().isEmpty()) {
            return Optional.empty();
        }
        Session s = r.session().get().withPrograms(d.folder());
        return Optional.of(new Answering(d, s, Outline.of(d.text(), s.profile().control())));
    }

    private record Answering(Doc doc, Session session, Outline outline) {
    }

    @Override
    public CompletableFuture<Hover> hover(HoverParams params) {
        return CompletableFuture.supplyAsync(() -> hover(params.getTextDocument().getUri(),
                params.getPosition().getLine() + 1, params.getPosition().getCharacter() + 1));
    }

    private Hover hover(String uri, int line, int column) {
        try {
            Optional<Answering> a = answering(uri);
            if (a.isEmpty()) {
                return null;
            }
            Answering at = a.get();
            StringBuilder md = new StringBuilder();
            Optional<Word> w = at.outline().wordAt(line, column);
            w.flatMap(word -> Hovers.function(at.session().profile(), word.letter().name() + word.number(), checks.get().lang()))
                    .ifPresent(text -> md.append(text).append("\n\n"));
            ModalStates.Snapshot s = states(at).get(line);
            if (s != null) {
                md.append(Hovers.state(s, at.session().profile()));
            }
            if (md.length() == 0) {
                return null;
            }
            Hover h = new Hover(new MarkupContent(MarkupKind.MARKDOWN, md.toString().strip()));
            w.ifPresent(word -> h.setRange(Navigation.range(word)));
            return h;
        } catch (IOException e) {
            return null;
        }
    }

    /** The states the buffer's check saw; a hover that comes before that check checks the text itself. */
    private synchronized Map<Integer, ModalStates.Snapshot> states(Answering a) throws IOException {
        Optional<Map<Integer, ModalStates.Snapshot>> checked = checks.get().states(a.doc());
        if (checked.isPresent()) {
            return checked.get();
        }
        if (statesOf != a.doc()) {
            states = ModalStates.of(a.session(), new StringReader(a.doc().text()));
            statesOf = a.doc();
        }
        return states;
    }

    @Override
    public CompletableFuture<Either<List<? extends Location>, List<? extends LocationLink>>> definition(DefinitionParams params) {
        Position at = params.getPosition();
        return answer(params.getTextDocument().getUri(), Either.forLeft(List.of()),
                a -> Either.forLeft(Navigation.definition(a.outline(), a.doc(), at.getLine() + 1, at.getCharacter() + 1)));
    }

    @Override
    public CompletableFuture<List<? extends Location>> references(ReferenceParams params) {
        boolean declaration = params.getContext() == null || params.getContext().isIncludeDeclaration();
        Position at = params.getPosition();
        return answer(params.getTextDocument().getUri(), List.of(),
                a -> Navigation.references(a.outline(), a.doc(), at.getLine() + 1, at.getCharacter() + 1, declaration));
    }

    @Override
    public CompletableFuture<List<Either<SymbolInformation, DocumentSymbol>>> documentSymbol(DocumentSymbolParams params) {
        return answer(params.getTextDocument().getUri(), List.of(),
                a -> Navigation.symbols(a.outline(), new Findings.Lines(a.doc().text()), checks.get().lang()).stream()
                        .map(Either::<SymbolInformation, DocumentSymbol>forRight).toList());
    }

    /**
     * An answer about a buffer, made on a pool thread from its {@link Answering}; {@code none} when the
     * buffer is not open, its profile is broken, or a file could not be read.
     */
    private <T> CompletableFuture<T> answer(String uri, T none, java.util.function.Function<Answering, T> make) {
        return CompletableFuture.supplyAsync(() -> {
            try {
                return answering(uri).map(make).orElse(none);
            } catch (IOException e) {
                return none;
            }
        });
    }

    @Override
    public CompletableFuture<List<Either<Command, CodeAction>>> codeAction(CodeActionParams params) {
        return CompletableFuture.supplyAsync(() -> {
            String uri = params.getTextDocument().getUri();
            Doc d = docs.get(uri);
            if (d == null || params.getContext() == null || params.getContext().getDiagnostics() == null) {
                return List.of();
            }
            Checks.Published last = checks.get().published(uri).filter(p -> p.doc() == d).orElse(null);
            return Actions.of(uri, params.getContext().getDiagnostics(), last, new Findings.Lines(d.text()));
        });
    }
}
