package gcnc.cli;

import static gcnc.cli.CliTest.gcnc;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.cli.CliTest.Run;
import gcnc.send.RunFault;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The smaller findings of issue 35's attack, each failing before its fix. */
class SmallFindingsTest {
    @Test
    void simulatingAResidentProgramSaysItsMotionIsInTheStream() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-resident");
        Path turn = Files.copy(Path.of("src/test/resources/gcnc/cli/turn.nc"), dir.resolve("t.nc"));
        assertEquals(0, gcnc("compile", turn.toString(), "--machine", "haas", "--form", "stream").status());
        Run r = gcnc("simulate", dir.resolve("t.dmc").toString(), "--machine", "haas");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().contains(dir.resolve("t.dmc") + ":1:1: note[E864]: " + dir.resolve("t.dmc")
                + " is the resident program of the stream form and moves nothing itself: its motion is in "
                + dir.resolve("t.stream")), r.err());
        // the program form moves by itself: no note
        assertEquals(0, gcnc("compile", turn.toString(), "--machine", "haas").status());
        assertFalse(gcnc("simulate", dir.resolve("t.dmc").toString(), "--machine", "haas").err().contains("E864"));
    }

    @Test
    void aRunTargetThatIsAPlainFileOrAFolderIsNoSerialPort() throws Exception {
        Path file = Files.writeString(Files.createTempFile("gcnc-not-a-port", ".txt"), "keep me\n");
        for (Path p : new Path[] {file, file.getParent()}) {
            RunFault f = assertThrows(RunFault.class, () -> SerialLink.open(p.toString(), 115200, true));
            assertEquals(gcnc.diag.Code.E865_PORT_NOT_A_DEVICE, f.code(), p.toString());
        }
        assertEquals("keep me\n", Files.readString(file));
        assertTrue(SerialLink.characterDevice(Path.of("/dev/null")), "a character device passes this check");
    }
}
