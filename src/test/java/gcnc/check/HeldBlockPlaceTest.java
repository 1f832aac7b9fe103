package gcnc.check;

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
 * A check that holds a block until the next move (a corner, the nose compensation, an angle) reports
 * on it while the flow has gone on, perhaps into a called program's file: the finding is the held
 * block's, in its own file, with no note of a call it was not made in.
 */
class HeldBlockPlaceTest {
    private static final String START = "G21 G40 G99\nG50 S2000\nT0101\nG97 S500 M03\n";

    /** Each finding as "E172 main:8", or "E145 O2000.nc:2" for the called program's file. */
    private static List<String> found(String main, String called) throws Exception {
        Path dir = Files.createTempDirectory("gcnc-held");
        Files.writeString(dir.resolve("O2000.nc"), called);
        Session s = Session.open(Session.Options.defaults().withMachine("haas")).withPrograms(Optional.of(dir));
        Compiler.Result r = s.compile(new StringReader(main), Optional.empty(), false, line -> { });
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            String file = d.origin().file() == null ? "main" : Path.of(d.origin().file()).getFileName().toString();
            out.add(d.code().id() + " " + file + ":" + d.span().line());
        }
        return out;
    }

    /** Line 8's step is too short for the nose; its corner is only known at O2000's first move, which is too short too. */
    @Test
    void theNoseCompensationsHeldBlockIsReportedInItsOwnFile() throws Exception {
        String main = START + "G00 X50. Z2.\nG42 G01 X40. Z0. F0.2\nG01 Z-10.\nG01 X40.1\nM98 P2000\nG40 G00 X100.\nM30\n";
        String called = "O2000\nG01 X40.0 Z-10.01\nG01 Z-20.\nM99\n";
        assertEquals(List.of("E172 main:8", "E172 O2000.nc:2", "E145 O2000.nc:2"), found(main, called));
    }

    /** The chamfer of line 7 meets the next move in O2000: too large for it, an error at line 7's ,C. */
    @Test
    void aHeldCornerIsReportedInItsOwnFile() throws Exception {
        String main = START + "G00 X38. Z2.\nG01 Z0. F0.2\nG01 X40. Z-10. ,C5.\nM98 P2000\nG00 X100.\nM30\n";
        String called = "O2000\nG01 X44.\nG01 Z-20.\nM99\n";
        assertEquals(List.of("E611 main:7"), found(main, called));
    }
}
