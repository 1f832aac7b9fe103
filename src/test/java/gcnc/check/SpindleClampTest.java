package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Diagnostic;
import gcnc.diag.Severity;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.sim.SimOptions;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * An rpm S above the program's G50 S (G92 S on Fanuc system B) limit (issue 31, key
 * {@code spindle_above_clamp}): the thesis's control stops (E048, Table 5 error 48); Fanuc and Haas
 * turn the spindle at the limit and run the block, the warning E280, and gcnc generates, simulates
 * and times the block at the limit. Each program on the generic machine (4000 rpm top speed) with
 * only the control changed.
 */
class SpindleClampTest {
    /** A feed-per-revolution cut: its feed rate in the DMC follows the spindle speed. */
    private static final String CUT = "G00 X42. Z2.\nG99 G01 X40. F0.2\nG01 Z-30.\nG00 X50.\nM30\n";

    private static MachineProfile machine(String control) {
        try {
            return ProfileLoader.load("generic", TableSource.builtIn(), Run.TABLES, control);
        } catch (TableException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    @Test
    void haasTurnsAtTheG50Limit() {
        assertEquals("2:5:E280", ControlRulesTest.check("generic", "haas", "G50 S2000\nG97 S2500 M03\n" + CUT));
    }

    @Test
    void fanucSystemATurnsAtTheG50Limit() {
        assertEquals("2:5:E280", ControlRulesTest.check("generic", "fanuc-a", "G50 S2000\nG97 S2500 M03\n" + CUT));
    }

    @Test
    void fanucSystemBTurnsAtTheG92Limit() {
        String p = "G92 S2000\nG97 S2500 M03\n" + CUT.replace("G99", "G95");
        assertEquals("2:5:E280", ControlRulesTest.check("generic", "fanuc-b", p));
        assertTrue(ControlRulesTest.messages("generic", "fanuc-b", p)
                .contains("S2500 is above the limit S2000 set by G92: the control turns the spindle at S2000"));
    }

    @Test
    void theThesisControlStopsThere() {
        assertEquals("2:1:E048", ControlRulesTest.check("generic", "thesis-2004", "G50 S2000\nS2500 M03\nM30\n"));
    }

    @Test
    void anSAtTheLimitOrUnderG96IsNothing() {
        assertEquals("", ControlRulesTest.check("generic", "haas", "G50 S2000\nG97 S2000 M03\n" + CUT));
        assertEquals("", ControlRulesTest.check("generic", "haas", "G50 S2000\nG96 S2500 M03\n" + CUT));
    }

    @Test
    void aLimitAboveTheMachinesTopSpeedLeavesTheMachinesError() {
        // G50 S5000 on a 4000 rpm machine: the control turns at 4000 at most, so S6000 is E119 as well
        assertEquals("2:5:E280, 2:5:E119", ControlRulesTest.check("generic", "haas", "G50 S5000\nG97 S6000 M03\nM30\n"));
    }

    @Test
    void theBlockRecordsTheLimitsSpeed() throws IOException {
        List<Double> rpm = new ArrayList<>();
        Compiler.check(new StringReader("G50 S2000\nG97 S2500 M03\n" + CUT),
                new Compiler.Settings(Run.TABLES, machine("haas"), Dialect.Kind.GALIL, Optional.empty()),
                b -> {
                    if (b.line() == 2) {
                        rpm.add(b.spindleRpm().getAsDouble());
                    }
                });
        assertEquals(List.of(2000.0), rpm);
    }

    @Test
    void aBlockRecoveredFromAnotherErrorKeepsTheLimitsSpeed() {
        // two motion Gs (E016): the block is refused, its S is kept as the control would run it
        Run r = Run.of(machine("haas"), "G50 S2000\nG00 G01 S2500 M03\nM30\n", Checker.ERROR_CAP);
        assertEquals("2:5:E016", r.errors());
        assertEquals(2000, r.checker.state().rpm(), 1e-9);
    }

    /** The DMC and cycle time of {@code program} on the haas control; any finding but E280 and notes (no blank: E316) fails. */
    private static String dmc(String program, double[] seconds) throws IOException {
        StringBuilder out = new StringBuilder();
        Compiler.Result r = Compiler.compile(new StringReader(program),
                new Compiler.Settings(Run.TABLES, machine("haas"), Dialect.Kind.GALIL, Optional.of(SimOptions.defaults().withoutBlank())),
                l -> out.append(l.text()).append('\n'));
        for (Diagnostic d : r.diagnostics().sorted()) {
            assertTrue(d.severity() == Severity.NOTE || d.code().id().equals("E280") && d.severity() == Severity.WARNING,
                    d::toString);
        }
        seconds[0] = r.simulation().orElseThrow().cycleSeconds();
        return out.toString();
    }

    @Test
    void theGeneratedSpeedFeedAndCycleTimeAreTheLimits() throws IOException {
        double[] clamped = new double[1];
        double[] atLimit = new double[1];
        double[] unclamped = new double[1];
        String above = dmc("G50 S2000\nG97 S2500 M03\n" + CUT, clamped);
        String limit = dmc("G50 S2000\nG97 S2000 M03\n" + CUT, atLimit);
        String faster = dmc("G50 S3000\nG97 S2500 M03\n" + CUT, unclamped);
        assertEquals(limit, above);
        assertEquals(atLimit[0], clamped[0], 1e-9);
        // the speed does show in the DMC and the time: S2500 under a higher limit is another program
        assertNotEquals(above, faster);
        assertTrue(unclamped[0] < clamped[0], () -> unclamped[0] + " s vs " + clamped[0] + " s");
    }
}
