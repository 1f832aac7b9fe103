package gcnc.cli;

import gcnc.studio.Studio;
import gcnc.tables.TableException;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/** {@code gcnc studio}: the local web editor (gcnc.studio, docs/studio.md); runs until stopped. */
@Command(name = "studio", mixinStandardHelpOptions = true,
        description = {"Edit the programs in DIR in a local web page: diagnostics as you type, the tool path, the"
                + " Galil DMC linked to each block, compile, and run on a Galil (or the studio's virtual one).",
                "Serves 127.0.0.1 only; prints the URL with this launch's token. Ctrl+C stops it."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:stopped", "2:usage, DIR is not a folder, the port is taken, or a broken table or profile"})
final class StudioCommand extends StreamsCommand {
    @Mixin
    CommonOptions common;

    @Parameters(paramLabel = "DIR", arity = "0..1", defaultValue = ".",
            description = "The folder whose programs the studio edits (default: the current one); it reads and writes nowhere else.")
    Path dir;

    @Option(names = "--port", paramLabel = "N", defaultValue = "0",
            description = "The port on 127.0.0.1 (default: a free one).")
    int port;

    @Option(names = "--open", description = "Open the URL in the desktop's browser (xdg-open).")
    boolean open;

    @Option(names = "--virtual-speed", paramLabel = "X", defaultValue = "1",
            description = "Run: the studio's virtual controller runs the motion X times faster than real time (default: ${DEFAULT-VALUE}).")
    double virtualSpeed;

    @Override
    Integer call(PrintWriter out, PrintWriter err) {
        Phrases say = new Phrases(common.language());
        if (!Files.isDirectory(dir)) {
            err.println("gcnc: " + say.get("studio.not_folder", dir));
            return ExitCode.USAGE;
        }
        if (!(virtualSpeed > 0) || virtualSpeed > 10_000) {
            err.println("gcnc: " + say.get("studio.bad_speed", virtualSpeed));
            return ExitCode.USAGE;
        }
        CommonOptions.Setup setup;
        try {
            setup = common.load(new Reporter(out, err, common.language()));
        } catch (TableException e) {
            return Reporter.tableFault(err, e, common.language());
        }
        Studio studio;
        try {
            // Run's serial ports through jSerialComm, as gcnc run --port opens them
            studio = Studio.start(new Studio.Config(dir, port, setup.session(), common.language(), Main.version(),
                    new Studio.Running(virtualSpeed, SerialLink::open)));
        } catch (IOException e) {
            err.println("gcnc: " + say.get("studio.cannot_start", port, SourceFiles.reason(e, common.language())));
            return ExitCode.USAGE;
        }
        serveUntilStopped(studio::close, () -> {
            out.println(say.get("studio.serving", studio.root(), setup.profile().name()));
            out.println(studio.url());
            out.flush();
            if (open) {
                openInBrowser(studio.url().toString(), err, say);
            }
        });
        return ExitCode.CLEAN;
    }

    private static void openInBrowser(String url, PrintWriter err, Phrases say) {
        try {
            new ProcessBuilder("xdg-open", url).redirectErrorStream(true)
                    .redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        } catch (IOException e) {
            err.println("gcnc: " + say.get("studio.cannot_open"));
            err.flush();
        }
    }
}
