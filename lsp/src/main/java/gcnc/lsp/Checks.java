package gcnc.lsp;

import gcnc.Compiler;
import gcnc.ModalStates;
import gcnc.Session;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Span;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.TimeUnit;
import org.eclipse.lsp4j.DiagnosticRelatedInformation;
import org.eclipse.lsp4j.DiagnosticSeverity;
import org.eclipse.lsp4j.Location;
import org.eclipse.lsp4j.Position;
import org.eclipse.lsp4j.PublishDiagnosticsParams;
import org.eclipse.lsp4j.Range;
import org.eclipse.lsp4j.services.LanguageClient;

/**
 * Diagnostics as the programmer types: each change of a buffer is checked on the checker's thread
 * a moment later ({@code checkDelayMs}; a change that arrives meanwhile replaces it, so a burst of
 * keystrokes is checked once), and the check's findings are published; once the buffer has been
 * left alone for {@code simulateAfterMs} and the check found no error, it is compiled with the
 * simulator on a thread of its own and the compile's findings (the check's and the simulator's) are
 * published, unless the buffer changed meanwhile. The findings are those of {@code gcnc check} and
 * {@code gcnc simulate} on the same text in the same folder, through the same {@link Session}.
 */
final class Checks {
    /** The longest buffer checked: 16 Mi characters (some 400,000 blocks); a longer one is refused (E504). */
    static final int MAX_TEXT = 16 << 20;

    /** Which pass a buffer's published findings come from. */
    enum Stage { CHECK, SIMULATE }

    /** What was last published for a buffer: the code actions read the findings' arguments from it. */
    record Published(Doc doc, Stage stage, List<Findings.Shown> shown) {
        List<org.eclipse.lsp4j.Diagnostic> diagnostics() {
            return shown.stream().map(Findings.Shown::diagnostic).toList();
        }
    }

    private final Map<String, Doc> docs;
    private final Config config;
    private final ExplainFiles explain;
    private final Log log;
    private final Map<String, ScheduledFuture<?>> pending = new ConcurrentHashMap<>();
    private final Map<String, Long> changedAt = new ConcurrentHashMap<>();
    private final Map<String, Published> published = new ConcurrentHashMap<>();
    /** The modal states each buffer's last check saw, for the hover: the check's own, not a second check. */
    private final Map<String, Seen> seen = new ConcurrentHashMap<>();
    /** The .gcnc files whose problems were published, and what they were. */
    private final Map<Path, List<FolderSettings.Problem>> settingsShown = new ConcurrentHashMap<>();
    private final ScheduledExecutorService checker = Executors.newSingleThreadScheduledExecutor(r -> thread(r, "gcnc-lsp-check"));
    private final ScheduledExecutorService simulator = Executors.newSingleThreadScheduledExecutor(r -> thread(r, "gcnc-lsp-simulate"));
    private volatile LanguageClient client;
    private volatile ErrorMessages.Lang lang;
    private volatile long checkDelayMs = 10;
    private volatile long simulateAfterMs = 500;

    Checks(Map<String, Doc> docs, Config config, ExplainFiles explain, ErrorMessages.Lang lang, Log log) {
        this.docs = docs;
        this.config = config;
        this.explain = explain;
        this.lang = lang;
        this.log = log;
    }

    private static Thread thread(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        return t;
    }

    void connect(LanguageClient c) {
        client = c;
    }

    /** {@code checkDelayMs}, {@code simulateAfterMs} (negative: never simulate), {@code lang}. */
    void timing(long checkDelay, long simulateAfter) {
        checkDelayMs = Math.max(0, checkDelay);
        simulateAfterMs = simulateAfter;
    }

    void lang(ErrorMessages.Lang l) {
        lang = l;
    }

    ErrorMessages.Lang lang() {
        return lang;
    }

    Optional<Published> published(String uri) {
        return Optional.ofNullable(published.get(uri));
    }

    /** What a check saw of a buffer's text: the state after each of its lines ({@link ModalStates#view}). */
    private record Seen(Doc doc, Map<Integer, ModalStates.Snapshot> states) {
    }

    /** The modal states the last check of {@code d} saw; empty when that text was not checked (yet). */
    Optional<Map<Integer, ModalStates.Snapshot>> states(Doc d) {
        Seen s = seen.get(d.uri());
        return s != null && s.doc() == d ? Optional.of(s.states()) : Optional.empty();
    }

    /** The buffer changed (or was opened): check it in a moment. */
    void changed(String uri) {
        changedAt.put(uri, System.nanoTime());
        pending.compute(uri, (k, old) -> {
            if (old != null) {
                old.cancel(false);
            }
            return checker.schedule(() -> guarded(() -> check(uri)), checkDelayMs, TimeUnit.MILLISECONDS);
        });
    }

    /** Every open buffer again (a profile or a setting changed). */
    void recheckAll() {
        config.forget();
        published.clear();
        seen.clear();
        docs.keySet().forEach(this::changed);
    }

    void closed(String uri) {
        ScheduledFuture<?> f = pending.remove(uri);
        if (f != null) {
            f.cancel(false);
        }
        published.remove(uri);
        seen.remove(uri);
        changedAt.remove(uri);
        LanguageClient c = client;
        if (c != null) {
            c.publishDiagnostics(new PublishDiagnosticsParams(uri, List.of()));
        }
    }

    /** Runs a pass; whatever goes wrong is logged in a line and the server goes on. */
    private void guarded(ThrowingRunnable pass) {
        try {
            pass.run();
        } catch (OutOfMemoryError e) {
            log.error("out of memory checking a buffer (E506): the server goes on; give the JVM more with GCNC_JAVA_OPTS=-Xmx1g");
        } catch (IOException | RuntimeException | StackOverflowError e) {
            log.error("gcnc could not check a buffer: " + e);
        }
    }

