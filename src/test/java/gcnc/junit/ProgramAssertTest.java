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
        // samples/arcs.nc on generic: X 0..210 (a diameter, 210 at the reference point), Z -60..190 mm from
        // work zero; in the machine frame X 0..105 mm (a radius), Z 90..340 mm; about 73 s
        assertThat(program("samples/arcs.nc")).on(machine("generic"))
                .compilesClean()
                .staysWithin(0, 210, -60, 190)
                .staysWithin(0, Double.POSITIVE_INFINITY, -60, Double.POSITIVE_INFINITY)
                .staysWithinMachine(0, 110, 80, 350)
                .cycleTimeBelow(Duration.ofMinutes(2));
    }

    @Test
    void eachLimitFailsWhenBroken() {
        ProgramAssert arcs = assertThat(program("samples/arcs.nc")).on(machine("generic"));
        AssertionError far = assertThrows(AssertionError.class, () -> arcs.staysWithin(0, 100, -60, 190));
        assertTrue(far.getMessage().contains("moves over X 0.000..210.000 (diameter), Z -60.000..190.000 mm from work"
                + " zero, not within X 0..100, Z -60..190 (machine frame: X 0.000..105.000 mm, a radius;"
                + " Z 90.000..340.000 mm)"), far.getMessage());
        AssertionError deep = assertThrows(AssertionError.class,
                () -> arcs.staysWithin(0, Double.POSITIVE_INFINITY, -50, Double.POSITIVE_INFINITY));
        assertTrue(deep.getMessage().contains("not within X 0..+inf, Z -50..+inf"), deep.getMessage());
        AssertionError machine = assertThrows(AssertionError.class, () -> arcs.staysWithinMachine(0, 50, 80, 350));
        assertTrue(machine.getMessage().contains("moves over machine X 0.000..105.000 mm (radius), Z 90.000..340.000 mm,"
                + " not within X 0..50, Z 80..350"), machine.getMessage());
        AssertionError slow = assertThrows(AssertionError.class, () -> arcs.cycleTimeBelow(Duration.ofSeconds(30)));
        assertTrue(slow.getMessage().contains("not below PT30S"), slow.getMessage());
    }

    @Test
    void anInchProgramsLimitsAreInInches() throws Exception {
        // X1.5 (a diameter) from Z0.1 to Z-1.2 in, on generic (whose reference point is X 210 Z 340 mm)
        Path p = Files.createTempDirectory("gcnc-fluent").resolve("inch.nc");
        Files.writeString(p, "O3\nG20 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X1.8 Z0.1\nG01 X1.5 F4.\n"
                + "G01 Z-1.2\nG00 X1.8\nM05\nM30\n");
        ProgramAssert inch = assertThat(p).on(machine("generic"));
        inch.staysWithin(1.5, Double.POSITIVE_INFINITY, -1.2, Double.POSITIVE_INFINITY);
        AssertionError e = assertThrows(AssertionError.class,
                () -> inch.staysWithin(1.5, Double.POSITIVE_INFINITY, -1, Double.POSITIVE_INFINITY));
        assertTrue(e.getMessage().contains("Z -1.2000..7.4803 in from work zero, not within X 1.5..+inf, Z -1..+inf"),
                e.getMessage());
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
