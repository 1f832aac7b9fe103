package gcnc.gradle;

import gcnc.Compiler;
import gcnc.ModalStates;
import gcnc.ProgramNumber;
import gcnc.Session;
import gcnc.SetupSheet;
import gcnc.sim.SimReport;
import gcnc.sim.SvgWriter;
import java.io.File;
import java.io.IOException;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.gradle.api.tasks.CacheableTask;

/**
 * {@code gcncSimulate}: each program checked, translated and replayed on the machine model with
 * its tool path kept, as {@code gcnc simulate} does. Under build/reports/gcnc/gcncSimulate/: per
 * program a drawing (.svg) and a setup sheet ({@link SetupSheet}: program, machine, units, blank,
 * work zero, tools, cycle time, the program's spindle limit, findings, envelope and the drawing) as HTML and as a PNG, and
 * for all of them summary.txt, one line a program.
 */
@CacheableTask
public class SimulateTask extends WritingTask {
    @Override
    protected File outputFolder() {
        return new File(getReportsDir(), getName());
    }

    /** A program's drawing and setup sheet (HTML and PNG). */
    @Override
    protected void clearOutputs(String relativePath) throws IOException {
        for (String x : List.of(".svg", ".html", ".png")) {
            Files.deleteIfExists(getOutputDir().toPath().resolve(GcncTask.withExtension(relativePath, x)));
        }
    }

    /**
     * The program's line of summary.txt is the outcome's one extra line. The program is read once: its
     * number from that text, the sheet's spindle clamps from the modal states its compile saw.
     */
    @Override
    protected Outcome process(Session session, Program program) throws IOException {
        String text = program.text();
        Map<Integer, ModalStates.Snapshot> states = new HashMap<>();
        Compiler.Result r = session.compile(new StringReader(text), Optional.of(simulation(session, program).withPath()),
                false, line -> { }, ModalStates.view(states));
        Optional<SimReport> sim = r.simulation();
        if (sim.isEmpty()) {
            return outcome(r, List.of(program.shown() + ": not simulated, "
                    + GcncTask.plural(r.diagnostics().errorCount(), "error")));
        }
        String number = ProgramNumber.of(new StringReader(text)).orElse(null);
        StringWriter svg = new StringWriter();
        SvgWriter.write(sim.get(), program.shown(), number, svg, true);
        Path svgFile = getOutputDir().toPath().resolve(program.withExtension(".svg"));
        Files.createDirectories(svgFile.getParent());
        gcnc.output.AtomicOutput.write(svgFile, gcnc.output.AtomicOutput.Name.DERIVED, w -> w.write(svg.toString()));
        SetupSheet sheet = SetupSheet.of(program.shown(), number, session.profile(), sim.get(), r.diagnostics(),
                session.tables().messages().in(TaskFindings.LANG)).withClamps(states);
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
        return outcome(r, List.of(program.shown() + ": " + sheet.summary()));
    }

    /** summary.txt: each program's line, in the programs' order, from this run or kept from the last. */
    @Override
    protected void finish(List<Program> programs, List<Outcome> outcomes) throws IOException {
        List<String> summary = new ArrayList<>();
        outcomes.forEach(o -> summary.addAll(o.extra()));
        gcnc.output.AtomicOutput.write(getOutputDir().toPath().resolve("summary.txt"), gcnc.output.AtomicOutput.Name.DERIVED, w -> {
            for (String line : summary) {
                w.write(line);
                w.write('\n');
            }
        });
        summary.forEach(getLogger()::lifecycle);
    }
}
