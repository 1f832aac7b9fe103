package gcnc.gradle;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.tables.TableException;
import java.io.File;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.gradle.api.DefaultTask;
import org.gradle.api.GradleException;
import org.gradle.api.file.FileCollection;
import org.gradle.api.file.FileTree;
import org.gradle.api.tasks.Input;
import org.gradle.api.tasks.InputFiles;
import org.gradle.api.tasks.Internal;
import org.gradle.api.tasks.Optional;
import org.gradle.api.tasks.OutputDirectory;
import org.gradle.api.tasks.OutputFile;
import org.gradle.api.tasks.PathSensitive;
import org.gradle.api.tasks.PathSensitivity;
import org.gradle.api.tasks.SkipWhenEmpty;
import org.gradle.api.tasks.TaskAction;

/**
 * What the three gcnc tasks share: their inputs (the programs, the files their calls can read beside
 * them, the machine, the control, the tables and any file among them, gcnc's version), one gcnc
 * session for the run, the programs judged on a pool of threads and only those that changed or call
 * a file that changed ({@link LibraryRun}; the others' results kept in {@link #getResultsDir}), and
 * the run's findings, printed GCC-style in the programs' order and written at the end as one JSON and
 * one SARIF report under build/reports/gcnc/. Any error fails the task, after every program was looked
 * at. Since inputs and outputs are declared, a second run with nothing changed is UP-TO-DATE, and the
 * subclasses are {@code @CacheableTask}: every input is named relative to the project, so another
 * clone with the same build cache takes the outputs FROM-CACHE.
 */
public abstract class GcncTask extends DefaultTask {
    /** One part program: the file, its path under the program tree (for outputs), and how findings name it. */
    public record Program(File file, String relativePath, String shown) {
        /** The relative path with {@code extension} in place of the program's own. */
        String withExtension(String extension) {
            return GcncTask.withExtension(relativePath, extension);
        }

        /** The program's text, decoded as every gcnc front end decodes it. */
        java.io.Reader open() throws IOException {
            return Session.decode(java.nio.file.Files.newInputStream(file.toPath()));
        }

        /** The program's text read whole, once, for a task that reads it more than once (its compile, its number). */
        String text() throws IOException {
            try (java.io.Reader in = open()) {
                java.io.StringWriter all = new java.io.StringWriter();
                in.transferTo(all);
                return all.toString();
            }
        }
    }

    private GcncExtension settings;

    void setSettings(GcncExtension settings) {
        this.settings = settings;
    }

    @InputFiles
    @SkipWhenEmpty
    @PathSensitive(PathSensitivity.RELATIVE)
    public FileTree getPrograms() {
        return settings.getPrograms().getAsFileTree();
    }

    /**
     * The files a call can read beside a program ({@code O1000.nc}, {@code 1000.nc}: gcnc.flow.Library's
     * names) that are not among the programs: editing one judges its callers again, as editing a program does.
     */
    @InputFiles
    @PathSensitive(PathSensitivity.RELATIVE)
    public FileCollection getCalledFiles() {
        java.util.Set<File> programs = new java.util.HashSet<>(getPrograms().getFiles());
        java.util.Set<File> folders = new java.util.TreeSet<>();
        programs.forEach(f -> folders.add(f.getAbsoluteFile().getParentFile()));
        List<File> called = new ArrayList<>();
        for (File folder : folders) {
            File[] files = folder.listFiles((dir, name) -> CALLED_NAME.matcher(name).matches());
            for (File f : files == null ? new File[0] : files) {
                if (f.isFile() && !programs.contains(f)) {
                    called.add(f);
                }
            }
        }
        called.sort(null);
        return getProject().files(called.toArray());
    }

    /** The names a call looks for beside its program (gcnc.flow.Library: O1000.nc, 1000.nc, O0100.nc). */
    static final java.util.regex.Pattern CALLED_NAME = java.util.regex.Pattern.compile("O?[0-9]+\\.nc");

    /** How the reports name the programs (relative to the root project): moving the tree runs the task again. */
    @Input
    public List<String> getProgramNames() {
        return programs().stream().map(Program::shown).toList();
    }

