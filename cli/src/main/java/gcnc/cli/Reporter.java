package gcnc.cli;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Finding;
import gcnc.diag.GnuRenderer;
import gcnc.diag.JsonRenderer;
import gcnc.diag.Messages;
import gcnc.diag.SarifRenderer;
import gcnc.diag.Span;
import gcnc.tables.CodeTable;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;

/**
 * Where a run's findings and its one-line summaries go. In the GNU format (the default) each
 * finding is printed GCC-style on standard error as it is reported, and the summaries on standard
 * output. In JSON and SARIF the findings are kept and written as one document on standard output
 * by {@link #finish}, and the summaries go to standard error, so that {@code gcnc check --format
 * sarif *.nc > gcnc.sarif} is a valid file. {@code --quiet} drops the summaries, never a finding.
 * Text from outside (file names, words of the program) is escaped in GNU lines ({@link Printable});
 * the JSON writer escapes it its own way.
 */
final class Reporter {
    /** The formats of {@code --format}. */
    enum Format { GNU, JSON, SARIF }

    private final Format format;
    private final boolean quiet;
    private final PrintWriter out;
    private final PrintWriter err;
    private final ErrorMessages.Lang lang;
    private final List<Finding> findings = new ArrayList<>();
    /** The simulations' summaries for the JSON document, by file, in the order they ran. */
    private final List<SimulationJson.Run> simulations = new ArrayList<>();
    /** Colour on a terminal (--color; NO_COLOR), else none: the report as it is without colour. */
    private Colour colour = Colour.OFF;

    /** The GNU line's pieces escaped ({@link Printable}) one by one, then coloured. */
    private GnuRenderer.Paint painted() {
        return new GnuRenderer.Paint() {
            @Override
            public String place(String text) {
                return colour.place(Printable.escape(text));
            }

            @Override
            public String severity(gcnc.diag.Severity s, String label) {
                return colour.severity(s, label);
            }

            @Override
            public String text(String text) {
                return Printable.escape(text);
            }
        };
    }

    /** Colours the GNU report from now on (on a terminal, or as --color says). */
    void colour(Colour c) {
        this.colour = java.util.Objects.requireNonNull(c);
    }

    /** The finding the GNU report's last line names (gcnc explain). */
    private final GnuRenderer.Hint hint = new GnuRenderer.Hint();
    private TableSource source = TableSource.builtIn();
    private Messages messages;
    private PrintWriter human;
    /** The program lines shown under GNU findings, or null when not shown ({@link #showSource}). */
    private SourceLines programLines;

    Reporter(Format format, boolean quiet, PrintWriter out, PrintWriter err, ErrorMessages.Lang lang) {
        this.format = format;
        this.quiet = quiet;
        this.out = out;
        this.err = err;
        this.lang = lang;
        this.human = format == Format.GNU ? out : err;
    }

    /** A GNU reporter with the built-in messages (the tables command, tests). */
    Reporter(PrintWriter out, PrintWriter err, ErrorMessages.Lang lang) {
        this(Format.GNU, false, out, err, lang);
    }

    /** The user's tables are loaded: their messages (and, for SARIF, their codes) are used from now on. */
    void use(Tables loaded, TableSource from) {
        this.source = from;
        this.messages = loaded.messagesIn(lang); // read when the first finding is printed
    }

    Format format() {
        return format;
    }

    /** Under each GNU finding, the program's line and a caret at the column (GCC's layout). */
    void showSource() {
        if (format == Format.GNU) {
            programLines = new SourceLines();
        }
    }

    /** Standard output carries the program (-o -): summaries move to standard error. */
    void stdoutTaken() {
        human = err;
    }

    /** The command line's sentences in the language of the run. */
    Phrases phrases() {
        if (phrases == null) {
            phrases = new Phrases(lang);
        }
        return phrases;
    }

    private Phrases phrases;

    /** A one-line summary for a person ("part.nc: 13 blocks, no errors"). */
    void say(String line) {
        if (!quiet) {
            human.println(Printable.escape(line));
        }
    }

