package gcnc.cli;

import static gcnc.cli.CliTest.gcnc;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.cli.CliTest.Run;
import gcnc.output.AtomicOutput;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Every output name gcnc chose is refused when someone planted a symbolic link there (E510), the
 * victim untouched and nothing of the compile written; a name the user gave is written through its
 * link as docs/command-line.md says (issue 35: {@code OUT.stream} was written through a planted link).
 */
class OutputLinksTest {
    private Path dir;
    private Path turn;
    private Path victim;

    @BeforeEach
    void copy() throws Exception {
        dir = Files.createTempDirectory("gcnc-links");
        turn = Files.copy(Path.of("src/test/resources/gcnc/cli/turn.nc"), dir.resolve("t.nc"));
        victim = Files.writeString(dir.resolve("victim.txt"), "keep me\n");
    }

    private Run compile(String... more) {
        List<String> args = new ArrayList<>(List.of("compile", turn.toString(), "--machine", "haas"));
        args.addAll(List.of(more));
        return gcnc(args.toArray(String[]::new));
    }

    private void refused(String planted, Run r) throws Exception {
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("error[E510]: " + dir.resolve(planted) + " is a symbolic link"), r.err());
        assertEquals("keep me\n", Files.readString(victim), planted);
        assertTrue(Files.isSymbolicLink(dir.resolve(planted)), "the link itself stays: " + planted);
        for (String written : List.of("b.dmc", "b.dmc.map", "b.stream", "b.stream.map", "t.dmc", "t.dmc.map")) {
            if (!written.equals(planted)) {
                assertFalse(Files.exists(dir.resolve(written), LinkOption.NOFOLLOW_LINKS), written + " beside " + planted);
            }
        }
    }

    @Test
    void theStreamFormsFourFilesAreNeverWrittenThroughAPlantedLink() throws Exception {
        for (String planted : List.of("b.stream", "b.stream.map", "b.dmc.map")) {
            Path link = Files.createSymbolicLink(dir.resolve(planted), victim.getFileName());
            refused(planted, compile("--form", "stream", "-o", dir.resolve("b.dmc").toString()));
            Files.delete(link);
        }
        // without the links the same compile writes all four
        assertEquals(0, compile("--form", "stream", "-o", dir.resolve("b.dmc").toString()).status());
        for (String written : List.of("b.dmc", "b.dmc.map", "b.stream", "b.stream.map")) {
            assertTrue(Files.isRegularFile(dir.resolve(written), LinkOption.NOFOLLOW_LINKS), written);
        }
    }

    @Test
    void theDmcANameGcncChoseIsRefusedAsALinkOneTheUserNamedIsFollowed() throws Exception {
        Files.createSymbolicLink(dir.resolve("t.dmc"), victim.getFileName());
        refused("t.dmc", compile()); // no -o: t.dmc is gcnc's choice
        Files.delete(dir.resolve("t.dmc"));
        Files.writeString(dir.resolve("real.dmc"), "");
        Path named = Files.createSymbolicLink(dir.resolve("b.dmc"), Path.of("real.dmc"));
        assertEquals(0, compile("-o", named.toString()).status());
        assertTrue(Files.isSymbolicLink(named));
        assertTrue(Files.size(dir.resolve("real.dmc")) > 0, "the file the named link leads to gets the DMC");
    }

    @Test
    void theOneWriterRefusesALinkAtADerivedNameAndFollowsAGivenOne() throws Exception {
        // the Gradle plugin's sheets, drawings and reports go through it with Name.DERIVED
        Path link = Files.createSymbolicLink(dir.resolve("report.html"), victim.getFileName());
        AtomicOutput.Refused e = assertThrows(AtomicOutput.Refused.class,
                () -> AtomicOutput.write(link, AtomicOutput.Name.DERIVED, w -> w.write("overwritten\n")));
        assertEquals(gcnc.diag.Code.E510_SIDE_FILE_IS_LINK, e.code());
        Path dangling = Files.createSymbolicLink(dir.resolve("summary.txt"), Path.of("nowhere.txt"));
        assertThrows(AtomicOutput.Refused.class,
                () -> AtomicOutput.write(dangling, AtomicOutput.Name.DERIVED, w -> w.write("x\n")));
        assertFalse(Files.exists(dir.resolve("nowhere.txt")));
        assertEquals("keep me\n", Files.readString(victim));
        AtomicOutput.write(link, AtomicOutput.Name.GIVEN, w -> w.write("named\n"));
        assertEquals("named\n", Files.readString(victim));
        assertTrue(Files.isSymbolicLink(link));
    }
}
