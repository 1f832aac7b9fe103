package gcnc.cli;

import gcnc.Compiler;
import gcnc.ProgramFiles;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

@Command(name = "check", mixinStandardHelpOptions = true,
        description = "Check programs and report every error with line and column. Writes nothing.",
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:no errors", "1:a program has errors", "2:usage, unreadable file, broken table or profile, out of memory (E506)"})
final class CheckCommand extends RunCommand {
    @Parameters(arity = "1..*", paramLabel = "FILE",
            description = "G-code programs to check; a folder: every program in it by its extension (--extensions;"
                    + " any case, sub-folders too); - reads standard input.")
    List<Path> files;

    @picocli.CommandLine.Option(names = "--extensions", split = ",", paramLabel = "EXT[,EXT...]",
            description = "The extensions of the programs in a folder (default: nc,ngc,tap,gcode). A folder's other"
                    + " files are skipped, and counted in a note.")
    List<String> extensions;

    @Override
    int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) {
        Reporter reporter = setup.reporter();
        if (files.stream().filter(SourceFiles::isStdin).count() > 1) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "- names standard input, which can be read once: give it once");
        }
        int status = ExitCode.CLEAN;
        int faults = 0;
        List<Path> programs = new ArrayList<>();
        for (Path file : files) {
            if (SourceFiles.isStdin(file) || !Files.isDirectory(file)) {
                programs.add(file);
                continue;
            }
            List<String> ext = extensions == null || extensions.isEmpty() ? ProgramFiles.configured()
                    : ProgramFiles.normal(extensions);
            try {
                ProgramFiles.Scan scan = ProgramFiles.scan(file, ext);
                List<Path> found = scan.programs();
                if (found.isEmpty()) {
                    faults++;
                    status = reporter.ioFault(SourceFiles.display(file), gcnc.diag.Phrase.IO_CANNOT_CHECK,
                            new IOException(gcnc.diag.Phrase.IO_NO_PROGRAM.with("." + String.join(", .", ext))));
                }
                if (scan.skippedCount() > 0) {
                    reporter.say(skipped(reporter.phrases(), SourceFiles.display(file), scan, ext));
                }
                programs.addAll(found);
            } catch (IOException e) {
                faults++;
                status = reporter.ioFault(SourceFiles.display(file), gcnc.diag.Phrase.IO_CANNOT_READ, e);
            }
        }
        long blocks = 0;
        int read = 0;
        long errorsInAll = 0;
        long waivedInAll = 0;
        for (Path file : programs) {
            String name = SourceFiles.display(file);
            try (Reader in = SourceFiles.open(file, streams().in())) {
                Compiler.Result r = setup.session().withPrograms(SourceFiles.programsFolder(file)).check(in);
                int errors = reporter.report(name, r.diagnostics());
                Phrases say = reporter.phrases();
                int waived = r.diagnostics().waivedCount();
                reporter.say(say.get("check.summary", name, say.count(r.blocks(), "block"),
                        (errors == 0 ? say.get("no_errors") : say.count(errors, "error"))
                                + (waived == 0 ? "" : ", " + say.count(waived, "waived"))));
                waivedInAll += waived;
                blocks += r.blocks();
                errorsInAll += errors;
                read++;
                if (errors > 0) {
                    status = Math.max(status, ExitCode.PROGRAM_ERRORS);
                }
            } catch (IOException e) {
                faults++;
                status = reporter.ioFault(name, gcnc.diag.Phrase.IO_CANNOT_READ, e);
            }
        }
        if (programs.size() + faults > 1) {
            // every program read, and every file or folder that could not be (an error each)
            long errors = errorsInAll + faults;
            Phrases say = reporter.phrases();
            reporter.say(say.get("check.total", say.count(read, "program"), say.count(blocks, "block"),
                    (errors == 0 ? say.get("no_errors") : say.count(errors, "error"))
                            + (waivedInAll == 0 ? "" : ", " + say.count(waivedInAll, "waived"))));
        }
        return status;
    }

    /** "parts/: skipped 3 files (.txt 2, .dmc 1): not a program's extension (.nc, .ngc, ...); --extensions to add one". */
    static String skipped(Phrases say, String folder, ProgramFiles.Scan scan, List<String> ext) {
        StringBuilder which = new StringBuilder();
        scan.skipped().forEach((e, n) -> which.append(which.length() > 0 ? ", " : "")
                .append(e.isEmpty() ? say.get("check.no_extension") : "." + e).append(' ').append(n));
        return say.get("check.skipped", folder, scan.skippedCount(), which, "." + String.join(", .", ext));
    }
}
