package gcnc.cli;

import gcnc.diag.Code;
import gcnc.tables.CodeTable;
import gcnc.tables.ErrorBasis;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code gcnc explain E305}: what a diagnostic code means, from errors.csv. */
@Command(name = "explain", mixinStandardHelpOptions = true,
        description = "Explain diagnostic codes: severity, the message in English and Spanish, which control"
                + " behaviour the rule stands for (tables/error_basis.csv) and the table's explanation if it has one.",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every code was explained", "2:no such code, or a broken errors.csv"})
final class ExplainCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "CODE", description = "E305, e305 or 305.")
    List<String> codes;

    @Option(names = "--tables", paramLabel = "DIR", description = "Read errors.csv from DIR instead of the built-in one.")
    Path tables;

    @Option(names = "--lang", paramLabel = "en|es", defaultValue = "en", description = "The language shown first: en (default) or es.")
    ErrorMessages.Lang lang;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        List<Code> wanted = codes.stream().map(this::code).toList();
        CodeTable table;
        ErrorBasis basis;
        try {
            table = CodeTable.load(tables == null ? TableSource.builtIn() : TableSource.directory(tables));
            basis = basis();
        } catch (TableException e) {
            return Reporter.tableFault(spec.commandLine().getErr(), e, lang);
        }
        boolean placeholders = false;
        for (Code c : wanted) {
            CodeTable.Entry e = table.find(c).orElseThrow(() ->
                    new ParameterException(spec.commandLine(), c.id() + " has no row in errors.csv"));
            out.println(c.id() + " (" + e.severity().label() + ")");
            ErrorMessages.Lang other = lang == ErrorMessages.Lang.EN ? ErrorMessages.Lang.ES : ErrorMessages.Lang.EN;
            out.println("  " + lang.name().toLowerCase(Locale.ROOT) + ": " + e.text(lang));
            out.println("  " + other.name().toLowerCase(Locale.ROOT) + ": " + e.text(other));
            basis.find(c).ifPresent(b -> out.println("  " + BASIS_LABELS.get(lang)[b.behaviour().ordinal()]
                    + " (" + BASIS_LABELS.get(lang)[3 + b.source().ordinal()] + "): " + b.text(lang)));
            if (!e.explanation().isEmpty()) {
                out.println();
                out.println("  " + e.explanation());
            }
            placeholders |= e.english().contains("{0}");
        }
        if (placeholders) {
            out.println("({0}, {1}... stand for the word or value each finding names.)");
        }
        out.flush();
        return ExitCode.CLEAN;
    }

    /** The words before a basis row: the control's behaviour, then the rule's source, per language. */
    private static final java.util.Map<ErrorMessages.Lang, String[]> BASIS_LABELS = java.util.Map.of(
            ErrorMessages.Lang.EN, new String[] {"the control stops (alarm)", "the control runs the block",
                "not supported yet by gcnc", "the manual's rule", "gcnc's rule beyond the manuals",
                "Galil's command reference"},
            ErrorMessages.Lang.ES, new String[] {"el control se detiene (alarma)", "el control ejecuta el bloque",
                "aún no soportado por gcnc", "regla del manual", "regla de gcnc más allá de los manuales",
                "referencia de órdenes de Galil"});

    /**
     * tables/error_basis.csv: built in, or from --tables DIR when that folder has one (an edited
     * errors.csv alone explains without it); a broken file is reported like errors.csv.
     */
    private ErrorBasis basis() throws TableException {
        if (tables == null) {
            return ErrorBasis.load(TableSource.builtIn());
        }
        if (java.nio.file.Files.exists(tables.resolve(ErrorBasis.FILE))) {
            return ErrorBasis.load(TableSource.directory(tables));
        }
        return ErrorBasis.empty();
    }

    private Code code(String text) {
        String digits = text.trim().toUpperCase(Locale.ROOT);
        if (digits.startsWith("E")) {
            digits = digits.substring(1);
        }
        try {
            return Code.byNumber(Integer.parseInt(digits));
        } catch (IllegalArgumentException e) {
            throw new ParameterException(spec.commandLine(), "'" + Printable.escape(text)
                    + "' is not a diagnostic code of this gcnc (gcnc tables lists them all)");
        }
    }
}
