package gcnc.cli;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.GnuRenderer;
import gcnc.diag.Span;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.PrintWriter;

/** Prints findings GCC-style on standard error, sorted by position, and a one-line count. */
final class Reporter {
    private final PrintWriter err;
    private final GnuRenderer renderer;

    Reporter(PrintWriter err, Tables tables, ErrorMessages.Lang lang) {
        this.err = err;
        this.renderer = new GnuRenderer(tables.messages().in(lang));
    }

    /** Prints every finding of one file; returns how many were errors. */
    int report(String path, Diagnostics diags) {
        for (Diagnostic d : diags.sorted()) {
            err.println(renderer.render(path, d));
        }
        return diags.errorCount();
    }

    void report(String path, Diagnostic d) {
        err.println(renderer.render(path, d));
    }

    /** A file that cannot be read or written: E500 at its first line; returns exit status 2. */
    int ioFault(Object path, String what, IOException e) {
        report(path.toString(), Diagnostic.error(Code.E500_IO, Span.of(1, 1), what + ": " + SourceFiles.reason(e)));
        return ExitCode.USAGE;
    }

    /** A broken table or profile: reported with the built-in messages, since the user's may be the broken ones. */
    static int tableFault(PrintWriter err, TableException e, ErrorMessages.Lang lang) {
        err.println(new GnuRenderer(Tables.builtIn().messages().in(lang)).render(e.path(), e.diagnostic()));
        return ExitCode.USAGE;
    }

    static String plural(long n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }
}
