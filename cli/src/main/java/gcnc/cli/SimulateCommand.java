package gcnc.cli;

import gcnc.Compiler;
import gcnc.diag.Diagnostics;
import gcnc.machine.MachineProfile;
import gcnc.output.AtomicOutput;
import gcnc.sim.DmcReplay;
import gcnc.sim.SimOptions;
import gcnc.sim.SimReport;
import gcnc.sim.SvgWriter;
import gcnc.tables.TableException;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

@Command(name = "simulate", mixinStandardHelpOptions = true,
        description = {"Check and translate a program, then replay the Galil program on a model of the lathe:",
                "travel, chuck, tailstock, rapids into stock, spindle and chuck state, path conformance.",
                "A .dmc FILE is replayed as it is (no G-code to compare it with)."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:no errors", "1:the program has errors, or the simulation found a fault",
                "2:usage, unreadable input, unwritable drawing, broken table or profile, out of memory (E506)"})
final class SimulateCommand extends RunCommand {
    @Mixin
    DialectOptions dialect;

    @Mixin
    StockOptions stock;

    @Mixin
    CornerOptions corners;

    @Parameters(paramLabel = "FILE", description = "A G-code program, or a .dmc program to replay by itself; - reads G-code from standard input.")
    Path file;

    @Option(names = "--svg", paramLabel = "OUT", description = "Draw the XZ half-section: chuck, tailstock, stock, part, tool path,"
            + " findings; - writes standard output.")
    Path svg;

    @Option(names = "--hide-rapids", description = "Leave the rapid moves out of the --svg drawing (feeds and findings only).")
    boolean hideRapids;

    @Option(names = "--trace", description = "Print every directive with the position and outputs after it"
            + " (on standard error when standard output carries a report or the drawing).")
    boolean trace;

    @Override
    int run(CommonOptions.Setup setup, PrintWriter out, PrintWriter err) throws TableException {
        SimOptions options = stock.options(setup.profile(), file, setup.reporter().phrases(), spec, err::println);
        Reporter reporter = setup.reporter();
        boolean svgToStdout = svg != null && SourceFiles.isStdin(svg);
        if (svgToStdout) {
            takeStandardOutput("--svg -", reporter);
        }
        if (svg != null) {
            options = options.withPath();
        }
        if (trace) {
            options = options.withTrace(svgToStdout || reporter.format() != Reporter.Format.GNU ? err : out);
        }
        MachineProfile profile = setup.profile();
        String name = SourceFiles.display(file);
        if (svg != null && !svgToStdout) {
            try {
                AtomicOutput.refuseInput(SourceFiles.fileOf(file), svg);
            } catch (AtomicOutput.Refused e) {
                return reporter.ioFault(svg.toString(), gcnc.diag.Phrase.IO_CANNOT_WRITE, e);
            }
        }
        Replayed done;
        try (Reader in = SourceFiles.open(file, streams().in())) {
            if (file.toString().endsWith(".stream") && !SourceFiles.isStdin(file)) {
                Path resident = residentOf(file);
                try {
                    done = replayedStream(in, resident, profile, options, name);
                } catch (java.nio.file.NoSuchFileException e) {
                    return reporter.ioFault(resident.toString(), gcnc.diag.Phrase.IO_CANNOT_READ, e);
                }
            } else if (file.toString().endsWith(".dmc")) {
                done = replayedDmc(in, profile, options, name);
            } else {
                java.util.function.Consumer<gcnc.dmc.Instruction> discard = line -> { };
                Compiler.Result r = setup.session().withDialect(dialect.kind()).withPrograms(SourceFiles.programsFolder(file)).compile(in, Optional.of(options), false,
                        discard);
                done = new Replayed(r.diagnostics(), r.simulation(), name);
            }
        } catch (IOException e) {
            return reporter.ioFault(name, gcnc.diag.Phrase.IO_CANNOT_READ, e);
        }
        out.flush();
        Diagnostics diags = done.diags();
        reporter.report(done.shown(), diags);
        if (done.report().isEmpty()) {
            reporter.say(reporter.phrases().get("simulate.nothing", name, reporter.phrases().count(diags.errorCount(), "error")));
            return diags.hasErrors() ? ExitCode.PROGRAM_ERRORS : ExitCode.CLEAN;
        }
        SimReport report = done.report().get();
        reporter.say(SimSummary.format(report, reporter.phrases()));
        corners.say(report, done.shown(), reporter);
        reporter.simulation(done.shown(), corners.kept(report));
        if (svg != null) {
            out.flush();
            try (AtomicOutput o = svgToStdout ? AtomicOutput.toStream(streams().out()) : AtomicOutput.open(svg, AtomicOutput.Name.GIVEN)) {
                String title = SourceFiles.isStdin(file) ? name : file.getFileName().toString();
                SvgWriter.write(report, title, number(file), o.writer(), !hideRapids);
                o.commit();
                reporter.say(reporter.phrases().get("simulate.drawing", svgToStdout ? "<stdout>" : svg));
            } catch (IOException e) {
                return reporter.ioFault(svgToStdout ? "<stdout>" : svg.toString(), gcnc.diag.Phrase.IO_CANNOT_WRITE, e);
            }
        }
        return diags.hasErrors() ? ExitCode.PROGRAM_ERRORS : ExitCode.CLEAN;
    }

    /** What a replay found: its findings, the simulation (none where the compile stopped first), and the file they are shown at. */
    private record Replayed(Diagnostics diags, Optional<SimReport> report, String shown) {
    }

