package gcnc.lsp;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import gcnc.diag.Code;
import gcnc.tables.ErrorMessages;
import java.net.URI;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import org.eclipse.lsp4j.CodeActionKind;
import org.eclipse.lsp4j.CodeActionOptions;
import org.eclipse.lsp4j.DidChangeConfigurationParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesParams;
import org.eclipse.lsp4j.DidChangeWatchedFilesRegistrationOptions;
import org.eclipse.lsp4j.ExecuteCommandOptions;
import org.eclipse.lsp4j.ExecuteCommandParams;
import org.eclipse.lsp4j.FileSystemWatcher;
import org.eclipse.lsp4j.InitializeParams;
import org.eclipse.lsp4j.InitializeResult;
import org.eclipse.lsp4j.InitializedParams;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.Registration;
import org.eclipse.lsp4j.RegistrationParams;
import org.eclipse.lsp4j.ServerCapabilities;
import org.eclipse.lsp4j.ServerInfo;
import org.eclipse.lsp4j.ShowDocumentParams;
import org.eclipse.lsp4j.TextDocumentSyncKind;
import org.eclipse.lsp4j.TextDocumentSyncOptions;
import org.eclipse.lsp4j.WorkspaceFolder;
import org.eclipse.lsp4j.jsonrpc.messages.Either;
import org.eclipse.lsp4j.services.LanguageClient;
import org.eclipse.lsp4j.services.LanguageClientAware;
import org.eclipse.lsp4j.services.LanguageServer;
import org.eclipse.lsp4j.services.TextDocumentService;
import org.eclipse.lsp4j.services.WorkspaceService;

/**
 * {@code gcnc lsp}: the language server's lifecycle (initialize, shutdown, exit), its settings
 * (initializationOptions and workspace/didChangeConfiguration, under a {@code "gcnc"} key or not),
 * the watched files (a {@code .gcnc}, a profile or a table changed: every open buffer is checked
 * again) and the explain command. docs/editors.md describes each setting.
 */
public final class LspServer implements LanguageServer, LanguageClientAware {
    private final Map<String, Doc> docs = new ConcurrentHashMap<>();
    private final Config config = new Config();
    private final FolderSettings base;
    private final ExplainFilesFactory explainFiles;
    private final Log log;
    private final String version;
    private ExplainFiles explain;
    /** Replaced by initialize (the client's language); {@link #texts} reads the one in force. */
    private volatile Checks checks;
    private final Texts texts;
    private volatile LanguageClient client;
    private volatile boolean showDocument;
    private volatile boolean watchedFiles;
    private final CompletableFuture<Integer> exited = new CompletableFuture<>();
    private volatile boolean shutdown;

    /** How the explanation files are made once the language and the folder are known. */
    @FunctionalInterface
    interface ExplainFilesFactory {
        ExplainFiles make(ErrorMessages.Lang lang, Optional<Path> folder, Log log);
    }

    LspServer(FolderSettings base, ErrorMessages.Lang lang, String version, ExplainFilesFactory explainFiles, Log log) {
        this.base = base;
        this.version = version;
        this.explainFiles = explainFiles;
        this.log = log;
        this.explain = explainFiles.make(lang, Optional.empty(), log);
        this.checks = new Checks(docs, config, explain, lang, log);
        this.texts = new Texts(docs, () -> checks, config);
        config.client(base);
    }

    /** Completes with the exit status when the client sends exit: 0 after shutdown, else 1 (as the protocol says). */
    CompletableFuture<Integer> exited() {
        return exited;
    }

    @Override
    public void connect(LanguageClient c) {
        client = c;
        checks.connect(c);
    }

    @Override
    @SuppressWarnings("deprecation") // rootUri: the clients that send no workspace folders send it
    public CompletableFuture<InitializeResult> initialize(InitializeParams params) {
        List<Path> roots = new ArrayList<>();
        if (params.getWorkspaceFolders() != null) {
            for (WorkspaceFolder f : params.getWorkspaceFolders()) {
                path(f.getUri()).ifPresent(roots::add);
            }
        }
        if (roots.isEmpty() && params.getRootUri() != null) {
            path(params.getRootUri()).ifPresent(roots::add);
        }
        config.roots(roots);
        JsonObject options = object(params.getInitializationOptions());
        if (options != null) {
            ErrorMessages.Lang lang = checks.lang();
            if (options.has("lang") && options.get("lang").isJsonPrimitive()) {
                lang = "es".equals(options.get("lang").getAsString()) ? ErrorMessages.Lang.ES : ErrorMessages.Lang.EN;
            }
            Optional<Path> folder = options.has("explainFolder") && options.get("explainFolder").isJsonPrimitive()
                    ? Optional.of(Path.of(options.get("explainFolder").getAsString())) : Optional.empty();
            explain = explainFiles.make(lang, folder, log);
            checks.stop();
            checks = new Checks(docs, config, explain, lang, log);
            checks.connect(client);
            settings(options);
        }
        var caps = params.getCapabilities();
        showDocument = caps != null && caps.getWindow() != null && caps.getWindow().getShowDocument() != null
                && caps.getWindow().getShowDocument().isSupport();
        watchedFiles = caps != null && caps.getWorkspace() != null && caps.getWorkspace().getDidChangeWatchedFiles() != null
                && Boolean.TRUE.equals(caps.getWorkspace().getDidChangeWatchedFiles().getDynamicRegistration());
        ServerCapabilities c = new ServerCapabilities();
        TextDocumentSyncOptions sync = new TextDocumentSyncOptions();
        sync.setOpenClose(true);
        sync.setChange(TextDocumentSyncKind.Full);
        sync.setSave(Either.forLeft(true));
        c.setTextDocumentSync(sync);
        c.setHoverProvider(true);
        c.setDefinitionProvider(true);
        c.setReferencesProvider(true);
        c.setDocumentSymbolProvider(true);
        c.setCodeActionProvider(new CodeActionOptions(List.of(CodeActionKind.QuickFix, CodeActionKind.Empty)));
        c.setExecuteCommandProvider(new ExecuteCommandOptions(List.of(Actions.EXPLAIN)));
        return CompletableFuture.completedFuture(new InitializeResult(c, new ServerInfo("gcnc", version)));
    }

