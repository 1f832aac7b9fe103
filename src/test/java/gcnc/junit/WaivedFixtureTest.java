package gcnc.junit;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The fixtures pass a program whose only findings are waived, and say which (issue 31). */
class WaivedFixtureTest {
    private static final Path PROGRAM = Path.of("src/test/resources/waivers/g70-u.fanuc.nc");

    /** What {@code run} prints on standard output. */
    private static String printed(Runnable run) {
        PrintStream before = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
        try {
            run.run();
        } finally {
            System.setOut(before);
        }
        return out.toString(StandardCharsets.UTF_8);
    }

    @Test
    void compilesCleanPassesWithAWaivedFindingAndNamesIt() {
        String said = printed(() -> ProgramAssert.assertThat(PROGRAM).on(ProgramAssert.machine("fanuc")).compilesClean()
                .compilesClean());
        assertTrue(said.startsWith("gcnc: " + PROGRAM + " is clean on fanuc with 1 waived finding:\n" + PROGRAM
                + ":13:13: note[E642] waived: our post writes U and W in every G70; the control ignores them: "), said);
        assertEquals(1, said.split("is clean on", -1).length - 1, "said once per program: " + said);
    }

    @Test
    void assertCompilesCleanSaysTheSame() {
        String said = printed(() -> GcodeAssertions.assertCompilesClean(PROGRAM, "fanuc"));
        assertTrue(said.contains("with 1 waived finding:\n" + PROGRAM + ":13:13: note[E642] waived: "), said);
    }
}
