package gcnc.flow;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.Compiler;
import gcnc.galil.Dialect;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * A called program in a file beside the main one whose first block after its O number is a macro
 * statement, the usual shape of a Fanuc macro file (issue 35: ArrayIndexOutOfBoundsException in
 * Library.read, and the studio answered 500).
 */
class CalledMacroFileTest {
    @Test
    void aCalledFileThatOpensWithAMacroStatementIsRead() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-called-macro");
        Files.writeString(dir.resolve("O1000.nc"), "O1000\n#1=5\nG00 X#1\nIF [#1 GT 9] GOTO 20\nN20 M99\n");
        String main = "O0001\nG00 G21 G99\nT0101\nG97 S800 M03\nG00 X52. Z2.\nM98 P1000\nM30\n";
        Tables t = Tables.builtIn();
        for (String control : new String[] {"fanuc-a", "haas"}) {
            Compiler.Settings s = new Compiler.Settings(t, ProfileLoader.load("generic", TableSource.builtIn(), t, control),
                    Dialect.Kind.GALIL, Optional.empty()).withPrograms(dir);
            Compiler.Result r = Compiler.check(new StringReader(main), s);
            assertEquals("", ProgramFlowTest.messages(r), control);
        }
    }
}