    /** Settings from the client: machine, control, tables; checkDelayMs, simulateAfterMs. */
    private void settings(JsonObject o) {
        JsonObject s = o.has("gcnc") && o.get("gcnc").isJsonObject() ? o.getAsJsonObject("gcnc") : o;
        FolderSettings given = FolderSettings.fromClient(s);
        config.client(new FolderSettings(given.machine().or(base::machine), given.control().or(base::control),
                given.tables().or(base::tables), Optional.empty(), List.of()));
        long delay = number(s, "checkDelayMs", 10);
        long simulate = number(s, "simulateAfterMs", 500);
        checks.timing(delay, simulate);
    }

    private static long number(JsonObject o, String key, long otherwise) {
        JsonElement e = o.get(key);
        return e != null && e.isJsonPrimitive() && e.getAsJsonPrimitive().isNumber() ? e.getAsLong() : otherwise;
    }

    private static JsonObject object(Object o) {
        return o instanceof JsonObject j ? j : null;
    }

    private static Optional<Path> path(String uri) {
        try {
            URI u = URI.create(uri);
            return "file".equals(u.getScheme()) ? Optional.of(Path.of(u)) : Optional.empty();
        } catch (IllegalArgumentException e) {
            return Optional.empty();
        }
    }

    @Override
    public void initialized(InitializedParams params) {
        if (watchedFiles && client != null) {
            List<FileSystemWatcher> w = List.of(new FileSystemWatcher(Either.forLeft("**/" + FolderSettings.FILE)),
                    new FileSystemWatcher(Either.forLeft("**/*.machine")), new FileSystemWatcher(Either.forLeft("**/*.csv")));
            client.registerCapability(new RegistrationParams(List.of(new Registration("gcnc-profiles",
                    "workspace/didChangeWatchedFiles", new DidChangeWatchedFilesRegistrationOptions(w)))));
        }
    }

    /** Whether the client asked for shutdown (an end of input after it is a clean stop). */
    boolean shutdownReceived() {
        return shutdown;
    }

    @Override
    public CompletableFuture<Object> shutdown() {
        shutdown = true;
        return CompletableFuture.completedFuture(null);
    }

    @Override
    public void exit() {
        checks.stop();
        exited.complete(shutdown ? 0 : 1);
    }

    @Override
    public TextDocumentService getTextDocumentService() {
        return texts; // one for the server's life: it reads the checks initialize put in force
    }

    @Override
    public WorkspaceService getWorkspaceService() {
        return new WorkspaceService() {
            @Override
            public void didChangeConfiguration(DidChangeConfigurationParams params) {
                JsonObject o = object(params.getSettings());
                if (o != null) {
                    settings(o);
                }
                checks.recheckAll();
            }

            @Override
            public void didChangeWatchedFiles(DidChangeWatchedFilesParams params) {
                checks.recheckAll();
            }

            @Override
            public CompletableFuture<Object> executeCommand(ExecuteCommandParams params) {
                return CompletableFuture.supplyAsync(() -> explain(params));
            }
        };
    }

    /** E107 (or 107) as a code of this gcnc, if it is one. */
    private static Optional<Code> code(String id) {
        String digits = id.strip().toUpperCase(java.util.Locale.ROOT);
        digits = digits.startsWith("E") ? digits.substring(1) : digits;
        try {
            return Optional.of(Code.byNumber(Integer.parseInt(digits)));
        } catch (IllegalArgumentException e) {
            return Optional.empty();
        }
    }

    /** gcnc.explain [code]: opens the explanation's file in the editor (or shows its text), and answers the text. */
    private Object explain(ExecuteCommandParams params) {
        if (!Actions.EXPLAIN.equals(params.getCommand()) || params.getArguments() == null || params.getArguments().isEmpty()) {
            return null;
        }
        Object a = params.getArguments().get(0);
        String id = a instanceof JsonElement e && e.isJsonPrimitive() ? e.getAsString() : String.valueOf(a);
        Optional<Code> code = code(id);
        if (code.isEmpty()) {
            log.error("gcnc.explain: no code " + id);
            return null;
        }
        String text = explain.text(code.get());
        Optional<String> uri = explain.uri(code.get());
        LanguageClient c = client;
        if (c != null) {
            if (showDocument && uri.isPresent()) {
                ShowDocumentParams p = new ShowDocumentParams(uri.get());
                p.setTakeFocus(true);
                c.showDocument(p);
            } else {
                c.showMessage(new MessageParams(MessageType.Info, text));
            }
        }
        return text;
    }
}
