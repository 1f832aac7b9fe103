package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.tables.TableException;
import gcnc.tables.Tables;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

class ProfileKeysTest {
    private static TableException loadWith(String extraLine) throws Exception {
        String text = Files.readString(Path.of("tables/machines/generic.machine")) + extraLine + "\n";
        try {
            ProfileLoader.read(ProfileFile.parse("t.machine", text), Tables.builtIn());
        } catch (TableException e) {
            assertEquals(text.split("\n", -1).length - 1, e.diagnostic().span().line(), e.getMessage());
            return e;
        }
        throw new AssertionError("no fault for " + extraLine);
    }

    private static String message(String extraLine) throws Exception {
        return loadWith(extraLine).english();
    }

    @Test
    void aMisspeltKeyIsNamedWithTheKeyItWasMeantToBe() throws Exception {
        assertEquals("unknown key 'x.counts_per_m' (did you mean 'x.counts_per_mm'?)", message("x.counts_per_m = 1000"));
        assertEquals("unknown key 'stock.stick_out' (did you mean 'stock.stickout'?)", message("stock.stick_out = 10"));
        assertEquals("unknown key 'Home' (did you mean 'home'?)", message("Home = 0, 0"));
    }

    @Test
    void theFaultIsAtTheKeysColumn() throws Exception {
        assertEquals(3, loadWith("  spindle.max_rmp = 10").diagnostic().span().column());
    }

    @Test
    void aKnownKeyWithTheSameLastPartIsSuggested() throws Exception {
        assertEquals("unknown key 'lathe.home' (did you mean 'home'?)", message("lathe.home = 0, 0"));
        assertEquals("unknown key 'turret.count' (did you mean 'tools.count'?)", message("turret.count = 12"));
    }

    @Test
    void aNumberedKeyOutOfItsFamilySaysHowTheFamilyIsWritten() throws Exception {
        assertEquals("unknown key 'work.G60' (work offsets are work.G54 .. work.G59)", message("work.G60 = 0, 0"));
        assertEquals("unknown key 'tool.100' (tool offsets are tool.<n> with n = 1 to 99)", message("tool.100 = 0, 0"));
        assertEquals("unknown key 'm.1000' (M code outputs are m.<n> with n = 0 to 999)", message("m.1000 = SB1"));
        assertTrue(message("sim.tool.3.shank = 0, 0").startsWith("unknown key 'sim.tool.3.shank' (tools are"));
    }

    @Test
    void anythingElseSaysWhereTheKeysAreListed() throws Exception {
        assertEquals("unknown key 'coolant' (docs/profiles.md and docs/simulator.md list the keys)", message("coolant = on"));
    }

    @Test
    void aToolOffsetNumberedZeroKeepsItsOwnReason() throws Exception {
        assertTrue(message("tool.0 = 0, 0").contains("numbered from 1"));
    }

    /** The keys the docs' tables list are the keys gcnc reads: none missing from either side. */
    @Test
    void theDocumentedKeysAreTheKnownKeys() throws Exception {
        List<String> documented = new ArrayList<>();
        for (String doc : List.of("docs/profiles.md", "docs/simulator.md")) {
            boolean keyTable = false;
            for (String line : Files.readAllLines(Path.of(doc))) {
                keyTable = line.startsWith("| key |") || keyTable && line.startsWith("|");
                if (keyTable && line.startsWith("| `")) {
                    Matcher m = Pattern.compile("`([^`]+)`").matcher(line.substring(0, line.indexOf('|', 1)));
                    while (m.find()) {
                        documented.add(m.group(1).replace("<n>", "7").replace(".N", ".7"));
                    }
                }
            }
        }
        for (String key : documented) {
            assertTrue(ProfileKeys.known(key), key + " is documented but gcnc does not read it");
        }
        for (String key : ProfileKeys.NAMED) {
            assertTrue(documented.contains(key), key + " is read but not documented");
        }
    }

    @Test
    void editDistanceCountsASwapAsOneEdit() {
        assertEquals(1, Spelling.distance("feed.mxa", "feed.max"));
        assertEquals(2, Spelling.distance("x.cuonts_per_m", "x.counts_per_mm"));
        assertEquals(0, Spelling.distance("HOME", "home"));
    }
}
