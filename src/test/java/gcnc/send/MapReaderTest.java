package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.io.BufferedReader;
import java.io.StringReader;
import org.junit.jupiter.api.Test;

/** The sender reads a source map tolerantly: two columns, a file column after them, or file:line. */
class MapReaderTest {
    static MapReader.Map read(String text) throws Exception {
        return MapReader.read(new BufferedReader(new StringReader(text)));
    }

    @Test
    void runsLastUntilTheNextEntry() throws Exception {
        MapReader.Map m = read("# source part.nc\n# source sha256 ab\n1 0\n6 4\n9 5\n12 0\n# dmc sha256 cd\n");
        assertEquals(0, m.line(1));
        assertEquals(0, m.line(5));
        assertEquals(4, m.line(6));
        assertEquals(4, m.line(8));
        assertEquals(5, m.line(11));
        assertEquals(0, m.line(12));
        assertNull(m.file(7));
    }

    @Test
    void aFileColumnNamesTheCalledProgram() throws Exception {
        MapReader.Map m = read("1 0\n6 4\n9 12 O2000.nc\n14 5\n20 O3000.nc:7\n");
        assertEquals(12, m.line(10));
        assertEquals("O2000.nc", m.file(10));
        assertEquals(5, m.line(14));
        assertNull(m.file(14));
        assertEquals(7, m.line(21));
        assertEquals("O3000.nc", m.file(21));
    }

    @Test
    void linesThatAreNotEntriesAreSkipped() throws Exception {
        MapReader.Map m = read("garbage\n\n1 0\nx 3\n6 4 extra words\n");
        assertEquals(4, m.line(6));
        assertEquals(0, m.line(5));
    }
}