    /**
     * A stream ({@code part.stream}) replayed after its resident program ({@code part.dmc}); the findings
     * are shown at the G-code file the stream's map names. A resident program that is not there throws.
     */
    private Replayed replayedStream(Reader in, Path resident, MachineProfile profile, SimOptions options, String name)
            throws IOException {
        Diagnostics diags = new Diagnostics();
        gcnc.dmc.SourceMap.Table residentMap = sourceMap(resident, diags);
        gcnc.dmc.SourceMap.Table streamMap = sourceMap(file, diags);
        pairedStream(resident, residentMap, file, diags);
        SimReport report;
        try (BufferedReader r = java.nio.file.Files.newBufferedReader(resident, java.nio.charset.StandardCharsets.UTF_8)) {
            report = gcnc.sim.StreamReplay.replay(r, residentMap == null ? null : residentMap.at(),
                    new BufferedReader(in), streamMap == null ? null : streamMap.at(), profile, options, diags);
        }
        return new Replayed(diags, Optional.of(report), shownAt(streamMap, name));
    }

    /**
     * A DMC program replayed as it is, against its source map when one is beside it (the findings then
     * at the G-code lines, shown at the G-code file the map names).
     */
    private Replayed replayedDmc(Reader in, MachineProfile profile, SimOptions options, String name) throws IOException {
        Diagnostics diags = new Diagnostics();
        gcnc.dmc.SourceMap.Table map = sourceMap(file, diags);
        SimReport report = DmcReplay.replay(new BufferedReader(in), profile, options, diags, map == null ? null : map.at());
        Path stream = gcnc.output.FormOutputs.streamFile(file);
        if (report.sequences() == 0 && (map != null && map.streamSha256().isPresent() || Files.isRegularFile(stream))) {
            // a resident program moves nothing itself: "0 sequences, 0 findings" said nothing of where its motion is
            diags.report(new gcnc.diag.Diagnostic(gcnc.diag.Code.E864_RESIDENT_WITHOUT_STREAM, gcnc.diag.Severity.NOTE,
                    gcnc.diag.Span.of(1, 1), java.util.List.of(file.toString(), stream.toString()),
                    gcnc.diag.Origin.file(file.toString())));
        }
        return new Replayed(diags, Optional.of(report), shownAt(map, name));
    }

    /** Where findings at G-code lines are shown: the G-code file beside FILE that its map names, else {@code name}. */
    private String shownAt(gcnc.dmc.SourceMap.Table map, String name) {
        return map == null ? name : map.source().map(s -> String.valueOf(file.resolveSibling(s))).orElse(name);
    }

    /** The resident program a stream goes with: {@code part.stream} is fed after {@code part.dmc} (docs/galil.md). */
    private static Path residentOf(Path stream) {
        String n = stream.getFileName().toString();
        return stream.resolveSibling(n.substring(0, n.length() - ".stream".length()) + ".dmc");
    }

    /** Warning E245 when the resident's map names another stream than this one (by SHA-256). */
    private static void pairedStream(Path resident, gcnc.dmc.SourceMap.Table residentMap, Path stream, Diagnostics diags) {
        if (residentMap == null || residentMap.streamSha256().isEmpty()) {
            return;
        }
        try {
            String sha = gcnc.output.AtomicOutput.sha256(stream);
            if (!sha.equals(residentMap.streamSha256().get())) {
                diags.report(gcnc.diag.Diagnostic.warning(gcnc.diag.Code.E245_STREAM_NOT_THIS_RESIDENT, gcnc.diag.Span.of(1, 1),
                        stream.toString(), resident.toString(), sha.substring(0, 12)));
            }
        } catch (IOException e) {
            // read below, where a failure is reported
        }
    }

    /** The program's O number for the drawing's title block; null for standard input, a DMC or a file without one. */
    private static String number(Path file) {
        if (SourceFiles.isStdin(file) || file.toString().endsWith(".dmc") || file.toString().endsWith(".stream")) {
            return null;
        }
        try (Reader in = gcnc.Session.decode(java.nio.file.Files.newInputStream(file))) {
            return gcnc.ProgramNumber.of(in).orElse(null);
        } catch (IOException e) {
            return null; // it was read a moment ago; the title block then says it has no number
        }
    }

    /**
     * The source map beside a .dmc ({@code OUT.dmc.map}, as compile writes it), or null when there
     * is none or it cannot be read; also null, with warning E331 at the DMC's first line, when the
     * map does not record this DMC's SHA-256 (another program's map, one left by an earlier compile,
     * or one from before maps recorded it): its lines would blame the wrong G-code lines.
     */
    private static gcnc.dmc.SourceMap.Table sourceMap(Path dmc, Diagnostics diags) {
        if (SourceFiles.isStdin(dmc)) {
            return null;
        }
        Path map = gcnc.output.DmcOutputs.mapFile(dmc);
        if (!java.nio.file.Files.isRegularFile(map)) {
            return null;
        }
        gcnc.dmc.SourceMap.Table table;
        String sha;
        try (BufferedReader r = java.nio.file.Files.newBufferedReader(map)) {
            table = gcnc.dmc.SourceMap.read(r);
            sha = gcnc.output.AtomicOutput.sha256(dmc);
        } catch (IOException | java.io.UncheckedIOException e) {
            return null; // located at DMC lines instead
        }
        if (!table.belongsTo(sha)) {
            diags.report(gcnc.diag.Diagnostic.warning(gcnc.diag.Code.E331_MAP_NOT_THIS_DMC, gcnc.diag.Span.of(1, 1),
                    map.toString(), sha.substring(0, 12)));
            return null;
        }
        return table;
    }
}
