package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import gcnc.tables.Utf8;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Absurd profile values (issue 18): each is refused at its line with a reason, none crashes
 * formatting its message, and a profile or table that is a link to a device is refused at a
 * stated size. Each case is the generic profile with one line changed.
 */
class ProfileLimitsTest {
    private static final Tables TABLES = Tables.builtIn();
    private static final String GOOD = read("tables/machines/generic.machine");

    private static String read(String p) {
        try {
            return Files.readString(Path.of(p));
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    /** The generic profile with {@code key}'s line set to {@code value} (added when absent). */
    private static String with(String key, String value) {
        Matcher m = Pattern.compile("(?m)^" + Pattern.quote(key) + " *=.*$").matcher(GOOD);
        return m.find() ? m.replaceFirst(Matcher.quoteReplacement(key + " = " + value)) : GOOD + key + " = " + value + "\n";
    }

    /** Loading {@code key = value} fails with {@code code} at that key's line, the message containing {@code text}. */
    private static void refused(String key, String value, Code code, String text) throws Exception {
        String profile = with(key, value);
        Path f = Files.createTempFile("absurd", ".machine");
        Files.writeString(f, profile);
        TableException e = assertThrows(TableException.class,
                () -> ProfileLoader.load(f.toString(), TableSource.builtIn(), TABLES), key + " = " + value);
        assertEquals(code, e.diagnostic().code(), e.getMessage());
        assertEquals(ProfileLoaderTest.lineOf(profile, key + " = " + value), e.diagnostic().span().line(), e.getMessage());
        assertTrue(e.english().contains(text), e.english());
        Files.delete(f);
    }

    @Test
    void aTravelOrCountThatOverflowsIsRefusedAtItsLine() throws Exception {
        // both crashed every command, machines validate included, formatting the message
        refused("x.travel", "-2, 1e306", Code.E401_PROFILE_NUMBER_TOO_LARGE, "x.travel = 1e306: no value in a profile");
        refused("x.counts_per_mm", "1e306", Code.E401_PROFILE_NUMBER_TOO_LARGE, "larger than 1000000000000");
        refused("x.travel", "-2, 1e11", Code.E400_TABLE, "x.travel 100000000000 mm is 100000000000000 counts");
    }

    @Test
    void elevenAbsurdValuesAreRefusedEachWithItsReason() throws Exception {
        refused("x.counts_per_mm", "0.001", Code.E402_PROFILE_VALUE_RANGE, "x.counts_per_mm = 0.001: gcnc takes 1 to 1000000");
        refused("z.counts_per_mm", "1e7", Code.E402_PROFILE_VALUE_RANGE, "gcnc takes 1 to 1000000");
        refused("x.counts_per_inch", "1", Code.E402_PROFILE_VALUE_RANGE, "gcnc takes 25.4 to 25400000");
        refused("spindle.max_rpm", "1e8", Code.E402_PROFILE_VALUE_RANGE, "spindle.max_rpm = 100000000: gcnc takes 1 to 100000");
        refused("spindle.max_rpm", "0.5", Code.E402_PROFILE_VALUE_RANGE, "gcnc takes 1 to 100000");
        refused("spindle.rpm_per_volt", "0.000001", Code.E402_PROFILE_VALUE_RANGE, "gcnc takes 1 to 100000");
        refused("feed.per_f", "1e9", Code.E402_PROFILE_VALUE_RANGE, "gcnc takes 0.001 to 1000000");
        refused("work.G54", "1e300, 150", Code.E401_PROFILE_NUMBER_TOO_LARGE, "work.G54 = 1e300");
        refused("tool.1", "0, 5e6", Code.E403_PROFILE_COUNTS_OVERFLOW, "tool.1: 5000000 is 5000000000 counts");
        refused("stock.length", "3e6", Code.E403_PROFILE_COUNTS_OVERFLOW, "stock.length: 3000000 is 3000000000 counts");
        refused("sim.centre_x", "-1e20", Code.E401_PROFILE_NUMBER_TOO_LARGE, "sim.centre_x = -1e20");
    }

    @Test
    void nanInfinityAndNegativeRatesStayRefused() throws Exception {
        refused("rapid.speed", "Infinity", Code.E400_TABLE, "'Infinity' is not a number");
        refused("x.sign", "NaN", Code.E400_TABLE, "'NaN' is not a number");
        refused("vector.acceleration", "-5", Code.E400_TABLE, "must be greater than 0");
        refused("z.travel", "0, 1e400", Code.E400_TABLE, "'1e400' is not a number");
    }

    @Test
    void aProfileThatIsALinkToDevZeroIsRefusedAtAStatedSize() throws Exception {
        Path dir = Files.createTempDirectory("zero");
        Path link = Files.createSymbolicLink(dir.resolve("zero.machine"), Path.of("/dev/zero"));
        TableException e = assertThrows(TableException.class,
                () -> ProfileLoader.load(link.toString(), TableSource.builtIn(), TABLES));
        assertEquals(Code.E404_TABLE_FILE_TOO_LARGE, e.diagnostic().code());
        assertEquals(link + ":1:1: larger than " + Utf8.MAX_BYTES + " bytes: not a table or control or profile"
                + " (a link to a device?)", e.getMessage());
        // a table or control under --tables DIR is read the same way
        Files.createDirectories(dir.resolve("controls/zero"));
        Files.createSymbolicLink(dir.resolve("controls/zero/control.cfg"), Path.of("/dev/zero"));
        TableException c = assertThrows(TableException.class,
                () -> ControlLoader.load(dir.resolve("controls/zero").toString(), TableSource.builtIn()));
        assertEquals(Code.E404_TABLE_FILE_TOO_LARGE, c.diagnostic().code());
    }
}
