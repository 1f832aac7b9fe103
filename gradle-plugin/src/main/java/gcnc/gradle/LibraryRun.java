package gcnc.gradle;

import gcnc.Session;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Span;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import org.gradle.api.GradleException;

/**
 * One run of a task over a shop's whole library of programs: which programs must be judged again,
 * judging them on a bounded pool of threads in Gradle's JVM, and the others' results taken from the
 * last run ({@link ResultStore}).
 *
 * <p>A program is judged again when its content changed or it is new, and so is every program whose
 * calls looked for a file that changed, appeared or went (M98/M97/G65 P1000 reading {@code O1000.nc}
 * beside it; a call inside a called file is looked for from the main program's folder, so the
 * callers of callers are among them). When gcnc's classes, the machine, the control or the tables
 * changed, or there is no usable index, every program is judged and the task's outputs cleared first.
 *
 * <p>Findings are printed and collected in the programs' order whichever thread judged them, so the
 * log and the reports are those of judging every program in turn.
 */
final class LibraryRun {
    private final ResultStore store;
    private final String fingerprint;
    private final List<ResultStore.Entry> entries;
    private final List<Outcome> outcomes;
    private final List<String> judged;

    private LibraryRun(ResultStore store, String fingerprint, List<ResultStore.Entry> entries, List<Outcome> outcomes,
                       List<String> judged) {
        this.store = store;
        this.fingerprint = fingerprint;
        this.entries = entries;
        this.outcomes = outcomes;
        this.judged = judged;
    }

    /** Every program's outcome, reported to {@code findings} in the programs' order. */
    static LibraryRun judge(GcncTask task, Session session, List<GcncTask.Program> programs, TaskFindings findings)
            throws IOException {
        long t0 = System.nanoTime();
        ResultStore store = new ResultStore(task.getResultsDir().toPath());
        String fingerprint = fingerprint(task);
        Optional<Map<String, ResultStore.Entry>> last = store.index(fingerprint);
        List<String> hashes = new ArrayList<>(programs.size());
        for (GcncTask.Program p : programs) {
            hashes.add(ResultStore.hash(p.file().toPath()));
        }
        Set<String> again = again(task, store, programs, hashes, last);
        long t1 = System.nanoTime();
        store.forgetIndex();
        List<GcncTask.Program> todo = new ArrayList<>();
        for (GcncTask.Program p : programs) {
            if (again.contains(p.shown())) {
                task.clearOutputs(p.relativePath());
                todo.add(p);
            }
        }
        int threads = Math.max(1, Math.min(todo.size(), task.getProject().getGradle().getStartParameter().getMaxWorkerCount()));
        ExecutorService pool = Executors.newFixedThreadPool(threads, daemons(task.getName()));
        try {
            List<Future<Outcome>> running = new ArrayList<>(todo.size());
            for (GcncTask.Program p : todo) {
                running.add(pool.submit(() -> judgeOne(task, session, p)));
            }
            List<ResultStore.Entry> entries = new ArrayList<>(programs.size());
            List<Outcome> outcomes = new ArrayList<>(programs.size());
            List<String> judged = new ArrayList<>();
            todo.forEach(p -> judged.add(p.shown()));
            int next = 0;
            for (int k = 0; k < programs.size(); k++) {
                GcncTask.Program p = programs.get(k);
                Outcome o;
                if (next < todo.size() && todo.get(next) == p) {
                    o = done(running.get(next++));
                    store.write(p.shown(), o);
                } else {
                    try {
                        o = store.read(p.shown());
                    } catch (IOException broken) {
                        // a result file that cannot be read (edited, cut short): the program is judged again
                        o = judgeOne(task, session, p);
                        store.write(p.shown(), o);
                        judged.add(p.shown());
                    }
                }
                findings.report(p.shown(), o.diagnostics());
                outcomes.add(o);
                entries.add(new ResultStore.Entry(p.shown(), p.relativePath(), hashes.get(k), o.calls()));
            }
            calledFiles(task, entries);
            // where the time of a run over a large library goes (docs/gradle-plugin.md, the benchmark)
            task.getLogger().info("{}: hashes and call graph {} s; {} judged and {} kept results read {} s",
                    task.getName(), seconds(t1 - t0), judged.size(), programs.size() - judged.size(),
                    seconds(System.nanoTime() - t1));
            return new LibraryRun(store, fingerprint, entries, outcomes, judged);
        } finally {
            pool.shutdownNow();
        }
    }

    /** The programs to judge again (by how reports name them); the results and outputs of removed programs are deleted here. */
    private static Set<String> again(GcncTask task, ResultStore store, List<GcncTask.Program> programs, List<String> hashes,
                                     Optional<Map<String, ResultStore.Entry>> last) throws IOException {
        Set<String> all = new HashSet<>();
        programs.forEach(p -> all.add(p.shown()));
        if (last.isEmpty()) {
            task.clearOutputs();
            task.getProject().delete(store.folder().toFile());
            Files.createDirectories(store.folder());
            return all;
        }
        // the files that changed, appeared or went since the last run
        Set<String> touched = new HashSet<>();
        for (int k = 0; k < programs.size(); k++) {
            ResultStore.Entry e = last.get().get(programs.get(k).shown());
            if (e == null || !e.hash().equals(hashes.get(k))) {
                touched.add(programs.get(k).shown());
            }
        }
        File root = task.getProject().getRootDir();
        for (ResultStore.Entry e : last.get().values()) {
            if (e.relativePath() == null) {
                // a called file that is not a program: touched when its content changed, it appeared or went
                if (!e.hash().equals(ResultStore.hash(root.toPath().resolve(e.shown())))) {
                    touched.add(e.shown());
                }
                continue;
            }
            if (!all.contains(e.shown())) {
                touched.add(e.shown());
                store.remove(e.shown());
                task.clearOutputs(e.relativePath());
            }
        }
        Set<String> again = new HashSet<>();
        for (GcncTask.Program p : programs) {
            ResultStore.Entry e = last.get().get(p.shown());
            if (touched.contains(p.shown()) || e.calls().stream().anyMatch(touched::contains)) {
                again.add(p.shown());
            }
        }
        return again;
    }