    @FunctionalInterface
    private interface ThrowingRunnable {
        void run() throws IOException;
    }

    private void check(String uri) throws IOException {
        Doc d = docs.get(uri);
        if (d == null) {
            return;
        }
        if (d.text().length() > MAX_TEXT) {
            refuse(d);
            return;
        }
        Config.Resolved r = config.resolve(d.folder());
        showSettingsProblems(r.settings());
        if (r.session().isEmpty()) {
            fault(d, r.fault().get());
            return;
        }
        Session s = r.session().get().withPrograms(d.folder());
        Map<Integer, ModalStates.Snapshot> states = new java.util.HashMap<>();
        Compiler.Result res = s.check(new StringReader(d.text()), ModalStates.view(states));
        if (docs.get(uri) != d) {
            return; // edited meanwhile: the next check publishes
        }
        seen.put(uri, new Seen(d, states));
        Outline outline = Outline.of(d.text(), s.profile().control());
        publish(d, Stage.CHECK, res.diagnostics().sorted(), s, outline);
        long after = simulateAfterMs;
        if (after >= 0 && !res.diagnostics().hasErrors()) {
            long since = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - changedAt.getOrDefault(uri, System.nanoTime()));
            simulator.schedule(() -> guarded(() -> simulate(d, s, outline)), Math.max(0, after - since), TimeUnit.MILLISECONDS);
        }
    }

    private void simulate(Doc d, Session s, Outline outline) throws IOException {
        if (docs.get(d.uri()) != d) {
            return;
        }
        Compiler.Result res = s.compile(new StringReader(d.text()), Optional.of(s.simulation()), false, line -> { });
        if (docs.get(d.uri()) == d) {
            publish(d, Stage.SIMULATE, res.diagnostics().sorted(), s, outline);
        }
    }

    private void publish(Doc d, Stage stage, List<Diagnostic> found, Session s, Outline outline) {
        Findings f = new Findings(s.tables().messages().in(lang), explain::uri);
        Published p = new Published(d, stage, f.of(found, d.uri(), d.text(), d.folder(), outline));
        published.put(d.uri(), p);
        send(d.uri(), p.diagnostics(), d.version());
    }

    private void send(String uri, List<org.eclipse.lsp4j.Diagnostic> shown, Integer version) {
        LanguageClient c = client;
        if (c != null) {
            c.publishDiagnostics(new PublishDiagnosticsParams(uri, shown, version));
        }
    }

    /** A buffer past {@link #MAX_TEXT}: one finding, E504 at its start, and a line in the log. */
    private void refuse(Doc d) {
        log.error(d.name() + ": " + d.text().length() + " characters, more than the " + MAX_TEXT
                + " this server checks as you type: not checked (gcnc check reads it from the file)");
        Diagnostic e504 = Diagnostic.error(Code.E504_TEXT_TOO_LONG, Span.of(1, 1), MAX_TEXT);
        Findings f = new Findings(gcnc.tables.Tables.builtIn().messages().in(lang), explain::uri);
        Published p = new Published(d, Stage.CHECK, f.of(List.of(e504), d.uri(), "", Optional.empty(), null));
        published.put(d.uri(), p);
        send(d.uri(), p.diagnostics(), d.version());
    }

    /** A broken profile, control or table: its finding at the buffer's start, pointing at the broken file's line. */
    private void fault(Doc d, TableException e) {
        var m = gcnc.tables.Tables.builtIn().messages().in(lang);
        Diagnostic td = e.diagnostic();
        String where = e.path() + ":" + td.span().line() + ":" + td.span().column();
        org.eclipse.lsp4j.Diagnostic shown = new org.eclipse.lsp4j.Diagnostic(
                new Range(new Position(0, 0), new Position(0, 1)), where + ": " + m.render(td.code(), td.args()),
                DiagnosticSeverity.Error, "gcnc", td.code().id());
        Path p = Path.of(e.path());
        if (p.isAbsolute() || java.nio.file.Files.exists(p)) {
            int line = td.span().line() - 1;
            shown.setRelatedInformation(List.of(new DiagnosticRelatedInformation(new Location(p.toAbsolutePath().toUri().toString(),
                    new Range(new Position(line, td.span().column() - 1), new Position(line, td.span().column()))),
                    m.render(td.code(), td.args()))));
        }
        log.error(where + ": " + m.render(td.code(), td.args()));
        published.put(d.uri(), new Published(d, Stage.CHECK, List.of(new Findings.Shown(td, shown))));
        send(d.uri(), List.of(shown), d.version());
    }

    /** A .gcnc file's lines that are not settings, as diagnostics on that file (cleared when it is fixed). */
    private void showSettingsProblems(FolderSettings s) {
        if (s.file().isEmpty()) {
            return;
        }
        Path file = s.file().get();
        List<FolderSettings.Problem> before = settingsShown.put(file, s.problems());
        if (s.problems().equals(before)) {
            return;
        }
        List<org.eclipse.lsp4j.Diagnostic> shown = new ArrayList<>();
        for (FolderSettings.Problem p : s.problems()) {
            shown.add(new org.eclipse.lsp4j.Diagnostic(new Range(new Position(p.line() - 1, 0), new Position(p.line() - 1, 1)),
                    p.text(), DiagnosticSeverity.Error, "gcnc", (String) null));
            log.error(file + ":" + p.line() + ": " + p.text());
        }
        send(file.toAbsolutePath().toUri().toString(), shown, null);
    }

    void stop() {
        checker.shutdownNow();
        simulator.shutdownNow();
    }
}
