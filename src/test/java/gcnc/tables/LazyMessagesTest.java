package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The built-in messages are read when the first one is rendered, not at every start (issue 35,
 * start-up); the tables of a directory are read and checked whole at load, so a broken errors.csv
 * still stops a run before it starts.
 */
class LazyMessagesTest {
    /** The built-in tables, noting each file read. */
    private static TableSource recording(List<String> read) {
        TableSource jar = TableSource.builtIn();
        return new TableSource() {
            @Override
            public String read(String name) throws TableException {
                read.add(name);
                return jar.read(name);
            }

            @Override
            public String describe(String name) {
                return jar.describe(name);
            }

            @Override
            public boolean isBuiltIn() {
                return true;
            }
        };
    }

    @Test
    void builtInMessagesAreReadAtTheFirstMessage() throws TableException {
        List<String> read = new ArrayList<>();
        Tables t = Tables.load(recording(read));
        assertFalse(read.contains("errors.csv"), read.toString());
        assertFalse(read.contains("phrases.csv"), read.toString());
        gcnc.diag.Messages en = t.messagesIn(ErrorMessages.Lang.EN);
        assertFalse(read.contains("errors.csv"), "a reporter holding the messages reads nothing yet");
        assertEquals(Tables.builtIn().messages().render(Code.E506_OUT_OF_MEMORY, List.of("64"), ErrorMessages.Lang.EN),
                en.render(Code.E506_OUT_OF_MEMORY, List.of("64")));
        assertTrue(read.contains("errors.csv") && read.contains("phrases.csv"), read.toString());
        int reads = read.size();
        t.messages();
        assertEquals(reads, read.size(), "read once");
    }

    @Test
    void aDirectorysBrokenMessagesStopTheLoad() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-lazy");
        for (String name : new String[] {"parameter_limits.csv", "tool_offsets.csv", "work_offsets.csv", "errors.csv",
                "phrases.csv"}) {
            Files.writeString(dir.resolve(name), TableSource.builtIn().read(name));
        }
        Path e = dir.resolve("errors.csv");
        Files.writeString(e, Files.readString(e).replace("arc radius R{0}", "arc radius R{0"));
        TableException fault = assertThrows(TableException.class, () -> Tables.load(TableSource.directory(dir)));
        assertTrue(fault.path().endsWith("errors.csv"), fault.path());
    }
}
