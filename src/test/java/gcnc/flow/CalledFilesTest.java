package gcnc.flow;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.Compiler;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The files beside a program that its calls looked for, found or not (Compiler.Result.calledFiles):
 * what the Gradle plugin's call graph is made of, so that an edit of O1000.nc judges its callers again
 * (issue 35 item 7). Check and compile give the same list.
 */
class CalledFilesTest {
    private static final Tables T = Tables.builtIn();

    private static Compiler.Settings haas(Path dir) throws Exception {
        return new Compiler.Settings(T, ProfileLoader.load("generic", TableSource.builtIn(), T, "haas"), "galil",
                Optional.empty()).withPrograms(dir);
    }

    @Test
    void aCallReadingAFileBesideNamesEveryNameItLooksFor() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-called-files");
        Files.writeString(dir.resolve("O1000.nc"), "O1000\nG00 X50.\nM99\n");
        String main = "O0001\nG00 G21 G99\nT0101\nG97 S800 M03\nG00 X52. Z2.\nM98 P1000\nM30\n";
        List<Path> expected = List.of(dir.resolve("O1000.nc"), dir.resolve("1000.nc")); // Library.names(1000)
        assertEquals(expected, Compiler.check(new StringReader(main), haas(dir)).calledFiles());
        assertEquals(expected, Compiler.compile(new StringReader(main), haas(dir), i -> { }).calledFiles());
    }

    @Test
    void aCallOfAMissingFileNamesItTooAndItsCallsInsideACalledFileAreAmongThem() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-called-files");
        Files.writeString(dir.resolve("O1000.nc"), "O1000\nM98 P2000\nM99\n"); // O2000.nc is not there: E131
        String main = "O0001\nG00 G21 G99\nT0101\nG97 S800 M03\nG00 X52. Z2.\nM98 P1000\nM30\n";
        assertEquals(List.of(dir.resolve("O1000.nc"), dir.resolve("1000.nc"), dir.resolve("O2000.nc"), dir.resolve("2000.nc")),
                Compiler.check(new StringReader(main), haas(dir)).calledFiles());
    }

    @Test
    void aCallOfAProgramInTheSameFileLooksForNoFile() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-called-files");
        String main = "O0001\nG00 G21 G99\nT0101\nG97 S800 M03\nG00 X52. Z2.\nM98 P1000\nM30\nO1000\nG00 X50.\nM99\n";
        assertEquals(List.of(), Compiler.check(new StringReader(main), haas(dir)).calledFiles());
    }
}
