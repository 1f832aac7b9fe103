package gcnc.junit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;

class GcodeAssertionsTest {
    @Test
    void aCleanProgramPasses() {
        GcodeAssertions.assertCompilesClean(Path.of("samples/turning.nc"), "generic");
    }

    @Test
    void aBadProgramFailsWithEveryFindingGccStyle() throws Exception {
        Path p = Files.createTempFile("part", ".nc");
        Files.writeString(p, "G21 G98\nG50 S2000\nM11\nG01 X10. Z5. F100.\nG00 X20. Y5.\nM30\n");
        AssertionError e = assertThrows(AssertionError.class, () -> GcodeAssertions.assertCompilesClean(p, "generic"));
        assertTrue(e.getMessage().contains(p + ":4:1: error[E051]"), e.getMessage());
        assertTrue(e.getMessage().contains(p + ":5:10: error[E004]"), e.getMessage());
        GcodeAssertions.assertFindings(p, "generic", "E051", "E004");
        assertThrows(AssertionError.class, () -> GcodeAssertions.assertFindings(p, "generic", "E051"));
    }

    @Test
    void oneDynamicTestPerProgramInAFolder() throws Throwable {
        // .nc only: samples/shop-project/ holds the sample shop's .gcode programs, for its own machine
        SystemOut.Printed<List<DynamicTest>> scan = SystemOut.capture(() -> GcodeAssertions.everyProgramIn(Path.of("samples"),
                GcodeAssertions.session("generic"), List.of("nc")).collect(Collectors.toList()));
        List<DynamicTest> tests = scan.value();
        assertTrue(scan.text().startsWith("gcnc: samples: skipped ") && scan.text().contains("not a program's extension (.nc)"),
                scan.text());
        assertEquals(List.of("arcs.nc", "bishop.nc", "dwell-css.nc", "home.nc", "offsets.nc", "turning.nc", "units.nc"),
                tests.stream().map(DynamicTest::getDisplayName).collect(Collectors.toList()));
        // the default list (gcnc.ProgramFiles.EXTENSIONS, as the command line's) takes them too
        List<String> all = SystemOut.capture(() -> GcodeAssertions.everyProgramIn(Path.of("samples"), "generic")
                .map(DynamicTest::getDisplayName).collect(Collectors.toList())).value();
        assertTrue(all.contains("shop-project/src/main/gcode/o1201-pin.gcode"), all.toString());
        for (DynamicTest t : tests) {
            t.getExecutable().execute();
        }
    }

    @Test
    void anUnknownMachineIsAClearFailure() {
        AssertionError e = assertThrows(AssertionError.class,
                () -> GcodeAssertions.assertCompilesClean(Path.of("samples/turning.nc"), "no-such-lathe"));
        assertTrue(e.getMessage().contains("no-such-lathe"), e.getMessage());
    }
}
