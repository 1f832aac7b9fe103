package gcnc.gradle;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.dmc.SourceMap;
import gcnc.output.DmcOutputs;
import java.io.File;
import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.gradle.api.tasks.OutputDirectory;

/**
 * {@code gcncCompile}: each program checked, translated to Galil and simulated, as {@code gcnc
 * compile} does, into build/gcnc/&lt;path under the programs&gt;.dmc with its .dmc.map beside it.
 * A program with an error gets no output; a clean one gets both files or neither, through
 * {@link DmcOutputs} as on the command line. The outputs of an earlier run are cleared first.
 */
public class CompileTask extends GcncTask {
    @OutputDirectory
    public File getOutputDir() {
        return new File(getProject().getBuildDir(), "gcnc");
    }

    @Override
    protected void begin() {
        getProject().delete(getOutputDir());
        getOutputDir().mkdirs();
    }

    @Override
    protected void process(Session session, Program program, Findings findings) throws IOException {
        Path dmc = getOutputDir().toPath().resolve(program.withExtension(".dmc"));
        Files.createDirectories(dmc.getParent());
        DmcOutputs outputs;
        try {
            outputs = DmcOutputs.open(program.file().toPath(), dmc, true);
        } catch (DmcOutputs.Failed e) {
            throw new IOException("cannot write " + e.path() + ": " + e.problem().getMessage(), e.problem());
        }
        try (outputs; Reader in = program.open()) {
            SourceMap mapper = SourceMap.toEntries(outputs::mapEntry).withStops(outputs::mapStop);
            outputs.mapSource(program.file().getName(), program.file().toPath());
            Compiler.Result r = session.compile(in, Optional.of(session.simulation()), false,
                    mapper.wrap(line -> outputs.dmcLine(line.text())));
            findings.report(program.shown(), r.diagnostics());
            if (r.ok()) {
                outputs.commit();
            }
        }
    }
}
