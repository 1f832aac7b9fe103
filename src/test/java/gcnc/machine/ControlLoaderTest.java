package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

class ControlLoaderTest {
    private static Control builtIn(String name) throws TableException {
        return ControlLoader.load(name, TableSource.builtIn());
    }

    @Test
    void thesisControlHasTablesThreeFourAndSeven() throws Exception {
        Control c = builtIn("thesis-2004");
        assertEquals(28, c.allG().size());
        assertEquals(1, c.g().get(2).group());
        assertFalse(c.g().get(4).modal());
        assertTrue(c.g().get(2).words().contains(Tables.Param.R));
        assertFalse(c.g().get(0).words().contains(Tables.Param.R));
        assertEquals(null, c.g().get(9).words(), "no Table 7 row: not restricted");
        assertTrue(c.g().get(41) == null, "G41 is not in Table 3");
        assertEquals(30, c.allM().size());
        MFunction m03 = c.m().get(3);
        assertEquals(2, m03.group());
        assertEquals(MRole.SPINDLE_CW, m03.role());
        assertTrue(m03.beforeMotion());
        assertFalse(c.m().get(5).beforeMotion());
        assertEquals(MRole.CHUCK_CLOSE, c.m().get(11).role());
        assertEquals("M30", c.endCodes());
        assertTrue(c.clampFromG50() && c.chuckByProgram() && c.increasingN() && c.noPointLiteral());
    }

    @Test
    void anEditedCopyIsReadWithoutRebuilding() throws Exception {
        Path dir = copyOf("thesis-2004");
        Path g = dir.resolve("g_codes.csv");
        Files.writeString(g, Files.readString(g).replace(",Dwell,", ",Pause,"));
        Control c = ControlLoader.load(dir.toString(), TableSource.builtIn());
        assertEquals("Pause", c.g().get(4).english());
    }

    @Test
    void aBadValueIsReportedWhereItIs() throws Exception {
        Path dir = copyOf("thesis-2004");
        Path m = dir.resolve("m_codes.csv");
        Files.writeString(m, Files.readString(m).replace("5,2,99,spindle_stop", "5,2,98,spindle_stop"));
        TableException e = assertThrows(TableException.class, () -> ControlLoader.load(dir.toString(), TableSource.builtIn()));
        assertTrue(e.path().endsWith("m_codes.csv"));
        assertEquals(11, e.diagnostic().span().line());
        assertEquals(5, e.diagnostic().span().column());
    }

    @Test
    void anUnknownFunctionOrKeyIsNamed() throws Exception {
        Path dir = copyOf("thesis-2004");
        Path g = dir.resolve("g_codes.csv");
        Files.writeString(g, Files.readString(g).replace("4,0,dwell,", "4,0,dwel,"));
        TableException e = assertThrows(TableException.class, () -> ControlLoader.load(dir.toString(), TableSource.builtIn()));
        assertTrue(e.getMessage().contains("unknown function 'dwel'"), e.getMessage());
        Files.writeString(g, Files.readString(g).replace("4,0,dwel,", "4,0,dwell,"));
        Path cfg = dir.resolve("control.cfg");
        Files.writeString(cfg, Files.readString(cfg) + "chuk = program\n");
        e = assertThrows(TableException.class, () -> ControlLoader.load(dir.toString(), TableSource.builtIn()));
        assertTrue(e.getMessage().contains("unknown key 'chuk'"), e.getMessage());
    }

    @Test
    void aMisspeltControlKeyGetsASuggestionAtItsColumn() throws Exception {
        Path dir = copyOf("thesis-2004");
        Path cfg = dir.resolve("control.cfg");
        Files.writeString(cfg, Files.readString(cfg) + "  dwell.q = seconds\n");
        TableException e = assertThrows(TableException.class, () -> ControlLoader.load(dir.toString(), TableSource.builtIn()));
        assertEquals("unknown key 'dwell.q' (did you mean 'dwell.p'?)", e.english());
        assertEquals(3, e.diagnostic().span().column());
    }

    @Test
    void aCodeListedTwiceIsAFault() throws Exception {
        Path dir = copyOf("thesis-2004");
        Path g = dir.resolve("g_codes.csv");
        Files.writeString(g, Files.readString(g) + "4,0,dwell,X U P,Dwell again,Otra vez\n");
        TableException e = assertThrows(TableException.class, () -> ControlLoader.load(dir.toString(), TableSource.builtIn()));
        assertTrue(e.getMessage().contains("G4 is listed twice"), e.getMessage());
    }

    @Test
    void theShippedListIsTheFoldersAndAnUnknownNameListsThem() throws Exception {
        try (Stream<Path> s = Files.list(Path.of("tables/controls"))) {
            assertEquals(new java.util.TreeSet<>(ControlLoader.SHIPPED), s.filter(Files::isDirectory)
                    .map(p -> p.getFileName().toString()).collect(java.util.stream.Collectors.toCollection(java.util.TreeSet::new)));
        }
        for (String name : ControlLoader.SHIPPED) {
            assertEquals(name, builtIn(name).name());
        }
        TableException e = assertThrows(TableException.class, () -> builtIn("okuma"));
        assertTrue(e.getMessage().contains("no control 'okuma' (shipped: thesis-2004, fanuc-a, fanuc-b, haas"), e.getMessage());
        // the machine's name given for its control's: the nearest control is named
        TableException near = assertThrows(TableException.class, () -> builtIn("fanuc"));
        assertTrue(near.getMessage().contains("no control 'fanuc': did you mean 'fanuc-a'? (shipped: thesis-2004, fanuc-a, fanuc-b, haas"),
                near.getMessage());
    }

    static Path copyOf(String control) throws IOException {
        Path dir = Files.createTempDirectory("gcnc-control");
        try (Stream<Path> s = Files.list(Path.of("tables/controls", control))) {
            for (Path p : (Iterable<Path>) s::iterator) {
                Files.copy(p, dir.resolve(p.getFileName()), StandardCopyOption.REPLACE_EXISTING);
            }
        }
        return dir;
    }
}
