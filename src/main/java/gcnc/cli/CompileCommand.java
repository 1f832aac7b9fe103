package gcnc.cli;

import gcnc.Compiler;
import gcnc.galil.SourceMap;
import gcnc.machine.MachineProfile;
import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.nio.file.Path;
import java.util.Optional;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

@Command(name = "compile", mixinStandardHelpOptions = true,
        description = {"Check a program, translate it to a Galil DMC program and verify that in the simulator.",
                "Writes the output file only when there is no error; never a half-written one."})
final class CompileCommand extends RunCommand {
    @Mixin
    DialectOptions dialect;

    @Parameters(paramLabel = "FILE", description = "The G-code program.")
    Path file;

    @Option(names = {"-o", "--output"}, paramLabel = "OUT", description = "Output file (default: FILE with extension .dmc).")
    Path output;

    @Option(names = "--source-map", description = "Put a Galil comment (NO L<line>) naming the G-code line before each block's directives.")
    boolean sourceMap;

    @Option(names = "--no-simulate", description = "Skip the simulation (travel, collisions, path conformance are then NOT verified).")
    boolean noSimulate;

    @Mixin
    StockOptions stock;

    @Override
    int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) throws TableException {
        Tables tables = setup.tables();
        MachineProfile profile = setup.profile();
        Reporter reporter = setup.reporter();
        boolean simulate = !noSimulate && dialect.simulatedByDefault();
        if (noSimulate) {
            err.println("gcnc: warning: --no-simulate: travel limits, collisions and path conformance were NOT verified");
        } else if (!simulate) {
            err.println("gcnc: note: the thesis dialect is a record of the thesis's Table 5.2, not a program for a real"
                    + " controller; it is not simulated (see why: gcnc simulate --dialect thesis)");
        }
        Path target = output != null ? output : defaultOutput(file);
        Compiler.Result r;
        try (Reader in = SourceFiles.open(file)) {
            try (AtomicOutput dmc = new AtomicOutput(target); AtomicOutput map = new AtomicOutput(mapFile(target))) {
                SourceMap mapper = new SourceMap(map::line);
                r = Compiler.compile(in, new Compiler.Settings(tables, profile, dialect.name(),
                        simulate ? Optional.of(stock.options(profile)) : Optional.empty(), sourceMap)
                        .withPrograms(SourceFiles.folder(file)),
                        mapper.wrap(line -> dmc.line(line.text())));
                reporter.report(file.toString(), r.diagnostics());
                if (r.ok()) {
                    dmc.commit();
                    if (!sourceMap) {
                        map.commit();
                    }
                    out.println(file + ": " + Reporter.plural(r.blocks(), "block") + " -> " + target
                            + " (" + Reporter.plural(mapper.lines(), "line") + ", dialect " + dialect.name() + ")");
                    r.simulation().ifPresent(s -> out.println(SimSummary.format(s)));
                } else {
                    out.println(file + ": " + Reporter.plural(r.diagnostics().errorCount(), "error") + "; no output written");
                }
            } catch (IOException e) {
                return reporter.ioFault(target, "cannot write", e);
            }
        } catch (IOException e) {
            return reporter.ioFault(file, "cannot read", e);
        } catch (StockOptions.BadStock e) {
            err.println("gcnc: " + e.getMessage());
            return ExitCode.USAGE;
        }
        return r.ok() ? ExitCode.CLEAN : ExitCode.PROGRAM_ERRORS;
    }

    static Path defaultOutput(Path file) {
        String name = file.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return file.resolveSibling((dot > 0 ? name.substring(0, dot) : name) + ".dmc");
    }

    static Path mapFile(Path target) {
        return target.resolveSibling(target.getFileName() + ".map");
    }
}
