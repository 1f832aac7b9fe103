package gcnc.cli;

import gcnc.diag.Code;
import gcnc.machine.Control;
import gcnc.machine.ControlLoader;
import gcnc.machine.FunctionText;
import gcnc.machine.ProfileLoader;
import gcnc.tables.CodeTable;
import gcnc.tables.ErrorBasis;
import gcnc.tables.ErrorMessages;
import gcnc.tables.Explanations;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.ParameterException;
import picocli.CommandLine.Parameters;

/**
 * {@code gcnc explain E305}: what a diagnostic code means: its message (errors.csv), which control
 * behaviour it stands for (error_basis.csv), and in prose why it is reported, what the control
 * does, the usual fix and an example program that brings it about (tables/explain/).
 * {@code gcnc explain G71 --machine haas}: what a G or M code does on that machine's control (or
 * {@code --control}'s), the studio's hover text ({@link FunctionText}); with neither, on every
 * shipped control.
 */
@Command(name = "explain", mixinStandardHelpOptions = true,
        description = {"Explain diagnostic codes: severity, the message in English and Spanish, which control"
                + " behaviour the rule stands for (tables/error_basis.csv), why it is reported, what the control"
                + " does, the usual fix and an example program (tables/explain/).",
                "Explain G and M codes (G71, M00): what each does on the control of --machine or --control"
                        + " (its row of g_codes.csv or m_codes.csv); with neither, on every shipped control."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every code was explained", "2:no such code (or a G or M code no control in question knows),"
                + " or a broken table or profile"})
final class ExplainCommand extends StreamsCommand {
    @Parameters(arity = "1..*", paramLabel = "CODE", description = "A diagnostic code (E305, e305 or 305) or a G or M code"
            + " (G71, g1, M00).")
    List<String> codes;

    @Option(names = "--machine", paramLabel = "NAME|PATH", description = "For a G or M code: the control of this machine"
            + " profile (a name under tables/machines/ or a .machine file).")
    String machine;

    @Option(names = "--control", paramLabel = "NAME|PATH", description = "For a G or M code: this control (a name under"
            + " tables/controls/ or a folder); with --machine, it replaces the profile's.")
    String control;

    @Option(names = "--tables", paramLabel = "DIR", description = "Read errors.csv from DIR instead of the built-in one.")
    Path tables;

    @Option(names = "--lang", paramLabel = "en|es", defaultValue = "en", description = "The language shown first: en (default) or es.")
    ErrorMessages.Lang lang;

    @Override
    Integer call(PrintWriter out, PrintWriter err) {
        if (codes.stream().anyMatch(FunctionText::isWord)) {
            if (!codes.stream().allMatch(FunctionText::isWord)) {
                throw new ParameterException(spec.commandLine(), "explain G and M codes or diagnostic codes, not both at once");
            }
            return functions(out);
        }
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
     * G and M codes: each on the control of {@code --machine} or {@code --control}, else on every
     * shipped control (those that do not have it are named on one line).
     */
    private int functions(PrintWriter out) {
        Phrases say = new Phrases(lang);
        List<Control> controls = new java.util.ArrayList<>();
        TableSource source = tables == null ? TableSource.builtIn() : TableSource.directory(tables);
        try {
            if (machine != null) {
                controls.add(ProfileLoader.load(machine, source, Tables.load(source), control).control());
            } else if (control != null) {
                controls.add(ControlLoader.load(control, source));
            } else {
                for (String name : ControlLoader.SHIPPED) {
                    controls.add(ControlLoader.load(name, source));
                }
            }
        } catch (TableException e) {
            return Reporter.tableFault(spec.commandLine().getErr(), e, lang);
        }
        int status = ExitCode.CLEAN;
        for (String word : codes) {
            List<String> without = new java.util.ArrayList<>();
            boolean any = false;
            for (Control c : controls) {
                FunctionText f = FunctionText.of(c, word).orElseThrow();
                if (!f.known()) {
                    without.add(c.name());
                    continue;
                }
                any = true;
                out.println(say.get("explain.function", f.name(), c.name(), f.text(lang)));
                out.println("  " + say.get("explain.function.other", lang == ErrorMessages.Lang.EN ? "es" : "en",
                        f.text(lang == ErrorMessages.Lang.EN ? ErrorMessages.Lang.ES : ErrorMessages.Lang.EN)));
                String kind = f.letter() == 'G'
                        ? (f.modal() ? say.get("explain.function.modal", f.group()) : say.get("explain.function.once"))
                        : say.get("explain.function.moment." + (f.moment() == 99 ? "end" : f.moment() == 1 ? "start" : "during"),
                                f.group());
                out.println("  " + kind + "; " + say.get("explain.function.role", f.role())
                        + (f.letter() == 'G' ? "; " + say.get("explain.function.words", switch (f.words()) {
                            case "*" -> say.get("explain.function.words.any");
                            case "" -> say.get("explain.function.words.none");
                            default -> f.words();
                        }) : ""));
            }
            FunctionText first = FunctionText.of(controls.get(0), word).orElseThrow();
            if (!without.isEmpty()) {
                out.println(say.get(any ? "explain.function.not_on" : "explain.function.unknown", first.name(),
                        String.join(", ", without)));
            }
            if (!any) {
                status = ExitCode.USAGE;
            }
        }
        out.println(say.get("explain.function.more"));
        out.flush();
        return status;
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
                    + (gcnc.galil.Dialect.Kind.of(x.dialect()) == gcnc.galil.Dialect.Kind.GALIL ? "" : ", --dialect " + x.dialect());
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
                "gcnc does not generate it", "the manual's rule", "gcnc's rule beyond the manuals",
                "Galil's command reference", "the thesis's control", "not a block of the program"},
            ErrorMessages.Lang.ES, new String[] {"el control se detiene (alarma)", "el control ejecuta el bloque",
                "gcnc no lo genera", "regla del manual", "regla de gcnc más allá de los manuales",
                "referencia de órdenes de Galil", "el control de la tesis", "no es un bloque del programa"});

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
