package gcnc.gradle;

import gcnc.CompileObserver;
import gcnc.Compiler;
import gcnc.Session;
import gcnc.output.DmcOutputs;
import gcnc.output.FormOutputs;
import java.io.File;
import java.io.IOException;
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.gradle.api.tasks.CacheableTask;

/**
 * {@code gcncCompile}: each program checked, translated to Galil and simulated, as {@code gcnc
 * compile} does, into build/gcnc/&lt;path under the programs&gt;.dmc with its .dmc.map beside it.
 * A program longer than the profile's controller memory is written in the stream form (a resident
 * .dmc and a .stream). A program with an error gets no output; a clean one gets all its files or
 * none, through {@link FormOutputs} as on the command line. The outputs of a program judged again,
 * or removed, are deleted first; those of the others are kept ({@link LibraryRun}).
 */
@CacheableTask
public class CompileTask extends WritingTask {
    @Override
    protected File outputFolder() {
        return new File(getProject().getBuildDir(), "gcnc");
    }

    /** A program's .dmc and .dmc.map, and in the stream form its .stream and .stream.map. */
    @Override
    protected void clearOutputs(String relativePath) throws IOException {
        Path dmc = getOutputDir().toPath().resolve(GcncTask.withExtension(relativePath, ".dmc"));
        Path stream = FormOutputs.streamFile(dmc);
        for (Path p : List.of(dmc, dmc.resolveSibling(dmc.getFileName() + ".map"), stream,
                stream.resolveSibling(stream.getFileName() + ".map"))) {
            Files.deleteIfExists(p);
        }
    }

    @Override
    protected Outcome process(Session session, Program program) throws IOException {
        Path dmc = getOutputDir().toPath().resolve(program.withExtension(".dmc"));
        Files.createDirectories(dmc.getParent());
        FormOutputs outputs;
        try {
            outputs = FormOutputs.open(program.file().toPath(), dmc, true, gcnc.output.AtomicOutput.Name.DERIVED);
        } catch (DmcOutputs.Failed e) {
            throw new IOException("cannot write " + e.path() + ": " + e.problem().getMessage(), e.problem());
        }
        try (outputs; Reader in = program.open()) {
            // as gcnc compile: the form that fits the profile's controller (the program, or a resident
            // program and its .stream), decided when clean
            Compiler.Result r = session.compileInto(outputs, program.file().getName(), program.file().toPath(), in,
                    Optional.of(simulation(session, program)), false, Optional.empty(), false, CompileObserver.NONE);
            Outcome o = outcome(r, List.of());
            if (r.ok()) {
                try {
                    outputs.commit();
                } catch (IOException e) {
                    List<gcnc.diag.Diagnostic> all = new java.util.ArrayList<>(o.diagnostics());
                    all.add(gcnc.diag.Diagnostic.error(gcnc.diag.Code.E500_IO, gcnc.diag.Span.of(1, 1),
                            gcnc.diag.Phrase.IO_CANNOT_READ_OR_WRITE.arg(), gcnc.diag.Phrase.reason(e)));
                    return new Outcome(all, o.calls(), o.extra());
                }
            }
            return o;
        }
    }
}
