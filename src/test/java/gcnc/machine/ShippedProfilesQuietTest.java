package gcnc.machine;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.Session;
import gcnc.diag.Diagnostic;
import gcnc.diag.Severity;
import java.io.StringReader;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 22: a shipped profile makes no warning of its own. A program that runs its machine at the
 * top speed the profile gives, through a roughing cycle's passes, compiles without a single
 * finding (before: E204 "spindle volts clamped" at the profile's own top speed, at every S).
 */
class ShippedProfilesQuietTest {
    @ParameterizedTest
    @ValueSource(strings = {"generic", "haas", "fanuc"})
    void theTopSpeedOfEveryShippedProfileCompilesWithoutAFinding(String machine) throws Exception {
        Session s = Session.open(Session.Options.defaults().withMachine(machine));
        int top = (int) s.profile().maxRpm();
        String close = machine.equals("generic") ? "M11\n" : "";
        String program = "G21 G40 G99\nG50 S" + top + "\n" + close + "T0101\nG97 S" + top + " M03\nG00 X52. Z2.\n"
                + "G01 X48. F0.2\nZ-10.\nG00 X60.\nG97 S" + top + "\nG00 X52. Z2.\nG00 X100. Z50.\nM05\nM30\n";
        List<Diagnostic> found = s.compile(new StringReader(program), Optional.of(s.simulation()), false, line -> { })
                .diagnostics().sorted();
        assertEquals(List.of(), found.stream().filter(d -> d.severity() != Severity.NOTE).map(d -> d.code().id()
                + "@" + d.span().line()).toList(), program);
    }
}
