package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

class TablesTest {
    @Test
    void tablesSixToNine() {
        Tables t = Tables.builtIn();
        assertTrue(t.limit('N').orElseThrow().integer());
        assertEquals(9999999, t.limit('N').orElseThrow().upper());
        assertEquals(20, t.toolOffsets().size());
        assertEquals(0.2, t.toolOffsets().get(2).x(), 1e-12);
        assertEquals(20, t.workOffsets().size());
    }

    @Test
    void anEditedCopyIsReadWithoutRebuilding() throws Exception {
        Path dir = copyOfTables();
        Path e = dir.resolve("errors.csv");
        Files.writeString(e, Files.readString(e).replace("arc radius R{0}", "radius R{0}"));
        Tables t = Tables.load(TableSource.directory(dir));
        assertTrue(t.messages().template(gcnc.diag.Code.E101_ARC_RADIUS_TOO_SMALL, ErrorMessages.Lang.EN)
                .startsWith("radius R{0}"));
    }

    @Test
    void aBadValueIsReportedWhereItIs() throws Exception {
        Path dir = copyOfTables();
        Path m = dir.resolve("tool_offsets.csv");
        Files.writeString(m, Files.readString(m).replaceFirst("\n3,", "\n4,"));
        TableException e = assertThrows(TableException.class, () -> Tables.load(TableSource.directory(dir)));
        assertTrue(e.path().endsWith("tool_offsets.csv"));
    }

    static Path copyOfTables() throws IOException {
        Path dir = Files.createTempDirectory("gcnc-tables");
        try (Stream<Path> s = Files.list(Path.of("tables"))) {
            for (Path p : (Iterable<Path>) s::iterator) {
                if (Files.isRegularFile(p)) {
                    Files.copy(p, dir.resolve(p.getFileName()), StandardCopyOption.REPLACE_EXISTING);
                }
            }
        }
        return dir;
    }
}
