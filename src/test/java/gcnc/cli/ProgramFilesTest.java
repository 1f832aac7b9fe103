package gcnc.cli;

import gcnc.ProgramFiles;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * One list of program extensions for every front end (gcnc.ProgramFiles): the command line given a
 * folder, the Gradle plugin's default programs and the JUnit fixtures; what a folder skipped is said.
 */
class ProgramFilesTest {
    private static Path shop() throws IOException {
        Path dir = Files.createTempDirectory("gcnc-programs");
        Files.createDirectories(dir.resolve("op2"));
        for (String name : List.of("O1000.NC", "turn.ngc", "face.tap", "t24.gcode", "op2/part.nc", "notes.txt",
                "setup.txt", "part.dmc", "README", ".hidden.nc~")) {
            Files.writeString(dir.resolve(name), "M30\n");
        }
        return dir;
    }

    @Test
    void theDefaultListIsWhatThePostsAndTheCorpusUse() {
        assertEquals(List.of("nc", "ngc", "tap", "gcode"), ProgramFiles.EXTENSIONS);
    }

    @Test
    void aFolderGivesItsProgramsAndCountsWhatItSkipped() throws IOException {
        Path dir = shop();
        ProgramFiles.Scan s = ProgramFiles.scan(dir, ProgramFiles.EXTENSIONS);
        assertEquals(List.of("O1000.NC", "face.tap", "op2/part.nc", "t24.gcode", "turn.ngc"),
                s.programs().stream().map(p -> dir.relativize(p).toString()).toList());
        assertEquals(Map.of("txt", 2, "dmc", 1, "", 1), s.skipped());
        assertEquals(4, s.skippedCount());
        assertEquals(s.programs(), ProgramFiles.in(dir, ProgramFiles.EXTENSIONS));
    }

    @Test
    void aShopThatSavesTxtAddsIt() throws IOException {
        Path dir = shop();
        ProgramFiles.Scan s = ProgramFiles.scan(dir, List.of(".TXT", "nc"));
        assertEquals(4, s.programs().size(), s.programs().toString());
        assertTrue(ProgramFiles.isProgram("notes.TXT", List.of("txt")));
        assertFalse(ProgramFiles.isProgram("notes.txt", ProgramFiles.EXTENSIONS));
    }

    @Test
    void theBuildsListReachesItsTestsThroughTheSystemProperty() {
        String before = System.getProperty(ProgramFiles.PROPERTY);
        try {
            System.clearProperty(ProgramFiles.PROPERTY);
            assertEquals(ProgramFiles.EXTENSIONS, ProgramFiles.configured());
            System.setProperty(ProgramFiles.PROPERTY, "NC, .cnc");
            assertEquals(List.of("nc", "cnc"), ProgramFiles.configured());
        } finally {
            if (before == null) {
                System.clearProperty(ProgramFiles.PROPERTY);
            } else {
                System.setProperty(ProgramFiles.PROPERTY, before);
            }
        }
    }

    @Test
    void theCommandLineChecksTheGcodeFileAndSaysWhatItSkipped() throws IOException {
        Path dir = shop();
        CliTest.Run r = CliTest.gcnc("check", dir.toString());
        assertTrue(r.out().contains("t24.gcode: 1 block, no errors"), "a .gcode program is checked: " + r.out());
        assertTrue(r.out().contains(dir + ": skipped 4 files (no extension 1, .dmc 1, .txt 2): not a program's"
                + " extension (.nc, .ngc, .tap, .gcode); --extensions adds one"), r.out());
        CliTest.Run txt = CliTest.gcnc("check", dir.toString(), "--extensions", "txt");
        assertTrue(txt.out().contains("total: 2 programs"), txt.out());
        assertTrue(txt.out().contains("skipped 7 files"), txt.out());
        CliTest.Run quiet = CliTest.gcnc("check", "--quiet", dir.toString());
        assertFalse(quiet.out().contains("skipped"), quiet.out());
    }
}
