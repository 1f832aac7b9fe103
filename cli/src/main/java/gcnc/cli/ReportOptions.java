package gcnc.cli;

import picocli.CommandLine.Option;

/** {@code --format} and {@code --quiet}: how findings are written, and whether summaries are. */
final class ReportOptions {
    /** What shell completion offers for --format: the values as a user types them. */
    static final class FormatNames implements Iterable<String> {
        @Override
        public java.util.Iterator<String> iterator() {
            return java.util.Arrays.stream(Reporter.Format.values())
                    .map(f -> f.name().toLowerCase(java.util.Locale.ROOT)).iterator();
        }
    }

    @Option(names = "--format", paramLabel = "gnu|json|sarif", defaultValue = "gnu", completionCandidates = FormatNames.class,
            description = {"gnu (default): file:line:column: error[E037]: message, on standard error.",
                    "json: one document on standard output (docs/command-line.md).",
                    "sarif: SARIF 2.1.0 on standard output, for code-scanning annotations in CI."})
    Reporter.Format format;

    @Option(names = {"-q", "--quiet"}, description = "Print the findings only: no summary lines.")
    boolean quiet;

    /** When the GNU format shows the program's line with a caret under the column. */
    enum Caret { AUTO, ALWAYS, NEVER }

    @Option(names = "--caret", paramLabel = "auto|always|never", defaultValue = "auto",
            description = "Under each GNU finding, the program's line and a caret at the column"
                    + " (auto: when gcnc runs on a terminal).")
    Caret caret;

    @Option(names = {"--color", "--colour"}, paramLabel = "auto|always|never", defaultValue = "auto",
            description = "Colour in the GNU format (auto: on a terminal, unless NO_COLOR is set).")
    Colour.When color;

    /** The report's colour for this run (off unless asked for or on a terminal: {@link Colour}). */
    Colour colour() {
        return color == Colour.When.NEVER ? Colour.OFF
                : Colour.of(color, System.getenv(), color == Colour.When.AUTO && Colour.stderrIsTerminal());
    }

    /** Whether to show source lines: asked for, or on a terminal ({@code console}: standard input and output are one). */
    boolean carets(boolean console) {
        return caret == Caret.ALWAYS || caret == Caret.AUTO && console;
    }
}
