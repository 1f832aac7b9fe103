package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.tables.TableException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/**
 * What a long-running JVM (the daemon, the studio) keeps between sessions: the tables and profiles
 * built into the jar, read once; a machine or a tables folder the user names by path, read again
 * every time, so that an edit between two runs counts.
 */
class SessionShippedTest {
    @Test
    void theShippedTablesAndProfilesAreReadOnce() throws Exception {
        Session a = Session.open(Session.Options.defaults().withMachine("haas"));
        Session b = Session.open(Session.Options.defaults().withMachine("haas"));
        assertSame(a.tables(), b.tables());
        assertSame(a.profile(), b.profile());
        Session fanucControl = Session.open(Session.Options.defaults().withMachine("haas").withControl("fanuc-a"));
        assertNotSame(a.profile(), fanucControl.profile(), "another control is another profile");
        assertEquals("fanuc-a", fanucControl.profile().control().name());
    }

    @Test
    void aMachineGivenAsAPathIsReadAgainEveryTime() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-shipped");
        Path machine = dir.resolve("lathe.machine");
        String generic = new String(Session.class.getResourceAsStream("/tables/machines/generic.machine").readAllBytes(),
                java.nio.charset.StandardCharsets.UTF_8);
        Files.writeString(machine, generic);
        Session first = Session.open(Session.Options.defaults().withMachine(machine.toString()));
        Files.writeString(machine, generic + "\nno_such_key = 1\n"); // the user edits it: now it is wrong
        assertThrows(TableException.class, () -> Session.open(Session.Options.defaults().withMachine(machine.toString())));
        Files.writeString(machine, generic);
        assertNotSame(first.profile(), Session.open(Session.Options.defaults().withMachine(machine.toString())).profile());
    }

    @Test
    void aMachineNameGcncDoesNotShipFailsEveryTime() {
        for (int i = 0; i < 2; i++) {
            TableException e = assertThrows(TableException.class,
                    () -> Session.open(Session.Options.defaults().withMachine("hass")));
            assertTrue(e.getMessage().contains("haas"), e.getMessage()); // the typo's nearest name
        }
    }
}
