package gcnc.cli;

import gcnc.Compiler;
import gcnc.SetupSheet;
import gcnc.SheetImage;
import gcnc.diag.Phrase;
import gcnc.output.AtomicOutput;
import gcnc.sim.SimOptions;
import gcnc.sim.SimReport;
import gcnc.sim.SvgWriter;
import gcnc.tables.TableException;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.Optional;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code gcnc sheet part.nc -o part.html}: the setup sheet the Gradle plugin's {@code gcncSimulate}
 * writes ({@link SetupSheet}: program, machine, units, blank, work zero, tools, cycle time, top
 * spindle speed, findings, envelope and the drawing), for one program from the command line. The
 * program is checked, translated and simulated as {@code gcnc simulate} does; the sheet is written
 * whole or not at all, also when the program has errors (the sheet lists them) as long as the
 * simulation ran.
 */
@Command(name = "sheet", mixinStandardHelpOptions = true,
        description = {"Write a program's setup sheet: one self-contained HTML page (or a PNG image: -o sheet.png) with the"
                + " program, machine, units, blank, work zero, tools, cycle time, top spindle speed and the program's G50/G92"
                + " limit, every finding, the envelope and the drawing."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:no errors; the sheet was written", "1:the program has errors (the sheet lists them when"
                + " the simulation ran, else nothing was written)",
                "2:usage, unreadable input, unwritable or refused output, broken table or profile, out of memory (E506)"})
final class SheetCommand extends RunCommand {
    @Mixin
    DialectOptions dialect;

    @Mixin
    StockOptions stock;

    @Parameters(paramLabel = "FILE", description = "The G-code program.")
    Path file;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT",
            description = "The sheet (default: FILE with extension .html); a name ending in .png writes it as one PNG image;"
                    + " - writes the HTML to standard output. Never the program itself.")
    Path output;

    @Override
    int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) throws TableException {
        SimOptions options = stock.options(setup.profile(), file, setup.reporter().phrases(), spec, err::println).withPath();
        Reporter reporter = setup.reporter();
        if (SourceFiles.isStdin(file)) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "sheet reads a program file, not standard input");
        }
        boolean toStdout = output != null && SourceFiles.isStdin(output);
        if (toStdout) {
            takeStandardOutput("-o -", reporter);
        }
        Path target = output != null ? output : withExtension(file, ".html");
        if (!toStdout) {
            try {
                AtomicOutput.refuseInput(file, target);
            } catch (AtomicOutput.Refused e) {
                return reporter.ioFault(target.toString(), Phrase.IO_CANNOT_WRITE, e);
            }
        }
        String name = SourceFiles.display(file);
        Compiler.Result r;
        String text;
        // read once: the compile's input, the program's number; the sheet's clamps are the modal states the compile saw
        java.util.Map<Integer, gcnc.ModalStates.Snapshot> states = new java.util.HashMap<>();
        try (Reader in = SourceFiles.open(file, streams().in())) {
            text = gcnc.send.CompiledRun.text(in);
            r = setup.session().withDialect(dialect.kind()).withPrograms(SourceFiles.programsFolder(file))
                    .compile(new java.io.StringReader(text), Optional.of(options), false, line -> { },
                            gcnc.ModalStates.view(states));
        } catch (IOException e) {
            return reporter.ioFault(name, Phrase.IO_CANNOT_READ, e);
        }
        String number;
        try {
            number = gcnc.ProgramNumber.of(new java.io.StringReader(text)).orElse(null);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e); // a StringReader does not fail
        }
        reporter.report(name, r.diagnostics());
        Optional<SimReport> sim = r.simulation();
        if (sim.isEmpty()) {
            reporter.say(reporter.phrases().get("sheet.nothing", name,
                    reporter.phrases().count(r.diagnostics().errorCount(), "error")));
            return r.diagnostics().hasErrors() ? ExitCode.PROGRAM_ERRORS : ExitCode.USAGE;
        }
        String title = file.getFileName().toString();
        StringWriter svg = new StringWriter();
        try {
            SvgWriter.write(sim.get(), title, number, svg, true);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e); // a StringWriter does not fail
        }
        SetupSheet sheet = SetupSheet.of(name, number, setup.profile(), sim.get(), r.diagnostics(),
                reporter.messages()).withClamps(states);
        boolean png = !toStdout && target.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".png");
        out.flush();
        try (AtomicOutput o = toStdout ? AtomicOutput.toStream(streams().out()) : AtomicOutput.open(target, output == null ? AtomicOutput.Name.DERIVED : AtomicOutput.Name.GIVEN)) {
            if (png) {
                java.io.ByteArrayOutputStream image = new java.io.ByteArrayOutputStream();
                SheetImage.write(sheet, true, image);
                o.bytes(image.toByteArray());
            } else {
                sheet.write(svg.toString(), o.writer());
            }
            o.commit();
        } catch (IOException e) {
            return reporter.ioFault(toStdout ? "<stdout>" : target.toString(), Phrase.IO_CANNOT_WRITE, e);
        }
        reporter.say(reporter.phrases().get("sheet.written", toStdout ? "<stdout>" : target, sheet.summary()));
        return r.diagnostics().hasErrors() ? ExitCode.PROGRAM_ERRORS : ExitCode.CLEAN;
    }

    /** {@code part.nc} → {@code part.html} beside it ({@code part} → {@code part.html}). */
    private static Path withExtension(Path file, String extension) {
        String n = file.getFileName().toString();
        int dot = n.lastIndexOf('.');
        return file.resolveSibling((dot > 0 ? n.substring(0, dot) : n) + extension);
    }
}
