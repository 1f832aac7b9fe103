package shop;

import static gcnc.junit.ProgramAssert.assertThat;
import static gcnc.junit.ProgramAssert.machine;
import static gcnc.junit.ProgramAssert.program;

import gcnc.junit.GcodeAssertions;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/** What the shop expects of its part programs, checked on every build (gcnc's JUnit fixtures). */
class PartProgramsTest {

    /** Every program in the folder compiles and simulates clean on the Haas: one test per file. */
    @TestFactory
    Stream<DynamicTest> everyProgramRunsOnTheHaas() {
        return GcodeAssertions.everyProgramIn(Path.of("src/main/gcode"), machine("haas"), List.of("gcode"));
    }

    /**
     * The pin is done in under two minutes and never goes behind Z-30, nor below X-2 (its facing
     * pass ends at ): X and Z as the program writes them (X a diameter, Z from work zero, mm);
     * the upper limits are open, for the G28 to the reference point. In the Haas's machine frame the
     * same is {@code staysWithinMachine(-1, 212, 120, 513)} (X a radius; the work zero is 150 mm out
     * from the chuck face).
     */
    @Test
    void thePinIsQuickAndKeepsClearOfTheJaws() {
        assertThat(program("src/main/gcode/o1201-pin.gcode")).on(machine("haas"))
                .compilesClean()
                .staysWithin(-2, Double.POSITIVE_INFINITY, -30, Double.POSITIVE_INFINITY)
                .cycleTimeBelow(Duration.ofMinutes(2));
    }
}
