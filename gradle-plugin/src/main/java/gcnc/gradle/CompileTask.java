package gcnc.gradle;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.galil.SourceMap;
import java.io.File;
import java.io.IOException;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Optional;
import org.gradle.api.tasks.OutputDirectory;

/**
 * {@code gcncCompile}: each program checked, translated to Galil and simulated, as {@code gcnc
 * compile} does, into build/gcnc/&lt;path under the programs&gt;.dmc with its .dmc.map beside it.
 * A program with an error gets no output (none half-written: both files are written aside and
 * moved in place only for a clean result); the outputs of an earlier run are cleared first.
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
        Path map = dmc.resolveSibling(dmc.getFileName() + ".map");
        Files.createDirectories(dmc.getParent());
        Path dmcPart = dmc.resolveSibling(dmc.getFileName() + ".part");
        Path mapPart = map.resolveSibling(map.getFileName() + ".part");
        boolean ok = false;
        try (Reader in = program.open();
             Writer dmcOut = Files.newBufferedWriter(dmcPart, StandardCharsets.UTF_8);
             Writer mapOut = Files.newBufferedWriter(mapPart, StandardCharsets.UTF_8)) {
            SourceMap mapper = new SourceMap(line -> write(mapOut, line));
            write(mapOut, SourceMap.sourceLine(program.file().getName()));
            Compiler.Result r = session.compile(in, Optional.of(session.simulation()), false,
                    mapper.wrap(line -> write(dmcOut, line.text())));
            findings.report(program.shown(), r.diagnostics());
            ok = r.ok();
        } catch (UncheckedIOException e) {
            throw e.getCause();
        } finally {
            if (ok) {
                Files.move(dmcPart, dmc, StandardCopyOption.REPLACE_EXISTING);
                Files.move(mapPart, map, StandardCopyOption.REPLACE_EXISTING);
            } else {
                Files.deleteIfExists(dmcPart);
                Files.deleteIfExists(mapPart);
            }
        }
    }

    private static void write(Writer out, String line) {
        try {
            out.write(line);
            out.write('\n');
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