    @Input
    public String getMachine() {
        return settings.getMachine();
    }

    @Input
    @Optional
    public String getControl() {
        return settings.getControl();
    }

    /** The blank ({@link GcncExtension#getStock}): gcncCompile's and gcncSimulate's simulations start from it. */
    @Input
    @Optional
    public String getStock() {
        return settings.getStock();
    }

    /** The files behind the settings, so that editing a table or a profile runs the task again. */
    @InputFiles
    @PathSensitive(PathSensitivity.RELATIVE)
    public FileCollection getSettingFiles() {
        return settings.settingFiles();
    }

    @Input
    public boolean getIgnoreFailures() {
        return settings.getIgnoreFailures();
    }

    @OutputFile
    public File getHtmlReport() {
        return reportFile(".html");
    }

    @OutputFile
    public File getJsonReport() {
        return reportFile(".json");
    }

    @OutputFile
    public File getSarifReport() {
        return reportFile(".sarif");
    }

    @Internal
    protected File getReportsDir() {
        return new File(getProject().getBuildDir(), "reports/gcnc");
    }

    private File reportFile(String extension) {
        return new File(getReportsDir(), getName() + extension);
    }

    /**
     * The task's results kept between runs: one file per program and the call graph
     * ({@link ResultStore}). An output, so the build cache restores it with the reports.
     */
    @OutputDirectory
    public File getResultsDir() {
        return new File(getProject().getBuildDir(), "gcnc-results/" + getName());
    }

    /** gcnc's version: a result of another gcnc is not taken from the build cache. */
    @Input
    public String getGcncVersion() {
        return TaskFindings.version();
    }

    @TaskAction
    public void run() {
        Session session = open();
        TaskFindings findings = new TaskFindings(session, getLogger(), settings.printed);
        List<Program> programs = programs();
        List<File> skipped = settings.skipped();
        if (!skipped.isEmpty()) {
            // as the command line's note: a program saved under another extension is not silently unchecked
            getLogger().lifecycle("{}: skipped {} under src/main/gcode: not a program's extension (.{}); gcnc { extensions } adds one: {}",
                    getName(), plural(skipped.size(), "file"), String.join(", .", settings.getExtensions()),
                    skipped.stream().map(f -> shown(getProject().getRootDir(), f)).toList());
        }
        LibraryRun library;
        try {
            library = LibraryRun.judge(this, session, programs, findings);
            long t = System.nanoTime();
            finish(programs, library.outcomes());
            findings.write(getJsonReport(), getSarifReport());
            findings.writeHtml(getHtmlReport(), getName(), programs);
            library.keep();
            getLogger().info("{}: reports and index {} s", getName(), LibraryRun.seconds(System.nanoTime() - t));
        } catch (IOException e) {
            throw new GradleException(getName() + ": cannot write the reports under " + getReportsDir() + ": " + reason(e));
        }
        if (library.kept() > 0) {
            getLogger().lifecycle("{}: {} judged again (changed, new, or calling a file that changed), {} kept from the last run",
                    getName(), plural(library.judged().size(), "program"), library.kept());
            getLogger().info("{}: judged again: {}", getName(), String.join(", ", library.judged()));
        }
        if (findings.errors() > 0) {
            String failed = String.format(Locale.ROOT, "%s: %s in %s of %s; see the report at %s",
                    getName(), plural(findings.errors(), "error"), plural(findings.filesWithErrors(), "program"),
                    programs.size(), getHtmlReport().toPath().toUri());
            if (!settings.getIgnoreFailures()) {
                throw new GradleException(failed);
            }
            getLogger().warn("{} (ignoreFailures = true: the build goes on)", failed);
            return;
        }
        getLogger().lifecycle("{}: {} checked, {}{}; reports in {}", getName(), plural(programs.size(), "program"),
                findings.warnings() == 0 ? "no findings" : plural(findings.warnings(), "warning"),
                findings.waived() == 0 ? "" : ", " + findings.waived() + " waived", getReportsDir());
    }

