package gcnc.studio;

import com.google.gson.JsonObject;
import gcnc.Compiler;
import gcnc.Session;
import gcnc.dmc.Form;
import gcnc.dmc.Instruction;
import gcnc.machine.MachineProfile;
import gcnc.output.DmcOutputs;
import gcnc.output.FormOutputs;
import gcnc.send.BlockTable;
import gcnc.send.DmcProgram;
import gcnc.sim.SimOptions;
import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.function.Consumer;

/**
 * A saved program made ready to run, step for step as {@code gcnc run FILE} makes it (SendCommand):
 * checked, compiled and simulated (blended as the profile plans it; every motion stopped at its end
 * in step mode), written beside it only when clean in the form {@code gcnc compile} chooses
 * ({@code FILE.dmc} and its map, and {@code FILE.stream} when the program does not fit the
 * controller), the compiled instructions kept as the program sent, with the checker's state at each
 * block for the live display. A program that is not clean comes back refused, with its diagnostics,
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
        List<Instruction> compiled = new ArrayList<>();
        Compiler.Result r;
        DmcProgram program;
        Form form;
        int dmcLines;
        try (FormOutputs outputs = FormOutputs.open(file, dmc, true, gcnc.output.AtomicOutput.Name.DERIVED)) {
            outputs.mapSource(file.getFileName().toString(), file);
            Consumer<Instruction> written = outputs.sink(Optional.empty(), session.profile().controllerLimits());
            Consumer<Instruction> sink = i -> {
                compiled.add(i);
                written.accept(i);
            };
            try (Reader in = Session.decode(Files.newInputStream(file))) {
                Session s = session.withPrograms(folder);
                // step mode runs one block at a time, so every motion stops at its end there (docs/run.md)
                r = step ? s.compileExactStop(in, sim, sink) : s.compile(in, sim, false, sink);
            }
            if (!r.ok()) {
                return new RunProgram(analysis.report(name, r), r.diagnostics().errorCount(), null, null, null, 0);
            }
            form = outputs.finish(r.diagnostics());
            program = DmcProgram.of(compiled, session.profile());
            outputs.commit();
            dmcLines = outputs.dmcLines();
        } catch (DmcOutputs.Failed e) {
            throw e.problem();
        }
        // with a blank given, the work offsets on the blank's face, as the compile placed them
        MachineProfile onBlank = sim.flatMap(SimOptions::stock).map(b -> session.profile().withStickout(b.stickout()))
                .orElse(session.profile());
        try (Reader again = Session.decode(Files.newInputStream(file))) {
            BlockTable blocks = BlockTable.of(again, session.tables(), onBlank, folder);
            return new RunProgram(analysis.report(name, r), 0, program, blocks, form, dmcLines);
        }
    }
}
