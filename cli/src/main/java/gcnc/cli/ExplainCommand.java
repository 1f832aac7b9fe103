package gcnc.cli;

import gcnc.diag.Code;
import gcnc.tables.CodeTable;
import gcnc.tables.ErrorBasis;
import gcnc.tables.ErrorMessages;
import gcnc.tables.Explanations;
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

/**
 * {@code gcnc explain E305}: what a diagnostic code means: its message (errors.csv), which control
 * behaviour it stands for (error_basis.csv), and in prose why it is reported, what the control
 * does, the usual fix and an example program that brings it about (tables/explain/).
 */
@Command(name = "explain", mixinStandardHelpOptions = true,
        description = "Explain diagnostic codes: severity, the message in English and Spanish, which control"
                + " behaviour the rule stands for (tables/error_basis.csv), why it is reported, what the control"
                + " does, the usual fix and an example program (tables/explain/).",
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
        Explanations prose = Explanations.builtIn();
        Phrases say = new Phrases(lang);
        boolean placeholders = false;
        for (Code c : wanted) {
            CodeTable.Entry e = table.find(c).orElseThrow(() ->
                    new ParameterException(spec.commandLine(), c.id() + " has no row in errors.csv"));
            out.println(c.id() + " (" + e.severity().label() + ")");
            ErrorMessages.Lang other = lang == ErrorMessages.Lang.EN ? ErrorMessages.Lang.ES : ErrorMessages.Lang.EN;
            out.println("  " + lang.name().toLowerCase(Locale.ROOT) + ": " + e.text(lang));
            out.println("  " + other.name().toLowerCase(Locale.ROOT) + ": " + e.text(other));
            java.util.Optional<ErrorBasis.Row> row = basis.find(c);
            row.ifPresent(b -> out.println("  " + BASIS_LABELS.get(lang)[b.behaviour().ordinal()]
                    + " (" + BASIS_LABELS.get(lang)[3 + b.source().ordinal()] + "): " + b.text(lang)));
            if (!e.explanation().isEmpty()) {
                out.println();
                out.println("  " + e.explanation());
            }
            prose(out, say, prose, c, e, row.isPresent());
            placeholders |= e.english().contains("{0}");
        }
        if (placeholders) {
            out.println(say.get("explain.placeholders"));
        }
        out.flush();
        return ExitCode.CLEAN;
    }

    /**
     * tables/explain/: why, what the control does (when error_basis.csv has no row for it: the
     * prose's own words, else the severity's), the fix and the example; for a code no program
     * brings about, why not.
     */
    private void prose(PrintWriter out, Phrases say, Explanations prose, Code c, CodeTable.Entry e, boolean basisShown) {
        String internal = Explanations.INTERNAL.get(c);
        java.util.Optional<Explanations.Prose> p = prose.prose(c, lang);
        if (internal != null || p.isEmpty()) {
            out.println();
            out.println("  " + say.get("explain.internal", internal == null ? "" : internal));
            return;
        }
        out.println();
        out.println("  " + say.get("explain.cause", p.get().cause()));
        if (!p.get().control().isEmpty() || !basisShown) {
            String control = p.get().control().isEmpty()
                    ? say.get("explain.control." + e.severity().label()) : p.get().control();
            out.println("  " + say.get("explain.control", control));
        }
        out.println("  " + say.get("explain.fix", p.get().fix()));
        prose.example(c).filter(x -> !x.lines().isEmpty()).ifPresent(x -> {
            String machine = x.machine() + (x.control().isEmpty() ? "" : ", control " + x.control())
                    + (x.dialect().equals("galil") ? "" : ", --dialect " + x.dialect());
            out.println("  " + (x.prelude().isEmpty() ? say.get("explain.example", machine)
                    : say.get("explain.example_after", machine, String.join(" / ", x.prelude()))));
            for (String line : x.lines()) {
                out.println("      " + Printable.escape(line));
            }
        });
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
