package gcnc.gradle;

import gcnc.Session;
import gcnc.diag.Diagnostic;
import gcnc.diag.Finding;
import gcnc.diag.GnuRenderer;
import gcnc.diag.JsonRenderer;
import gcnc.diag.Messages;
import gcnc.diag.SarifRenderer;
import gcnc.diag.Severity;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.gradle.api.logging.Logger;

/**
 * A task run's findings: each printed GCC-style as it is reported, and all of them
 * written at the end as gcnc's JSON report and as SARIF 2.1.0, with the renderers the command line
 * uses.
 */
final class Findings {
    /** Reports are in English, the language CI annotations are read in. */
    static final ErrorMessages.Lang LANG = ErrorMessages.Lang.EN;

    private final Session session;
    private final Logger logger;
    private final Messages messages;
    private final List<Finding> all = new ArrayList<>();
    private final Set<String> filesWithErrors = new HashSet<>();
    private final Set<String> printed;

    /** @param printed the findings already printed in this build by another task: not printed again */
    Findings(Session session, Logger logger, Set<String> printed) {
        this.session = session;
        this.logger = logger;
        this.printed = printed;
        this.messages = session.tables().messages().in(LANG);
    }

    /** Every diagnostic of one program, in the order of the program. */
    void report(String file, List<Diagnostic> sorted) {
        for (Diagnostic d : sorted) {
            report(file, d);
        }
    }

    void report(String file, Diagnostic d) {
        // Gradle's QUIET level: shown even with -q, and on standard output, where Gradle starts a line
        // for it; at the ERROR level (standard error) it would be glued to the task's header line in a
        // log that merges the two streams, and CI's file:line:col parsers would miss it.
        String line = render(file, d);
        if (printed.add(line)) {
            logger.quiet(line);
        }
        if (d.severity() == Severity.ERROR && !d.waived()) {
            filesWithErrors.add(file);
        }
        all.add(Finding.of(file, d, messages));
    }

    /** The messages findings are rendered in (the build's language). */
    Messages messages() {
        return messages;
    }

    /** One finding as a GCC-style line. */
    String render(String file, Diagnostic d) {
        return new GnuRenderer(messages).render(file, d);
    }

    long errors() {
        return count(Severity.ERROR);
    }

    /** Warnings and notes (not waived). */
    long warnings() {
        return all.size() - errors() - waived();
    }

    /** Findings the programs' waivers accept ({@code (GCNC ALLOW E642: reason)}): reported, counted apart. */
    long waived() {
        return all.stream().filter(f -> f.diagnostic().waived()).count();
    }

    int filesWithErrors() {
        return filesWithErrors.size();
    }

    private long count(Severity s) {
        return all.stream().filter(f -> f.diagnostic().severity() == s && !f.diagnostic().waived()).count();
    }

    /** Both reports, findings sorted by file and place. */
    void write(File json, File sarif) throws IOException {
        List<Finding> sorted = new ArrayList<>(all);
        sorted.sort(Comparator.comparing(Finding::file).thenComparing(Finding::diagnostic));
        Files.createDirectories(json.getParentFile().toPath());
        // names the plugin chose in the build folder: never written through a link planted there (E510)
        gcnc.output.AtomicOutput.write(json.toPath(), gcnc.output.AtomicOutput.Name.DERIVED,
                w -> JsonRenderer.write(sorted, version(), w));
        gcnc.output.AtomicOutput.write(sarif.toPath(), gcnc.output.AtomicOutput.Name.DERIVED,
                w -> SarifRenderer.write(sorted, rules(), version(), w));
    }

    /** The HTML report a person reads (what a failure links to), findings sorted by file and place. */
    void writeHtml(File html, String task, List<GcncTask.Program> programs) throws IOException {
        List<Finding> sorted = new ArrayList<>(all);
        sorted.sort(Comparator.comparing(Finding::file).thenComparing(Finding::diagnostic));
        HtmlReport.write(html.toPath(), task, version(), programs, sorted);
    }

    /** SARIF's rules from the session's errors.csv, or the built-in one if the user's has no catalogue. */
    private List<SarifRenderer.Rule> rules() {
        try {
            return session.codes().rules(LANG);
        } catch (TableException e) {
            try {
                return gcnc.tables.CodeTable.load(gcnc.tables.TableSource.builtIn()).rules(LANG);
            } catch (TableException builtIn) {
                throw new IllegalStateException("the tables built into gcnc.jar are broken", builtIn);
            }
        }
    }

    /** The gcnc library's version, from its jar's manifest. */
    static String version() {
        String v = Session.class.getPackage().getImplementationVersion();
        return v == null ? "development" : v;
    }
}
