package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.dmc.DmcPrinter;
import gcnc.dmc.Form;
import gcnc.galil.Dialect;
import gcnc.output.AtomicOutput;
import gcnc.output.FormOutputs;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * Session.compileInto, the one compile-to-file wiring of gcnc compile, gcnc run and the studio: the
 * sink the dialect calls for, the form decided when clean, nothing in place until the caller commits.
 */
class CompileIntoTest {
    /** The thesis's own part, on the thesis's machine. */
    private static String program() throws java.io.IOException {
        return Files.readString(Path.of("samples/bishop.nc"));
    }

    private static List<String> written(Session s, String program, Path dmc) throws Exception {
        try (FormOutputs outputs = FormOutputs.open(null, dmc, false, AtomicOutput.Name.GIVEN)) {
            Compiler.Result r = s.compileInto(outputs, "p.nc", null, new StringReader(program), Optional.empty(), false,
                    Optional.empty(), false, CompileObserver.NONE);
            assertTrue(r.ok(), r.diagnostics().sorted().toString());
            assertFalse(Files.exists(dmc), "nothing is in place before the caller commits");
            assertEquals(Form.PROGRAM, outputs.form());
            outputs.commit();
        }
        return Files.readAllLines(dmc);
    }

    @Test
    void theThesisDialectWritesOneCommandALineNoForm() throws Exception {
        Session thesis = Session.open(Session.Options.defaults().withMachine("thesis-2004").withDialect(Dialect.Kind.THESIS));
        List<String> printed = new ArrayList<>();
        thesis.compile(new StringReader(program()), Optional.empty(), false, i -> printed.add(DmcPrinter.print(i.command())));
        Path dmc = Files.createTempDirectory("gcnc-into").resolve("p.dmc");
        assertEquals(printed, written(thesis, program(), dmc)); // unpacked: the thesis's Table 5.2 format
    }

    @Test
    void theGalilDialectPacksTheProgramForm() throws Exception {
        Session galil = Session.open(Session.Options.defaults().withMachine("thesis-2004"));
        List<String> printed = new ArrayList<>();
        galil.compile(new StringReader(program()), Optional.empty(), false, i -> printed.add(DmcPrinter.print(i.command())));
        Path dmc = Files.createTempDirectory("gcnc-into").resolve("p.dmc");
        List<String> lines = written(galil, program(), dmc);
        assertTrue(lines.size() < printed.size(), "packed: " + lines.size() + " lines for " + printed.size() + " commands");
        assertEquals(String.join(";", printed), String.join(";", lines).replace(";;", ";")); // the same commands, in order
    }
}
