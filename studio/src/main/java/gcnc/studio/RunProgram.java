package gcnc.studio;

import com.google.gson.JsonObject;
import gcnc.Compiler;
import gcnc.Session;
import gcnc.dmc.DmcPrinter;
import gcnc.dmc.SourceMap;
import gcnc.machine.MachineProfile;
import gcnc.output.DmcOutputs;
import gcnc.send.BlockTable;
import gcnc.send.DmcProgram;
import gcnc.send.MapReader;
import gcnc.sim.SimOptions;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * A saved program made ready to run, step for step as {@code gcnc run FILE} makes it (SendCommand):
 * checked, compiled and simulated with every motion stopped at its end, {@code FILE.dmc} and its map
 * written beside it only when clean, then the DMC and the map read back from disk (so that what runs
 * is what the files say) with the checker's state at each block for the live display. A program that
 * is not clean comes back refused, with its diagnostics, and nothing else is done.
 *
 * @param report  the diagnostics, as {@code gcnc check --format json} writes them
 * @param program the DMC program and its source map (null when refused)
 * @param blocks  the modal state at each G-code line (null when refused)
 */
record RunProgram(JsonObject report, int errors, DmcProgram program, BlockTable blocks) {
    boolean clean() {
        return program != null;
    }

    /** {@code file} (named {@code name} on the page) compiled to {@code dmc} and its map, and read back. */
    static RunProgram prepare(Session session, Analysis analysis, String name, Path file, Path dmc) throws IOException {
        Optional<Path> folder = Optional.ofNullable(file.getParent());
        Optional<SimOptions> sim = Optional.of(session.simulation());
        Compiler.Result r;
        try (DmcOutputs outputs = DmcOutputs.open(file, dmc, true)) {
            SourceMap mapper = SourceMap.toEntries(outputs::mapEntry);
            outputs.mapSource(file.getFileName().toString(), file);
            try (Reader in = Session.decode(Files.newInputStream(file))) {
                // exact stop: the sender follows the program sequence by sequence (docs/run.md), as gcnc run
                r = session.withPrograms(folder).compileExactStop(in, sim,
                        mapper.wrap(i -> outputs.dmcLine(DmcPrinter.print(i.command()))));
            }
            if (!r.ok()) {
                return new RunProgram(analysis.report(name, r), r.diagnostics().errorCount(), null, null);
            }
            outputs.commit();
        } catch (DmcOutputs.Failed e) {
            throw e.problem();
        }
        // with a blank given, the work offsets on the blank's face, as the compile placed them
        MachineProfile onBlank = sim.flatMap(SimOptions::stock).map(b -> session.profile().withStickout(b.stickout()))
                .orElse(session.profile());
        try (BufferedReader map = Files.newBufferedReader(DmcOutputs.mapFile(dmc), StandardCharsets.UTF_8);
             Reader again = Session.decode(Files.newInputStream(file))) {
            DmcProgram program = DmcProgram.read(Files.readAllLines(dmc, StandardCharsets.UTF_8), MapReader.read(map),
                    session.profile());
            BlockTable blocks = BlockTable.of(again, session.tables(), onBlank, folder);
            return new RunProgram(analysis.report(name, r), 0, program, blocks);
        }
    }
}
