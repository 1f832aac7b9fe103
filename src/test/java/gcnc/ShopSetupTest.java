package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.diag.Diagnostic;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * Programs as shops write them, on machines as shops set them up (issue 17): a bar pull is not a
 * cut, a station the profile does not describe is said to be assumed, a described one is not.
 * Each expectation is "line:code" of check, then of compile (checked, translated and simulated).
 */
class ShopSetupTest {
    /** The haas machine with a few more lines of its tool table. */
    private static String haasWith(String lines) throws Exception {
        Path f = Files.createTempFile("haas-shop", ".machine");
        Files.writeString(f, Files.readString(Path.of("tables/machines/haas.machine")) + lines);
        return f.toString();
    }

    private static String genericWith(String lines) throws Exception {
        Path f = Files.createTempFile("generic-shop", ".machine");
        Files.writeString(f, Files.readString(Path.of("tables/machines/generic.machine")) + lines);
        return f.toString();
    }

    private static String run(String machine, String program, boolean compile) throws Exception {
        Session s = Session.open(Session.Options.defaults().withMachine(machine));
        Compiler.Result r = compile ? s.compile(new StringReader(program), Optional.of(s.simulation()), false, l -> { })
                : s.check(new StringReader(program));
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            out.add(d.span().line() + ":" + d.code().id());
        }
        return String.join(", ", out);
    }

    /** Face the bar, then pull it out of the chuck: M05, the puller onto the bar, M11 (Haas unclamp), G98 G01, M10 (clamp). */
    private static final String PULL = String.join("\n",
            "G20 G40 G99",
            "G50 S3000",
            "T0101",
            "G97 S1000 M03",
            "G00 X2.1 Z0.05",
            "G01 X-0.05 F0.004",
            "G00 Z0.1",
            "G28 U0. W0.",
            "M05",
            "T1111 (BAR PULLER)",
            "G00 X0. Z0.5",
            "G98 G01 Z-0.25 F20.",             // line 12: onto the bar's end (a gripper, spindle stopped)
            "M11",
            "G01 Z1.25 F40.",                  // line 14: the pull, chuck open
            "M10",
            "G00 Z4.",
            "G28 U0. W0.",
            "M30", "");

    @Test
    void aBarPullIsACutOnlyWhereTheSimulationSaysItTakesStock() throws Exception {
        String puller = haasWith("station.11 = puller\n");
        // check cannot tell: it warns that compile decides (660 spindle stopped; 661 and the chuck open)
        assertEquals("12:E660, 14:E661", run(puller, PULL, false));
        // under G99 (feed per revolution) the axis cannot feed with the spindle stopped: an error as before
        assertEquals("12:E037, 14:E038", run(puller, PULL.replace("G98 G01 Z-0.25", "G01 Z-0.25"), false));
        // compile does: the puller grips the bar and takes nothing
        assertEquals("", run(puller, PULL, true));
        // the same moves with a turning insert at station 11: onto the bar is a cut with the spindle stopped
        // (and its holder, above the insert at the centreline, goes into the bar's end)
        String insert = haasWith("station.11 = turn C 12.7\n");
        assertEquals("12:E315, 12:E306", run(insert, PULL, true));
    }

    /** Part off a Ø44 bar at Z-33. with the blade of station 6. */
    private static final String PART_OFF = String.join("\n",
            "O1", "G21 G90 G98", "G50 S2500", "M11",
            "T0606",                           // line 5
            "S800 M03", "G00 X46. Z-33.", "G01 X-1. F40.", "G00 X46.", "M05", "M30", "");

    @Test
    void aPartingBladeAtAStationTheProfileDoesNotDescribeIsWarned() throws Exception {
        // generic describes station 1 only: the blade is checked as the default 80° insert, and said so;
        // plunged 22 mm deep, that insert's holder head meets the wall (a finding resting on the assumption)
        assertEquals("5:E321, 8:E315", run(ProfileLoaderDefault.NAME, PART_OFF, true));
        // described: no assumption, nothing to say
        assertEquals("", run(genericWith("station.6 = part 3, reach 32\n"), PART_OFF, true));
        // check does not simulate: no tool geometry involved
        assertEquals("", run(ProfileLoaderDefault.NAME, PART_OFF, false));
    }

    /** The default machine's name, as a front end passes it. */
    private static final class ProfileLoaderDefault {
        static final String NAME = gcnc.machine.ProfileLoader.DEFAULT;
    }
}
