package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.diag.Diagnostic;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * Where the simulator's findings go when the program calls a subprogram (M98): each in the file
 * and calls of the block whose DMC caused it, with the note of the call, as the checker's are.
 */
class CalledProgramPlaceTest {
    private static final String START = "G21 G40 G99\nG50 S2000\nT0101\nG97 S500 M03\nG00 X50. Z2.\n";

    /** Each finding as "E303 O1000.nc:3 O1000@8", or "main" for the program's file; its calls by program and line. */
    private static List<String> found(Compiler.Result r) {
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            String file = d.origin().file() == null ? "main" : Path.of(d.origin().file()).getFileName().toString();
            StringBuilder s = new StringBuilder(d.code().id() + " " + file + ":" + d.span().line());
            d.origin().calls().forEach(c -> s.append(' ').append(c.program()).append('@').append(c.line()));
            out.add(s.toString());
        }
        return out;
    }

    private static Compiler.Result compile(String main, Path programs) throws Exception {
        Session s = Session.open(Session.Options.defaults().withMachine("haas")).withPrograms(Optional.of(programs));
        return s.compile(new StringReader(main), Optional.of(s.simulation()), false, line -> { });
    }

    /**
     * The planner runs a feed on from the main program into a subprogram of the same file, one
     * sequence: the crash in the subprogram's blocks is theirs, called from line 8 (E136), not the
     * main program's, where the sequence's first motion is.
     */
    @Test
    void aSequenceRunningOnIntoASubprogramOfTheSameFilePlacesItsCrashInTheSubprogram() throws Exception {
        String main = START + "G01 X40. F0.2\nG01 Z-10.\nM98 P1000\nG00 X100.\nM30\n"
                + "O1000\nG01 X45. Z-20.\nG01 Z-155.\nG01 X100.\nM99\n";
        Compiler.Result r = compile(main, Files.createTempDirectory("gcnc-called"));
        assertEquals(List.of("E303 main:13 O1000@8", "E136 main:13", "E303 main:14 O1000@8", "E136 main:14"), found(r));
    }

    /** The same subprogram in a file of its own (the planner ends the sequence at the call): its file, and E145. */
    @Test
    void aCrashInASubprogramOfItsOwnFileIsInThatFile() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-called");
        Files.writeString(dir.resolve("O1000.nc"), "O1000\nG01 X45. Z-20.\nG01 Z-155.\nG01 X100.\nM99\n");
        Compiler.Result r = compile(START + "G01 X40. F0.2\nG01 Z-10.\nM98 P1000\nG00 X100.\nM30\n", dir);
        assertEquals(List.of("E303 O1000.nc:3 O1000@8", "E145 O1000.nc:3", "E303 O1000.nc:4 O1000@8", "E145 O1000.nc:4"),
                found(r));
    }
}
