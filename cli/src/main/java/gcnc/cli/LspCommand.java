package gcnc.cli;

import gcnc.tables.ErrorMessages;
import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.io.PrintStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.Optional;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code gcnc lsp}: the language server (gcnc.lsp, docs/editors.md) on standard input and output. The
 * protocol owns standard output: everything else gcnc might print there goes to standard error while
 * the server runs.
 */
@Command(name = "lsp", mixinStandardHelpOptions = true,
        description = {"Serve the Language Server Protocol on standard input and output, for an editor: diagnostics"
                + " as you type (check, then the simulator after a pause), hover, go to definition, references,"
                + " symbols and quick fixes (docs/editors.md).",
                "--machine, --control and --tables are the defaults under the editor's settings and a folder's .gcnc file."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:the client sent shutdown, then exit (or closed its end)", "1:exit or the end of input without shutdown"})
final class LspCommand implements Callable<Integer> {
    @Mixin
    CommonOptions common;

    @Option(names = "--stdio", description = "Talk over standard input and output (the only transport; editors' clients pass it).")
    boolean stdio;

    /** Hidden: the longest message read, in bytes (tests; the default is Lsp.Options.INPUT_LIMIT). */
    @Option(names = "--input-limit", hidden = true, paramLabel = "BYTES")
    long inputLimit = gcnc.lsp.Lsp.Options.INPUT_LIMIT;

    /** Hidden: the most output kept for a client that does not read, in bytes (tests; default Lsp.Options.OUTPUT_LIMIT). */
    @Option(names = "--output-limit", hidden = true, paramLabel = "BYTES")
    long outputLimit = gcnc.lsp.Lsp.Options.OUTPUT_LIMIT;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws InterruptedException {
        Main main = (Main) spec.root().userObject();
        PrintWriter err = spec.commandLine().getErr();
        PrintStream stdout = System.out;
        // nothing but the protocol on standard output: a stray print would corrupt it
        System.setOut(System.err);
        try {
            ErrorMessages.Lang lang = common.language();
            gcnc.lsp.Lsp.Options o = new gcnc.lsp.Lsp.Options(Optional.ofNullable(
                    common.machine == null || common.machine.equals(gcnc.machine.ProfileLoader.DEFAULT) ? null : common.machine),
                    Optional.ofNullable(common.control), Optional.ofNullable(common.tables), lang, Main.version(),
                    LspCommand::explain, inputLimit, outputLimit);
            return gcnc.lsp.Lsp.run(main.streams().in(), main.streams().out(), err, o);
        } finally {
            System.setOut(stdout);
        }
    }

    /** {@code gcnc --lang LANG explain CODE}'s text, as the command prints it. */
    static String explain(String code, ErrorMessages.Lang lang) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Main.execute(new String[] {"--lang", lang.name().toLowerCase(java.util.Locale.ROOT), "explain", code},
                new Main.Invocation(InputStream.nullInputStream(), out, err, java.util.Map.of(), false, p -> false));
        String text = out.toString(StandardCharsets.UTF_8);
        return text.isEmpty() ? err.toString(StandardCharsets.UTF_8) : text;
    }
}
