package gcnc.gradle;

import gcnc.Compiler;
import gcnc.ProgramNumber;
import gcnc.Session;
import gcnc.SetupSheet;
import gcnc.sim.SimReport;
import gcnc.sim.SvgWriter;
import java.io.File;
import java.io.IOException;
import java.io.Reader;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.gradle.api.tasks.OutputDirectory;

/**
 * {@code gcncSimulate}: each program checked, translated and replayed on the machine model with
 * its tool path kept, as {@code gcnc simulate} does. Under build/reports/gcnc/gcncSimulate/: per
 * program a drawing (.svg) and a setup sheet ({@link SetupSheet}: program, machine, units, blank,
 * work zero, tools, cycle time, the program's spindle limit, findings, envelope and the drawing) as HTML and as a PNG, and
 * for all of them summary.txt, one line a program.
 */
public class SimulateTask extends GcncTask {
    private final List<String> summary = new ArrayList<>();

    @OutputDirectory
    public File getOutputDir() {
        return new File(getReportsDir(), getName());
    }

    @Override
    protected void begin() {
        getProject().delete(getOutputDir());
        getOutputDir().mkdirs();
        summary.clear();
    }

    @Override
    protected void process(Session session, Program program, Findings findings) throws IOException {
        Compiler.Result r;
        try (Reader in = program.open()) {
            r = session.compile(in, Optional.of(session.simulation().withPath()), false, line -> { });
        }
        findings.report(program.shown(), r.diagnostics());
        Optional<SimReport> sim = r.simulation();
        if (sim.isEmpty()) {
            summary.add(program.shown() + ": not simulated, " + GcncTask.plural(r.diagnostics().errorCount(), "error"));
            return;
        }
        String number;
        try (Reader in = program.open()) {
            number = ProgramNumber.of(in).orElse(null);
        }
        StringWriter svg = new StringWriter();
        SvgWriter.write(sim.get(), program.shown(), number, svg, true);
        Path svgFile = getOutputDir().toPath().resolve(program.withExtension(".svg"));
        Files.createDirectories(svgFile.getParent());
        gcnc.output.AtomicOutput.write(svgFile, gcnc.output.AtomicOutput.Name.DERIVED, w -> w.write(svg.toString()));
        SetupSheet of = SetupSheet.of(program.shown(), number, session.profile(), sim.get(), r.diagnostics(),
                findings.messages());
        SetupSheet sheet;
        try (Reader in = program.open()) {
            sheet = of.withClamps(session, in);
        }
        gcnc.output.AtomicOutput.write(getOutputDir().toPath().resolve(program.withExtension(".html")),
                gcnc.output.AtomicOutput.Name.DERIVED, w -> sheet.write(svg.toString(), w));
        // the same sheet as one PNG image, to print or pin beside the machine (gcnc sheet -o FILE.png)
        java.io.ByteArrayOutputStream png = new java.io.ByteArrayOutputStream();
        gcnc.SheetImage.write(sheet, true, png);
        try (gcnc.output.AtomicOutput o = gcnc.output.AtomicOutput.open(getOutputDir().toPath()
                .resolve(program.withExtension(".png")), gcnc.output.AtomicOutput.Name.DERIVED)) {
            o.bytes(png.toByteArray());
            o.commit();
        }
        summary.add(program.shown() + ": " + sheet.summary());
    }

    @Override
    protected void finish(List<Program> programs) throws IOException {
        gcnc.output.AtomicOutput.write(getOutputDir().toPath().resolve("summary.txt"), gcnc.output.AtomicOutput.Name.DERIVED, w -> {
            for (String line : summary) {
                w.write(line);
                w.write('\n');
            }
        });
        summary.forEach(getLogger()::lifecycle);
    }
}
