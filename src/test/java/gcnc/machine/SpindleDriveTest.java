package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import gcnc.diag.Code;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * One verdict for the spindle drive (issue 18): a profile whose own top speed needs more than the
 * OF output's 10 V is refused when it is loaded (E410 at rpm_per_volt's line), instead of passing
 * {@code machines validate} and {@code check} and making every compile at top speed E203.
 */
class SpindleDriveTest {
    @Test
    void aDriveThatCannotReachTheTopSpeedIsRefusedAtItsLine() throws Exception {
        Path slow = Path.of("src/test/resources/gcnc/machine/slow-drive.machine");
        TableException e = assertThrows(TableException.class,
                () -> ProfileLoader.load(slow.toString(), TableSource.builtIn(), Tables.builtIn()));
        assertEquals(Code.E410_SPINDLE_TOP_SPEED_VOLTS, e.diagnostic().code());
        List<String> lines = Files.readAllLines(slow);
        int line = 0;
        while (!lines.get(line).startsWith("spindle.rpm_per_volt")) {
            line++;
        }
        assertEquals(line + 1, e.diagnostic().span().line());
        assertEquals("spindle.rpm_per_volt = ".length() + 1, e.diagnostic().span().column());
        // max_rpm 4000 at 100 rpm per volt: 40 V; 400 rpm per volt would do
        assertEquals(List.of("4000", "40", "100", "400"), e.diagnostic().args().stream().map(String::valueOf).toList());
    }

    private static Path withGain(String gain) throws Exception {
        String text = Files.readString(Path.of("src/test/resources/gcnc/machine/slow-drive.machine"))
                .replaceFirst("spindle.rpm_per_volt = 100", "spindle.rpm_per_volt = " + gain);
        Path p = Files.createTempDirectory("gcnc-drive").resolve("drive.machine");
        Files.writeString(p, text);
        return p;
    }

    /**
     * 10 V exactly is more than the 9.998 V the backend writes: every program at the machine's top
     * speed would get warning E204 (clamped): the profile is refused at load, E405 (issue 22).
     */
    @Test
    void aDriveThatNeedsTenVoltsAtTheTopSpeedIsRefusedSoThatNoProgramIsWarnedForIt() throws Exception {
        TableException e = assertThrows(TableException.class,
                () -> ProfileLoader.load(withGain("400").toString(), TableSource.builtIn(), Tables.builtIn()));
        assertEquals(Code.E405_SPINDLE_TOP_SPEED_CLAMPED, e.diagnostic().code());
        assertEquals(List.of("4000", "10", "400", "400.081"), e.diagnostic().args());
        // just under 9.998 V at 4000 r/min: accepted, and S4000 gives no E204
        assertEquals(4000, ProfileLoader.load(withGain("400.081").toString(), TableSource.builtIn(), Tables.builtIn())
                .maxRpm());
    }

    @ParameterizedTest
    @ValueSource(strings = {"generic", "haas", "fanuc", "thesis-2004"})
    void theBuiltInProfilesDriveTheirTopSpeed(String name) throws Exception {
        assertEquals(name, ProfileLoader.load(name, TableSource.builtIn(), Tables.builtIn()).name());
    }
}
