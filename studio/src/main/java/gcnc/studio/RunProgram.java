package gcnc.studio;

import com.google.gson.JsonObject;
import gcnc.Compiler;
import gcnc.Session;
import gcnc.dmc.Form;
import gcnc.output.DmcOutputs;
import gcnc.output.FormOutputs;
import gcnc.send.BlockTable;
import gcnc.send.CompiledRun;
import gcnc.send.DmcProgram;
import gcnc.sim.SimOptions;
import java.io.IOException;
import java.io.Reader;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * A saved program made ready to run, step for step as {@code gcnc run FILE} makes it (SendCommand):
 * checked, compiled and simulated (blended as the profile plans it; every motion stopped at its end
 * in step mode), written beside it only when clean in the form {@code gcnc compile} chooses
 * ({@code FILE.dmc} and its map, and {@code FILE.stream} when the program does not fit the
 * controller); the program sent, its time and the checker's state at each block (for the live display)
 * are what the compile published of itself ({@code CompiledRun}), not a second reading. A program that is not clean comes back refused, with its diagnostics,
 * and nothing else is done.
 *
 * @param report  the diagnostics, as {@code gcnc check --format json} writes them
 * @param errors  how many errors (the refusal says it)
 * @param program the DMC program and its source lines (null when refused)
 * @param blocks  the modal state at each G-code line (null when refused)
 * @param form    program or stream: the form sent (null when refused)
 * @param dmcLines the lines of {@code FILE.dmc} as written (packed): the program, or the resident program
 */
record RunProgram(JsonObject report, int errors, DmcProgram program, BlockTable blocks, Form form, int dmcLines) {
    boolean clean() {
        return program != null;
    }

    /** {@code file} (named {@code name} on the page) compiled to {@code dmc} (and its stream) beside it. */
    static RunProgram prepare(Session session, Analysis analysis, String name, Path file, Path dmc, boolean step)
            throws IOException {
        Optional<Path> folder = Optional.ofNullable(file.getParent());
        Optional<SimOptions> sim = Optional.of(session.simulation());
        // what the run needs of the compile, as it publishes it (CompiledRun): the lines replayed with the
        // simulator's clock, the checker's state at each block; the file is read once
        CompiledRun seen = new CompiledRun();
        try (FormOutputs outputs = FormOutputs.open(file, dmc, true, gcnc.output.AtomicOutput.Name.DERIVED)) {
            String text;
            try (Reader in = Session.decode(Files.newInputStream(file))) {
                text = CompiledRun.text(in);
            }
            // as gcnc compile (Session.compileInto): the form that fits the controller, decided when clean;
            // step mode runs one block at a time, so every motion stops at its end there (docs/run.md)
            Compiler.Result r = session.withPrograms(folder).compileInto(outputs, file.getFileName().toString(), file,
                    new StringReader(text), sim, false, Optional.empty(), step, seen);
            if (!r.ok()) {
                return new RunProgram(analysis.report(name, r), r.diagnostics().errorCount(), null, null, null, 0);
            }
            DmcProgram program = seen.program(session.profile());
            outputs.commit();
            return new RunProgram(analysis.report(name, r), 0, program, seen.blocks(text), outputs.form(), outputs.dmcLines());
        } catch (DmcOutputs.Failed e) {
            throw e.problem();
        }
    }
}