    /**
     * Index entries (without a path under the program tree) for the files the calls looked for that
     * are not programs, with their content's hash ("none": not there), so that the next run sees them change.
     */
    private static void calledFiles(GcncTask task, List<ResultStore.Entry> entries) throws IOException {
        Set<String> programs = new HashSet<>();
        entries.forEach(e -> programs.add(e.shown()));
        Set<String> called = new java.util.TreeSet<>();
        entries.forEach(e -> called.addAll(e.calls()));
        Path root = task.getProject().getRootDir().toPath();
        for (String c : called) {
            if (!programs.contains(c)) {
                entries.add(new ResultStore.Entry(c, null, ResultStore.hash(root.resolve(c)), List.of()));
            }
        }
    }

    /** One program, judged with its calls looked for beside it (as the command line does); an unreadable one is E500 at 1:1. */
    private static Outcome judgeOne(GcncTask task, Session session, GcncTask.Program p) {
        Path folder = p.file().getAbsoluteFile().toPath().getParent();
        try {
            return task.process(session.withPrograms(Optional.ofNullable(folder)), p);
        } catch (IOException e) {
            return new Outcome(List.of(Diagnostic.error(Code.E500_IO, Span.of(1, 1),
                    gcnc.diag.Phrase.IO_CANNOT_READ_OR_WRITE.arg(), gcnc.diag.Phrase.reason(e))), List.of(), List.of());
        }
    }

    private static Outcome done(Future<Outcome> f) {
        try {
            return f.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new GradleException("gcnc: interrupted", e);
        } catch (ExecutionException e) {
            if (e.getCause() instanceof RuntimeException r) {
                throw r;
            }
            if (e.getCause() instanceof Error err) {
                throw err;
            }
            throw new GradleException("gcnc: " + e.getCause(), e.getCause());
        }
    }

    /**
     * Everything besides the programs that the verdicts depend on: gcnc's and the plugin's classes
     * (their jars' hashes), the task, the machine, the control and the files behind the settings
     * (named relative to the root project, so that another clone has the same fingerprint).
     */
    private static String fingerprint(GcncTask task) throws IOException {
        GcncExtension settings = task.settings();
        StringBuilder s = new StringBuilder();
        s.append("gcnc ").append(TaskFindings.version()).append('\n');
        s.append("task ").append(task.getClass().getName()).append('\n');
        s.append("machine ").append(settings.getMachine()).append('\n');
        s.append("control ").append(settings.getControl()).append('\n');
        s.append("stock ").append(settings.getStock()).append('\n');
        s.append("tables ").append(settings.getTables() == null ? "built-in" : "given").append('\n');
        for (Class<?> c : List.of(Session.class, GcncTask.class)) {
            s.append("classes ").append(classes(c)).append('\n');
        }
        File root = task.getProject().getRootDir();
        List<File> files = new ArrayList<>(settings.settingFiles().getFiles());
        files.sort(Comparator.comparing(f -> GcncTask.shown(root, f)));
        for (File f : files) {
            if (f.isFile()) {
                s.append("file ").append(GcncTask.shown(root, f)).append(' ').append(ResultStore.hash(f.toPath())).append('\n');
            }
        }
        return ResultStore.hash(s.toString());
    }

    /** The hash of the jar a class was loaded from (a folder of classes: its path; the development build). */
    private static String classes(Class<?> c) throws IOException {
        try {
            Path where = Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI());
            return Files.isRegularFile(where) ? ResultStore.hash(where) : where.toString();
        } catch (java.net.URISyntaxException | RuntimeException e) {
            return "unknown";
        }
    }

    static String seconds(long nanos) {
        return String.format(java.util.Locale.ROOT, "%.2f", nanos / 1e9);
    }

    private static java.util.concurrent.ThreadFactory daemons(String task) {
        AtomicInteger n = new AtomicInteger();
        return r -> {
            Thread t = new Thread(r, "gcnc " + task + " " + n.incrementAndGet());
            t.setDaemon(true);
            return t;
        };
    }

    List<Outcome> outcomes() {
        return outcomes;
    }

    /** The programs this run judged, in their order. */
    List<String> judged() {
        return judged;
    }

    /** How many programs' results were kept from the last run. */
    int kept() {
        return outcomes.size() - judged.size();
    }

    /** Writes the call graph and hashes for the next run: after the reports, so a run that failed writing them leaves none. */
    void keep() throws IOException {
        store.writeIndex(fingerprint, entries);
    }
}
