package gcnc.junit;

import static gcnc.junit.ProgramAssert.assertThat;
import static gcnc.junit.ProgramAssert.machine;
import static gcnc.junit.ProgramAssert.program;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;

/** The fluent assertions say what a shop means, and fail with the findings. */
class ProgramAssertTest {
    @Test
    void aCleanProgramWithinItsLimitsAndTime() {
        // samples/arcs.nc on generic: envelope X 0..105 mm (radius), Z 90..340 mm, about 73 s
        assertThat(program("samples/arcs.nc")).on(machine("generic"))
                .compilesClean()
                .staysWithin(0, 110, 80, 350)
                .cycleTimeBelow(Duration.ofMinutes(2));
    }

    @Test
    void eachLimitFailsWhenBroken() {
        ProgramAssert arcs = assertThat(program("samples/arcs.nc")).on(machine("generic"));
        AssertionError far = assertThrows(AssertionError.class, () -> arcs.staysWithin(0, 50, 80, 350));
        assertTrue(far.getMessage().contains("not within X 0.0..50.0"), far.getMessage());
        AssertionError slow = assertThrows(AssertionError.class, () -> arcs.cycleTimeBelow(Duration.ofSeconds(30)));
        assertTrue(slow.getMessage().contains("not below PT30S"), slow.getMessage());
    }

    @Test
    void aFaultyProgramFailsWithItsFindings() throws Exception {
        Path p = Files.createTempDirectory("gcnc-fluent").resolve("bad.nc");
        Files.writeString(p, "G21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X46. Z2.\nG01 X41. Z-3O. F100.\nM30\n");
        AssertionError e = assertThrows(AssertionError.class, () -> assertThat(p).on(machine("generic")).compilesClean());
        assertTrue(e.getMessage().contains("bad.nc:7:10: error[E120]"), e.getMessage());
        assertThat(p).on(machine("generic")).hasFindings("E120");
    }
}
