package gcnc.studio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The rule under every file the studio touches, over many names: a name either is refused or stands
 * for a path strictly below DIR that is DIR joined with the name's own segments (no "..", ".", empty
 * segment, absolute path, backslash, colon or control character gets through, in any mix).
 */
class WorkspaceNamesTest {
    private static final String[] PIECES = {"..", ".", "", "/", "\\", ":", "a", "b.nc", "C.NC", "~", "%2e%2e",
        "\u0000", "\n", "\u007f", "é", " ", "..a", "a..", "...", "parts", "-", "$HOME"};

    @Test
    void everyNameIsRefusedOrLiesBelowTheFolder() throws Exception {
        Workspace w = new Workspace(Files.createTempDirectory("gcnc-names"));
        Random random = new Random(20261126);
        int accepted = 0;
        for (int i = 0; i < 20000; i++) {
            StringBuilder name = new StringBuilder();
            for (int n = 1 + random.nextInt(6); n > 0; n--) {
                name.append(PIECES[random.nextInt(PIECES.length)]);
            }
            Path p;
            try {
                p = w.resolve(name.toString());
            } catch (Workspace.Refused r) {
                assertEquals(400, r.status(), name.toString());
                continue;
            }
            accepted++;
            String s = name.toString();
            assertTrue(p.normalize().equals(p) && p.startsWith(w.root()) && !p.equals(w.root()), s + " -> " + p);
            assertEquals(s, w.name(p), "the name of the path is the name given");
            for (String segment : s.split("/", -1)) {
                assertTrue(!segment.isEmpty() && !segment.equals(".") && !segment.equals(".."), s);
                assertTrue(segment.chars().noneMatch(c -> c < 0x20 || c == 0x7f || c == '\\' || c == ':'), s);
            }
        }
        assertTrue(accepted > 1000, "the names tried include sound ones: " + accepted);
    }
}