    /** Every output of an earlier run, before all programs are judged afresh. */
    protected void clearOutputs() {
    }

    /** The outputs of one program of an earlier run, before it is judged again or after it was removed. */
    protected void clearOutputs(String relativePath) throws IOException {
    }

    /**
     * What the task does with one program: its findings and the task's own lines about it
     * ({@link #outcome}). Called on several threads at once, one program each.
     */
    protected abstract Outcome process(Session session, Program program) throws IOException;

    /** After the last program, with every program's outcome in the programs' order: e.g. a summary of them all. */
    protected void finish(List<Program> programs, List<Outcome> outcomes) throws IOException {
    }

    /** The outcome of a gcnc run over a program, every file named relative to the root project. */
    protected Outcome outcome(Compiler.Result r, List<String> extra) {
        File root = getProject().getRootDir();
        return new Outcome(Outcome.relocated(r.diagnostics().sorted(), f -> shown(root, new File(f))),
                r.calledFiles().stream().map(f -> shown(root, f.toFile())).toList(), extra);
    }

    /** The settings, for {@link LibraryRun}'s fingerprint. */
    GcncExtension settings() {
        return settings;
    }

    private Session open() {
        Session.Options o = Session.Options.defaults().withMachine(path(settings.getMachine()));
        if (settings.getControl() != null) {
            o = o.withControl(path(settings.getControl()));
        }
        if (settings.getTables() != null) {
            if (!settings.getTables().isDirectory()) {
                throw new GradleException("gcnc: tables = " + settings.getTables() + " is not a folder (a copy of gcnc's tables/)");
            }
            o = o.withTables(settings.getTables().toPath());
        }
        try {
            return Session.open(o);
        } catch (TableException e) {
            // A broken table or profile is shown with the built-in messages: the user's may be the broken ones.
            String line = new gcnc.diag.GnuRenderer(gcnc.tables.Tables.builtIn().messages().in(TaskFindings.LANG))
                    .render(tableShown(e.path()), e.diagnostic());
            getLogger().quiet(line);
            throw new GradleException(getName() + ": the machine, control or tables cannot be used: " + line);
        }
    }

    /** A table or profile of the project relative to the root project, as programs are named; else as gcnc names it. */
    private String tableShown(String path) {
        try {
            return java.nio.file.Path.of(path).isAbsolute() ? shown(getProject().getRootDir(), new File(path)) : path;
        } catch (java.nio.file.InvalidPathException e) {
            return path;
        }
    }

    /** A machine or control path relative to the project (Gradle's working directory is not the project's). */
    private String path(String nameOrPath) {
        return GcncExtension.isPath(nameOrPath) ? getProject().file(nameOrPath).getAbsolutePath() : nameOrPath;
    }

    List<Program> programs() {
        List<Program> list = new ArrayList<>();
        File root = getProject().getRootDir();
        getPrograms().visit(d -> {
            if (!d.isDirectory()) {
                list.add(new Program(d.getFile(), d.getRelativePath().getPathString(), shown(root, d.getFile())));
            }
        });
        list.sort(java.util.Comparator.comparing(Program::shown));
        return list;
    }

    /** A program's path relative to the root project (where CI runs and SARIF's %SRCROOT% is), else absolute. */
    static String shown(File root, File f) {
        java.nio.file.Path r = root.toPath().toAbsolutePath().normalize();
        java.nio.file.Path p = f.toPath().toAbsolutePath().normalize();
        return p.startsWith(r) ? r.relativize(p).toString().replace(File.separatorChar, '/') : p.toString();
    }

    /** {@code relativePath} with {@code extension} in place of the program's own. */
    static String withExtension(String relativePath, String extension) {
        int slash = relativePath.lastIndexOf('/');
        int dot = relativePath.lastIndexOf('.');
        return (dot > slash ? relativePath.substring(0, dot) : relativePath) + extension;
    }

    static String reason(IOException e) {
        return e.getMessage() == null ? e.getClass().getSimpleName() : e.getClass().getSimpleName() + ": " + e.getMessage();
    }

    static String plural(long n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }
}
