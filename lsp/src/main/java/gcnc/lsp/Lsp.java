package gcnc.lsp;

import gcnc.tables.ErrorMessages;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Optional;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.Future;
import java.util.function.BiFunction;
import java.util.logging.Handler;
import java.util.logging.Level;
import java.util.logging.LogRecord;
import java.util.logging.Logger;
import org.eclipse.lsp4j.MessageParams;
import org.eclipse.lsp4j.MessageType;
import org.eclipse.lsp4j.jsonrpc.Launcher;
import org.eclipse.lsp4j.jsonrpc.ResponseErrorException;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseError;
import org.eclipse.lsp4j.jsonrpc.messages.ResponseErrorCode;
import org.eclipse.lsp4j.launch.LSPLauncher;
import org.eclipse.lsp4j.services.LanguageClient;

/**
 * Runs the language server on a pair of streams (the command line's {@code gcnc lsp}: standard input
 * and output) until the client sends exit or closes its end. Nothing but the protocol is written to
 * {@code out}; every problem is one line on {@code err} and, once the client is connected, a
 * window/logMessage: a malformed message, a message past the input limit, a client that does not
 * read (its output queue past the output limit), a fault while checking.
 */
public final class Lsp {
    /**
     * What the command line gives the server.
     *
     * @param machine     the profile ({@code --machine}), under the client's settings and a .gcnc file
     * @param control     the control ({@code --control}), likewise
     * @param tables      the tables ({@code --tables}), likewise
     * @param lang        the language of the messages (the client's initializationOptions may change it)
     * @param version     gcnc's version, for the client's serverInfo and the explanations' folder
     * @param explain     {@code gcnc explain CODE}'s text for a code and a language
     * @param inputLimit  the longest message read, in bytes (a longer one is skipped)
     * @param outputLimit the most bytes kept for a client that does not read
     */
    public record Options(Optional<String> machine, Optional<String> control, Optional<Path> tables, ErrorMessages.Lang lang,
                          String version, BiFunction<String, ErrorMessages.Lang, String> explain, long inputLimit,
                          long outputLimit) {
        /** 64 MiB: a 16 Mi-character buffer (the most checked, {@link Checks#MAX_TEXT}) in JSON with room to spare. */
        public static final long INPUT_LIMIT = 64L << 20;
        /** 32 MiB of answers waiting for a client that does not read. */
        public static final long OUTPUT_LIMIT = 32L << 20;
    }

    private Lsp() {
    }

    /** Serves until exit (status 0 after shutdown, else 1) or the end of {@code in} (0 after shutdown, else 1). */
    public static int run(InputStream in, OutputStream out, PrintWriter err, Options o) throws InterruptedException {
        ClientLog log = new ClientLog(err);
        Log stderrOnly = log.stderrOnly();
        FolderSettings base = new FolderSettings(o.machine(), o.control(), o.tables(), Optional.empty(), java.util.List.of());
        LspServer server = new LspServer(base, o.lang(), o.version(),
                (lang, folder, l) -> new ExplainFiles(code -> o.explain().apply(code, lang),
                        folder.orElse(ExplainFiles.defaultFolder(o.version(), lang.name().toLowerCase(java.util.Locale.ROOT))), l),
                log);
        Framing.QueuedOutput queued = new Framing.QueuedOutput(out, o.outputLimit(), stderrOnly);
        Logger lsp4j = Logger.getLogger("org.eclipse.lsp4j");
        lsp4j.setUseParentHandlers(false);
        lsp4j.addHandler(log);
        Launcher<LanguageClient> launcher = new LSPLauncher.Builder<LanguageClient>()
                .setLocalService(server)
                .setRemoteInterface(LanguageClient.class)
                .setInput(new Framing.GuardedInput(in, o.inputLimit(), log))
                .setOutput(queued)
                .setExceptionHandler(t -> {
                    Throwable cause = t instanceof java.util.concurrent.CompletionException && t.getCause() != null ? t.getCause() : t;
                    if (cause instanceof ResponseErrorException r) { // the protocol's own answer (an unknown method)
                        return r.getResponseError();
                    }
                    log.error("a request failed: " + cause);
                    return new ResponseError(ResponseErrorCode.InternalError, "gcnc: " + cause, null);
                })
                .create();
        LanguageClient client = launcher.getRemoteProxy();
        server.connect(client);
        log.connect(client);
        Future<Void> listening = launcher.startListening();
        CompletableFuture<Integer> ended = new CompletableFuture<>();
        server.exited().thenAccept(ended::complete);
        Thread waiter = new Thread(() -> {
            try {
                listening.get();
            } catch (Exception e) {
                // the input ended or failed: as at its end
            }
            ended.complete(server.shutdownReceived() ? 0 : 1);
        }, "gcnc-lsp-input");
        waiter.setDaemon(true);
        waiter.start();
        int status;
        try {
            status = ended.get();
        } catch (java.util.concurrent.ExecutionException e) {
            status = 1;
        }
        queued.drain(2000);
        lsp4j.removeHandler(log);
        return status;
    }

    /** Lines on standard error and, once connected, window/logMessage; also LSP4J's own log records. */
    private static final class ClientLog extends Handler implements Log {
        private final PrintWriter err;
        private volatile LanguageClient client;
        private final ThreadLocal<Boolean> inside = ThreadLocal.withInitial(() -> false);

        ClientLog(PrintWriter err) {
            this.err = err;
        }

        void connect(LanguageClient c) {
            client = c;
        }

        Log stderrOnly() {
            return new Log() {
                @Override
                public void error(String line) {
                    line(line);
                }

                @Override
                public void info(String line) {
                    line(line);
                }
            };
        }

        private void line(String text) {
            synchronized (err) {
                err.println("gcnc lsp: " + text.replace('\n', ' '));
                err.flush();
            }
        }

        @Override
        public void error(String text) {
            say(MessageType.Error, text);
        }

        @Override
        public void info(String text) {
            say(MessageType.Info, text);
        }

        private void say(MessageType type, String text) {
            line(text);
            LanguageClient c = client;
            if (c != null && !inside.get()) {
                inside.set(true); // a log record made while sending one is not sent again
                try {
                    c.logMessage(new MessageParams(type, "gcnc: " + text));
                } catch (RuntimeException e) {
                    line("cannot send a log message: " + e);
                } finally {
                    inside.set(false);
                }
            }
        }

        /** LSP4J's records (a message that is not JSON-RPC, an unknown method): one line, no stack trace. */
        @Override
        public void publish(LogRecord r) {
            if (r.getLevel().intValue() < Level.WARNING.intValue()) {
                return;
            }
            String text = r.getMessage() == null ? "" : r.getMessage();
            if (r.getParameters() != null) {
                text = java.text.MessageFormat.format(text, r.getParameters());
            }
            if (r.getThrown() != null) {
                Throwable t = r.getThrown();
                text += (text.isEmpty() ? "" : ": ") + t.getClass().getSimpleName() + ": " + t.getMessage();
            }
            error(text);
        }

        @Override
        public void flush() {
            err.flush();
        }

        @Override
        public void close() {
        }
    }
}
