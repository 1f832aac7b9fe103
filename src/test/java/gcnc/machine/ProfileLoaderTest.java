package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.ir.Point;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

class ProfileLoaderTest {
    private static final Tables TABLES = Tables.builtIn();

    private static MachineProfile load(String name) throws TableException {
        return ProfileLoader.load(name, TableSource.builtIn(), TABLES);
    }

    @Test
    void thesisProfileHoldsTheNumbersTableFiveTwoPins() throws Exception {
        MachineProfile p = load("thesis-2004");
        assertEquals(1.5, p.x().countsPerMm());
        assertEquals(1200, p.z().countsPerInch());
        assertEquals(new Point(-20000, -20000), p.workOffset(54).orElseThrow());
        assertEquals(20000, p.rapidSpeed());
        assertEquals(20, p.feedPerF());
        assertEquals(300, p.rpmPerVolt());
        assertTrue(p.maxRpm() >= 5000);
        assertFalse(p.diameterX());
        assertEquals(1, p.noPointMm());
        assertEquals(List.of("CB4", "SB3"), p.outputsFor(3));
        assertEquals(-1, p.x().sign());
    }

    @Test
    void genericProfileIsAMetricDiameterLathe() throws Exception {
        MachineProfile p = load(ProfileLoader.DEFAULT);
        assertTrue(p.diameterX());
        assertEquals(0.001, p.noPointMm());
        assertEquals(1000 * 25.4, p.x().countsPerInch(), 1e-9);
        assertEquals(150_000, p.workOffset(54).orElseThrow().z());
        assertEquals(200, p.toolOffset(3).orElseThrow().x(), 1e-9, "Table 8 row 3 is 0.2 mm");
        assertEquals(12, p.tools());
        assertEquals('X', p.z().galil());
    }

    @Test
    void aProfileFileByPath() throws Exception {
        Path f = Files.createTempFile("lathe", ".machine");
        Files.writeString(f, Files.readString(Path.of("tables/machines/generic.machine")).replace("name = generic", "name = my-lathe"));
        assertEquals("my-lathe", ProfileLoader.load(f.toString(), TableSource.builtIn(), TABLES).name());
    }

    @Test
    void faultsAreLocated() throws Exception {
        String good = Files.readString(Path.of("tables/machines/generic.machine"));
        assertFault(good.replace("x.counts_per_mm = 1000", "x.counts_per_mm = ten"), "x.counts_per_mm = ten", "not a number");
        assertFault(good.replace("x.sign = 1", "x.sign = 2"), "x.sign = 2", "1 or -1");
        assertFault(good.replace("m.5 = CB1", "m.5 = CLEAR1"), "m.5 = CLEAR1", "SBn or CBn");
        assertFault(good.replace("tool_post = rear", "tool_post = left"), "tool_post = left", "front, rear");
        assertFault(good + "x.sign = 1\n", "x.sign = 1\n", "given twice");
    }

    private static void assertFault(String text, String badLine, String message) throws Exception {
        Path f = Files.createTempFile("bad", ".machine");
        Files.writeString(f, text);
        TableException e = assertThrows(TableException.class, () -> ProfileLoader.load(f.toString(), TableSource.builtIn(), TABLES));
        int line = text.substring(0, text.lastIndexOf(badLine)).split("\n", -1).length;
        assertEquals(line, e.diagnostic().span().line(), e.getMessage());
        assertTrue(e.diagnostic().args().get(0).contains(message), e.diagnostic().args().toString());
    }
}
