package gcnc.tables;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
    void tableThreeHasTheThesisPreparatoryFunctions() {
        Tables t = Tables.builtIn();
        assertEquals(28, t.allG().size());
        assertEquals(1, t.g(2).orElseThrow().group());
        assertFalse(t.g(4).orElseThrow().modal());
        assertTrue(t.g(41).isEmpty(), "G41 is not in Table 3");
    }

    @Test
    void tableFourKeepsGroupAndMoment() {
        Tables t = Tables.builtIn();
        assertEquals(30, t.allM().size());
        MFunction m03 = t.m(3).orElseThrow();
        assertEquals(2, m03.group());
        assertTrue(m03.beforeMotion());
        assertFalse(t.m(5).orElseThrow().beforeMotion());
    }

    @Test
    void tablesSixToNine() {
        Tables t = Tables.builtIn();
        assertTrue(t.limit('N').orElseThrow().integer());
        assertEquals(9999999, t.limit('N').orElseThrow().upper());
        assertTrue(t.allowedParameters(2).orElseThrow().contains(Tables.Param.R));
        assertFalse(t.allowedParameters(0).orElseThrow().contains(Tables.Param.R));
        assertEquals(20, t.toolOffsets().size());
        assertEquals(0.2, t.toolOffsets().get(2).x(), 1e-12);
        assertEquals(20, t.workOffsets().size());
    }

    @Test
    void anEditedCopyIsReadWithoutRebuilding() throws Exception {
        Path dir = copyOfTables();
        Path g = dir.resolve("g_codes.csv");
        Files.writeString(g, Files.readString(g).replace("Dwell,", "Pause,"));
        Tables t = Tables.load(TableSource.directory(dir));
        assertEquals("Pause", t.g(4).orElseThrow().english());
    }

    @Test
    void aBadValueIsReportedWhereItIs() throws Exception {
        Path dir = copyOfTables();
        Path m = dir.resolve("m_codes.csv");
        Files.writeString(m, Files.readString(m).replace("5,2,99,Spindle stop", "5,2,98,Spindle stop"));
        TableException e = assertThrows(TableException.class, () -> Tables.load(TableSource.directory(dir)));
        assertTrue(e.path().endsWith("m_codes.csv"));
        assertEquals(10, e.diagnostic().span().line());
        assertEquals(5, e.diagnostic().span().column());
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
