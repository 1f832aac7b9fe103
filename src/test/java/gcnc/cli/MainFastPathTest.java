package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.OutputStreamWriter;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * gcnc --version answers without building picocli's model (issue 35, start-up): the same bytes and
 * status as picocli's own --version, and only when the version is the whole command line.
 */
class MainFastPathTest {
    /** What Main.execute prints: the path a cold run and the resident checker take. */
    private static byte[][] executed(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.execute(args, new Main.Invocation(new ByteArrayInputStream(new byte[0]), out, err,
                Map.of(), false, p -> false));
        return new byte[][] {out.toByteArray(), err.toByteArray(), {(byte) status}};
    }

    /** What picocli's model prints for the same arguments, built as before the fast path. */
    private static byte[][] throughPicocli(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        CommandLine cl = Main.commandLine(new Main.Streams(new ByteArrayInputStream(new byte[0]), out, Map.of(), false,
                p -> false), HelpLanguage.of(args, Map.of()), args);
        cl.setOut(new PrintWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), true));
        cl.setErr(new PrintWriter(new OutputStreamWriter(err, StandardCharsets.UTF_8), true));
        int status = cl.execute(args);
        return new byte[][] {out.toByteArray(), err.toByteArray(), {(byte) status}};
    }

    @Test
    void versionAloneIsPicocliBytes() {
        for (String flag : new String[] {"--version", "-V"}) {
            byte[][] fast = executed(flag);
            byte[][] slow = throughPicocli(flag);
            assertArrayEquals(slow[0], fast[0], flag);
            assertArrayEquals(slow[1], fast[1], flag);
            assertEquals(slow[2][0], fast[2][0], flag);
            String text = new String(fast[0], StandardCharsets.UTF_8);
            assertTrue(text.startsWith("gcnc ") && text.endsWith(System.lineSeparator()), text);
        }
    }

    @Test
    void onlyTheWholeCommandLineTakesTheFastPath() {
        assertTrue(Main.isVersionAlone(new String[] {"--version"}));
        assertTrue(Main.isVersionAlone(new String[] {"-V"}));
        assertFalse(Main.isVersionAlone(new String[] {"--lang", "es", "--version"}));
        assertFalse(Main.isVersionAlone(new String[] {"--version", "check"}));
        assertFalse(Main.isVersionAlone(new String[] {"--versions"}));
        assertFalse(Main.isVersionAlone(new String[0]));
        // a version with picocli's format or colour markup would print differently: picocli prints it
        assertFalse(Main.plain(new String[] {"gcnc 1.0 (100%)"}));
        assertFalse(Main.plain(new String[] {"gcnc @|bold 1.0|@"}));
        assertTrue(Main.plain(new String[] {"gcnc (development build)"}));
    }

    @Test
    void versionWithOtherWordsIsStillPicocli() {
        byte[][] fast = executed("--version", "check");
        byte[][] slow = throughPicocli("--version", "check");
        assertArrayEquals(slow[0], fast[0]);
        assertArrayEquals(slow[1], fast[1]);
        assertEquals(slow[2][0], fast[2][0]);
    }
}