    /** A simulation's summary for the JSON document ({@code "simulations"}); GNU and SARIF have their own. */
    void simulation(String path, gcnc.sim.SimReport report) {
        if (format == Format.JSON) {
            simulations.add(new SimulationJson.Run(path, report));
        }
    }

    /** Every finding of one file; returns how many were errors. */
    int report(String path, Diagnostics diags) {
        for (Diagnostic d : diags.sorted()) {
            report(path, d);
        }
        return diags.errorCount();
    }

    void report(String path, Diagnostic d) {
        report(path, d, messages());
    }

    private void report(String path, Diagnostic d, Messages m) {
        if (format == Format.GNU) {
            if (!gcnc.tables.Explanations.INTERNAL.containsKey(d.code())) {
                hint.saw(d); // a file or table fault is not what gcnc explain is for
            }
            if (!colour.on()) {
                err.println(Printable.escape(new GnuRenderer(m).render(path, d)));
            } else {
                err.println(new GnuRenderer(m).render(path, d, painted()));
            }
            String line = programLines == null ? null : programLines.line(path, d.span().line());
            if (line != null) {
                String shown = SourceLines.withCaret(line, d.span());
                int caret = shown.lastIndexOf('\n') + 1;
                err.println(shown.substring(0, caret) + colour.caret(shown.substring(caret)));
            }
        } else {
            findings.add(Finding.of(path, d, m));
        }
    }

    /** A file that cannot be read or written, or an output gcnc refuses: at its first line; returns status 2. */
    int ioFault(String path, gcnc.diag.Phrase what, IOException e) {
        if (e instanceof gcnc.output.AtomicOutput.Refused r) {
            report(path, new Diagnostic(r.code(), gcnc.diag.Severity.ERROR, Span.of(1, 1), r.args()));
        } else {
            report(path, Diagnostic.error(Code.E500_IO, Span.of(1, 1), what.arg(), gcnc.diag.Phrase.reason(e)));
        }
        return ExitCode.USAGE;
    }

    /** A broken table or profile: reported with the built-in messages, since the user's may be the broken ones. */
    int tableFault(TableException e) {
        report(e.path(), e.diagnostic(), Tables.builtIn().messages().in(lang));
        return ExitCode.USAGE;
    }

    /**
     * Writes the JSON or SARIF document, findings sorted by file and place; for GNU, the closing
     * hint (rustc's "For more information about this error, try ..."), once for the run, unless quiet.
     */
    void finish() {
        if (format == Format.GNU) {
            if (!quiet) {
                hint.chosen().ifPresent(d -> {
                    String text = new GnuRenderer(messages()).hint(d);
                    int tick = text.indexOf('`');
                    int end = text.lastIndexOf('`');
                    err.println(tick < 0 || end <= tick ? text
                            : text.substring(0, tick) + colour.command(text.substring(tick, end + 1)) + text.substring(end + 1));
                });
            }
            return;
        }
        try {
            if (format == Format.JSON) {
                JsonRenderer.write(findings, Main.version(), out, json -> SimulationJson.write(simulations, json));
            } else {
                SarifRenderer.write(findings, rules(), Main.version(), out);
            }
        } catch (IOException e) {
            // A PrintWriter does not throw; its errors are seen by checkError, reported by Main.
            err.println("gcnc: cannot write the report: " + SourceFiles.reason(e, lang));
        }
        out.flush();
    }

    private List<SarifRenderer.Rule> rules() {
        try {
            return CodeTable.load(source).rules(lang);
        } catch (TableException e) {
            try {
                return CodeTable.load(TableSource.builtIn()).rules(lang);
            } catch (TableException builtIn) {
                throw new IllegalStateException("the tables built into gcnc.jar are broken", builtIn);
            }
        }
    }

    /** The messages findings are rendered in: the run's tables', in the run's language. */
    Messages messages() {
        if (messages == null) {
            messages = Tables.builtIn().messages().in(lang);
        }
        return messages;
    }

    /** A broken table or profile, for commands without a run (tables): GNU on {@code err}. */
    static int tableFault(PrintWriter err, TableException e, ErrorMessages.Lang lang) {
        return new Reporter(err, err, lang).tableFault(e);
    }
}
