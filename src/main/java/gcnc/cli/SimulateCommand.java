package gcnc.cli;

import gcnc.Compiler;
import gcnc.diag.Diagnostics;
import gcnc.galil.LineSink;
import gcnc.machine.MachineProfile;
import gcnc.sim.DmcReplay;
import gcnc.sim.SimOptions;
import gcnc.sim.SimReport;
import gcnc.sim.SvgWriter;
import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.nio.file.Path;
import java.util.Optional;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

@Command(name = "simulate", mixinStandardHelpOptions = true,
        description = {"Check and translate a program, then replay the Galil program on a model of the lathe:",
                "travel, chuck, tailstock, rapids into stock, spindle and chuck state, path conformance.",
                "A .dmc FILE is replayed as it is (no G-code to compare it with)."})
final class SimulateCommand extends RunCommand {
    @Mixin
    DialectOptions dialect;

    @Mixin
    StockOptions stock;

    @Parameters(paramLabel = "FILE", description = "A G-code program, or a .dmc program to replay by itself.")
    Path file;

    @Option(names = "--svg", paramLabel = "OUT", description = "Draw the XZ half-section: chuck, tailstock, stock, part, tool path, findings.")
    Path svg;

    @Option(names = "--trace", description = "Print every directive with the position and outputs after it.")
    boolean trace;

    @Override
    int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) throws TableException {
        SimOptions options;
        try {
            options = stock.options(setup.profile());
        } catch (StockOptions.BadStock e) {
            err.println("gcnc: " + e.getMessage());
            return ExitCode.USAGE;
        }
        if (svg != null) {
            options = options.withPath();
        }
        if (trace) {
            options = options.withTrace(out);
        }
        Tables tables = setup.tables();
        MachineProfile profile = setup.profile();
        Reporter reporter = setup.reporter();
        Diagnostics diags;
        Optional<SimReport> report;
        try (Reader in = SourceFiles.open(file)) {
            if (file.toString().endsWith(".dmc")) {
                diags = new Diagnostics();
                report = Optional.of(DmcReplay.replay(new BufferedReader(in), profile, options, diags));
            } else {
                LineSink discard = line -> { };
                Compiler.Result r = Compiler.compile(in, new Compiler.Settings(tables, profile, dialect.name(), Optional.of(options))
                        .withPrograms(SourceFiles.folder(file)), discard);
                diags = r.diagnostics();
                report = r.simulation();
            }
        } catch (IOException e) {
            return reporter.ioFault(file, "cannot read", e);
        }
        out.flush();
        reporter.report(file.toString(), diags);
        if (report.isPresent()) {
            out.println(SimSummary.format(report.get()));
            if (svg != null) {
                try (AtomicOutput o = new AtomicOutput(svg)) {
                    SvgWriter.write(report.get(), file.getFileName().toString(), o.writer());
                    o.commit();
                    out.println("drawing: " + svg);
                } catch (IOException e) {
                    return reporter.ioFault(svg, "cannot write", e);
                }
            }
        } else {
            out.println(file + ": " + Reporter.plural(diags.errorCount(), "error") + " before simulation; nothing simulated");
        }
        return diags.hasErrors() ? ExitCode.PROGRAM_ERRORS : ExitCode.CLEAN;
    }
}
