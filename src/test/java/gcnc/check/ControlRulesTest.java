package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Diagnostic;
import gcnc.diag.GnuRenderer;
import gcnc.galil.Dialect;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The rules that differ between controls (issue 8), one tiny program each, through the real
 * parser and checker, on the generic machine with the control named (so only the control
 * differs), and on the shipped haas and fanuc machines where the machine matters.
 */
class ControlRulesTest {
    /** A cut that every control accepts once the spindle runs: the same body under each control. */
    private static final String CUT = "G00 X42. Z2.\nG01 X40. F0.2\nG01 Z-10.\n";

    private static MachineProfile machine(String machine, String control) {
        try {
            return ProfileLoader.load(machine, TableSource.builtIn(), Run.TABLES, control);
        } catch (TableException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    /** Every finding as "line:column:Ennn", sorted, comma separated. */
    static String check(String machine, String control, String program) {
        return codes(run(machine(machine, control), program));
    }

    static Compiler.Result run(MachineProfile p, String program) {
        try {
            return Compiler.check(new StringReader(program), new Compiler.Settings(Run.TABLES, p, Dialect.Kind.GALIL, Optional.empty()));
        } catch (IOException e) {
            throw new AssertionError(e);
        }
    }

    static String codes(Compiler.Result r) {
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            out.add(d.span().line() + ":" + d.span().column() + ":" + d.code().id());
        }
        return String.join(", ", out);
    }

    static String messages(String machine, String control, String program) {
        GnuRenderer g = new GnuRenderer(Run.TABLES.messages().in(ErrorMessages.Lang.EN));
        List<String> out = new ArrayList<>();
        for (Diagnostic d : run(machine(machine, control), program).diagnostics().sorted()) {
            out.add(g.render("p.nc", d));
        }
        return String.join("\n", out);
    }

    // ---- the thesis's rules are rules of thesis-2004 only ----

    @Test
    void theChuckIsClosedByTheOperatorExceptOnTheThesisControl() {
        String p = "G50 S2500\nS1000 M03\n" + CUT + "M30\n";
        assertEquals("5:1:E038, 5:1:E115", check("generic", "thesis-2004", "G21 G90 G98\n" + p.replace("F0.2", "F100.")));
        assertEquals("", check("generic", "fanuc-a", p));
        assertEquals("", check("generic", "haas", p));
    }

    @Test
    void openingTheChuckAndThenCuttingIsStillAnError() {
        // fanuc: M10 opens the chuck; haas: M11 unclamps it (M10 clamps)
        assertEquals("5:1:E040", check("generic", "fanuc-a", "S1000 M03\n" + CUT + "M10\nM30\n"));
        assertEquals("5:1:E040", check("generic", "haas", "S1000 M03\n" + CUT + "M11\nM30\n"));
        assertEquals("4:1:E038", check("generic", "haas", "M11\nS1000 M03\n" + CUT + "M30\n").split(", ")[0]);
        assertEquals("", check("generic", "haas", "M10\nS1000 M03\n" + CUT + "M30\n"));
    }

    @Test
    void e038NamesTheChuckCloseCodeOfTheControl() {
        // Haas clamps with M10, the thesis and fanuc-a with M11: the message says the machine's own code
        String cut = "M11\nS1000 M03\n" + CUT + "M30\n";
        assertTrue(messages("generic", "haas", cut).contains("the chuck must be closed (M10) before cutting"),
                messages("generic", "haas", cut));
        String open = "M10\nS1000 M03\n" + CUT + "M30\n";
        assertTrue(messages("generic", "fanuc-a", open).contains("the chuck must be closed (M11) before cutting"),
                messages("generic", "fanuc-a", open));
    }

    @Test
    void aHaasBarPullIsAWarningForTheSimulationToJudge() {
        // Haas: M05 stops, M11 unclamps, G98 G01 pulls the bar, M10 clamps again (spindle stopped)
        String pull = "G50 S2500\nS1000 M03\n" + CUT + "M05\nM11\nG98 G01 Z50. F1000.\nM10\nM30\n";
        assertEquals("8:5:E661", check("generic", "haas", pull));
        assertTrue(messages("generic", "haas", pull).contains("spindle stopped and the chuck open (M11)"),
                messages("generic", "haas", pull));
    }

    @Test
    void m02EndsTheProgramExceptOnTheThesisControl() {
        assertEquals("", check("generic", "haas", "G00 X42. Z2.\nM02\n"));
        assertEquals("", check("generic", "fanuc-a", "G00 X42. Z2.\nM02\n"));
        assertEquals("2:1:E053", check("generic", "haas", "M02\nG00 X42.\n"));
        assertTrue(messages("generic", "haas", "G00 X42.\n").contains("the program must end with M02 or M30"));
        assertEquals("2:1:E052", check("generic", "thesis-2004", "G00 X42.\nM02\n"));
    }

    @Test
    void sWithoutAG50ClampIsClampedByTheMachine() {
        assertEquals("1:1:E050", check("generic", "thesis-2004", "S1000 M03\nM30\n"));
        assertEquals("", check("generic", "haas", "S1000 M03\n" + CUT + "M30\n"));
        // the generic machine turns at most 4000 rpm
        assertEquals("1:1:E119", check("generic", "haas", "S5000 M03\nM30\n"));
        // above the program's G50 clamp: Haas turns at the clamp (E280 warning, SpindleClampTest)
        assertEquals("2:1:E280", check("generic", "haas", "G50 S2000\nS2500 M03\nM30\n"));
    }

    @Test
    void sequenceNumbersMayRepeatOrGoDownExceptOnTheThesisControl() {
        assertEquals("2:1:E043", check("generic", "thesis-2004", "N10\nN5\nM30\n"));
        assertEquals("", check("generic", "haas", "N10\nN5\nM30\n"));
        assertEquals("3:1:E114", check("generic", "haas", "N10 G00 X42.\nN20\nN10 G00 X44.\nM30\n"));
    }

    @Test
    void axisWordsBeforeAnyMotionGAreARapidAtPowerUp() {
        assertEquals("1:1:E044", check("generic", "thesis-2004", "X10.\nM30\n"));
        assertEquals("", check("generic", "haas", "X42. Z2.\nM30\n"));
        assertEquals("", check("generic", "fanuc-a", "X42. Z2.\nM30\n"));
    }

    // ---- the words of real safe-start and homing lines ----

    @Test
    void safeStartLinesAreAcceptedAndOtherPlanesAreNamed() {
        assertEquals("", check("generic", "haas", "G00 G18 G20 G40 G80 G99\nG18 G21 G40 G80 G97 G99\nM30\n"));
        assertEquals("", check("generic", "fanuc-a", "G00 G18 G21 G40 G80 G99\nM30\n"));
        assertEquals("1:1:E112", check("generic", "haas", "G17\nM30\n"));
        assertEquals("1:5:E112", check("generic", "fanuc-a", "G00 G19\nM30\n"));
        assertEquals("1:5:E011", check("generic", "thesis-2004", "G00 G18\nM30\n"));
    }

    @Test
    void g53MovesInMachineCoordinatesFromTheReferencePoint() {
        MachineProfile p = machine("generic", "haas");
        Run r = Run.of(p, "G00 X42. Z2.\nG53 G00 X0.\nG53 Z-10.\nM30", Checker.ERROR_CAP);
        assertEquals("", r.errors());
        assertEquals(p.machineZero().x(), r.line(2).end().x(), 1e-9);
        assertEquals(p.machineZero().z() - 10 * p.z().countsPerMm(), r.line(3).end().z(), 1e-9);
        assertEquals("1:5:E023", check("generic", "haas", "G53 U0.\nM30\n"));
        assertEquals("2:5:E117", check("generic", "fanuc-b", "G91\nG53 X0.\nM30\n"));
        assertEquals("1:5:E015", check("generic", "haas", "G53 X400.\nM30\n"));
        assertEquals("1:1:E011", check("generic", "thesis-2004", "G53 X0.\nM30\n"));
    }

    @Test
    void aBareG28HomesBothAxesOnHaas() {
        MachineProfile p = machine("generic", "haas");
        Run r = Run.of(p, "G00 X42. Z2.\nG28\nM30", Checker.ERROR_CAP);
        assertEquals("", r.errors());
        assertEquals(p.home(), r.line(2).end());
        assertEquals("2:1:E030", check("generic", "thesis-2004", "G00 X42. Z2.\nG28\nM30\n"));
        assertEquals("", check("generic", "haas", "G28 G00 U0 W0\nM30\n"));
        assertEquals("", check("generic", "thesis-2004", "G28 G00 U0 W0\nM30\n"));
        assertEquals("1:5:E035", check("generic", "haas", "G28 G01 U0 W0\nM30\n").split(", ")[0]);
    }

    @Test
    void aBareG28MovesNothingOnFanucWithAWarning() {
        for (String control : new String[] {"fanuc-a", "fanuc-b"}) {
            MachineProfile p = machine("fanuc", control);
            Run r = Run.of(p, "G00 X42. Z2.\nG28\nM30", Checker.ERROR_CAP);
            assertEquals("2:1:E704", r.errors(), control);
            assertEquals(r.line(1).end(), r.line(2).end(), control);
            assertEquals(0, r.line(2).motions().size(), control);
        }
        // naming the axes homes them, as before
        MachineProfile a = machine("fanuc", "fanuc-a");
        Run named = Run.of(a, "G00 X42. Z2.\nG28 U0. W0.\nM30", Checker.ERROR_CAP);
        assertEquals("", named.errors());
        assertEquals(a.home(), named.line(2).end());
    }

    @Test
    void dwellPIsSecondsWithAPointOnHaasAndMillisecondsOnFanuc() {
        assertEquals(3.0, dwell("haas", "G04 P3."), 1e-9);
        assertEquals(0.003, dwell("haas", "G04 P3"), 1e-9);
        assertEquals(0.5, dwell("haas", "G04 P0.5"), 1e-9);
        assertEquals(3.0, dwell("fanuc-a", "G04 P3000"), 1e-9);
        assertEquals("1:5:E013", check("generic", "fanuc-a", "G04 P3.\nM30\n"));
    }

    private static double dwell(String control, String block) {
        Run r = Run.of(machine("generic", control), block + "\nM30", Checker.ERROR_CAP);
        assertEquals("", r.errors());
        return ((gcnc.ir.Motion.Dwell) r.line(1).motions().get(0)).seconds();
    }

    @Test
    void programNumbersWithAColonAndBlockDelete() {
        assertEquals("", check("generic", "fanuc-a", "%\n:0100 (FLANGE)\nG00 X42. Z2.\n/M01\nN20 /G00 X44.\nM30\n%\n"));
        assertEquals("2:1:E010", check("generic", "thesis-2004", "G00 X42.\n/M01\nM30\n"));
    }

    @Test
    void bothPositionsOfTheBlockDeleteSwitchAreChecked() {
        // switch off (as compiled): the block runs and the cut is clean; switch on: no spindle for the cut
        String p = "G00 X42. Z2.\n/S1000 M03\nG01 X40. F0.2\nM30\n";
        assertEquals("3:1:E051, 3:1:E118", check("generic", "haas", p));
        assertTrue(messages("generic", "haas", p).contains("note[E118]: this occurs with the block delete switch on"),
                messages("generic", "haas", p));
        // an error in the deleted block itself is found with the switch off
        assertEquals("2:6:E015", check("generic", "haas", "G00 X42. Z2.\n/G00 X900.\nM30\n"));
    }

    // ---- every M code of the control's table; no output is a warning ----

    @Test
    void anMCodeWithoutAnOutputIsAWarningOnce() {
        String p = "M31\nG00 X42.\nM33\nM33\nM30\n";
        assertEquals("1:1:E113, 3:1:E113", check("generic", "haas", p));
        assertTrue(messages("generic", "haas", p).contains("warning[E113]: M33 has no output on machine generic: it does nothing"));
        assertEquals("1:1:E012", check("generic", "haas", "M93\nM30\n"));
        // fanuc M codes beyond its table are the machine builder's: passed on, with the same warning
        assertEquals("1:1:E113", check("generic", "fanuc-a", "M16\nM30\n"));
    }

    // ---- never misread: cycles and friends are named, at their G ----

    @Test
    void g92AndG90MeanWhatTheControlSays() {
        String thread = "G00 X42. Z2.\nG92 X39. Z-20. F1.5\nM30\n";
        // haas and fanuc A: G92 is the thread cycle, which the generic machine cannot cut (no spindle
        // encoder: docs/threading.md), never a coordinate shift
        assertEquals("2:1:E190", check("generic", "haas", thread));
        assertEquals("2:1:E190", check("generic", "fanuc-a", thread));
        assertTrue(messages("generic", "haas", thread).contains("error[E190]: machine generic has no spindle encoder: G92 cannot be cut"),
                messages("generic", "haas", thread));
        // fanuc B: G92 sets the coordinates (and with S the clamp); thesis: the position register
        assertEquals("", check("generic", "fanuc-b", "G92 X100. Z50.\nG92 S500\nM30\n"));
        assertEquals("", check("generic", "thesis-2004", "G92 X100. Z50.\nM30\n"));
        // haas and fanuc A: G90 is the turning cycle (docs/cycles.md); fanuc B numbers it G77
        String turn = "S500 M03\nG00 X42. Z2.\nG90 X39. Z-20. F0.2\nM30\n";
        assertEquals("", check("generic", "haas", turn));
        assertEquals("", check("generic", "fanuc-a", turn));
        assertEquals("", check("generic", "fanuc-b", "S500 M03\nG00 X42. Z2.\nG77 X39. Z-20. F0.2\nM30\n"));
        assertEquals("3:1:E169", check("generic", "fanuc-a", "S500 M03\nG00 X42. Z2.\nG90 X39. F0.2\nM30\n"));
        assertEquals("", check("generic", "fanuc-b", "G90 G00 X42. Z2.\nG91 G00 X-1.\nM30\n"));
    }

    @Test
    void cyclesCompensationAndSubprogramsAreNamedAtTheirWord() {
        // Fanuc's G83 on the centre line is followed (TappingTest), G85 face boring too (BoringCyclesTest);
        // C-axis positioning (live tooling) is not supported yet, nor side drilling along X
        assertEquals("1:9:E188", check("generic", "fanuc-a", "N40 G83 C90. Z-1. Q1000 F0.01\nM30\n"));
        assertTrue(messages("generic", "fanuc-a", "G87 X10. R0.5\nM30\n").contains(
                "p.nc:1:1: error[E110]: G87 side drilling cycle (live tooling along X) is not supported yet"),
                messages("generic", "fanuc-a", "G87 X10. R0.5\nM30\n"));
        // G41/G42 are followed (NoseCompensationTest), no longer E110; generic's offsets have no nose radius (E177, a note)
        assertEquals("3:1:E177", check("generic", "haas", "S500 M03\nG00 X40. Z2.\nG42 G01 X30. F0.1\nZ-10.\nG40 G00 X40.\nM30\n"));
        // the thesis's control has no subprograms; Fanuc's follows the call (ProgramFlowTest): no O1000 here
        assertEquals("1:1:E110", check("generic", "thesis-2004", "M98 P1000\nM30\n"));
        assertEquals("1:5:E130", check("generic", "fanuc-a", "M98 P1000\nM30\n"));
    }

    @Test
    void aWordOfNoFunctionIsNamed() {
        assertEquals("1:14:E108", check("generic", "haas", "G00 X42. Z2. Q5.\nM30\n"));
        assertEquals("1:14:E004", check("generic", "thesis-2004", "G00 X42. Z2. Q5.\nM30\n"));
    }

    // ---- recovery without echoes ----

    @Test
    void aRejectedSafeStartLineKeepsItsUnitsAndFeedMode() {
        // G07 is not a G code: the block is rejected, but G20 and G99 stand on their own
        MachineProfile p = machine("generic", "fanuc-a");
        Run r = Run.of(p, "G00 G20 G99 G07\nS1000 M03\nG00 X1. Z0.1\nG01 Z-1. F0.01\nM30", Checker.ERROR_CAP);
        assertEquals("1:13:E011", r.errors());
        Run ok = Run.of(p, "G00 G20 G99\nS1000 M03\nG00 X1. Z0.1\nG01 Z-1. F0.01\nM30", Checker.ERROR_CAP);
        assertEquals(ok.line(4).end(), r.line(4).end());
    }

    @Test
    void aBlockRejectedForItsSKeepsItsFeedUnderG99() {
        // docs/examples/mistakes.nc with G99 and F0.2: line 9's S is above the clamp; line 12's arc is still judged
        String p = String.join("\n", "O1003", "N10 G21 G90 G99", "N20 G50 S2500", "N30 M11", "N40 T0101",
                "N50 G00 X42. Z2.", "N60 G01 X40. F0.2", "N70 S3000 M03", "N80 G01 Z-30.", "N90 G01 X44. Z-31.",
                "N100 G02 X50. Z-60. R3.", "N110 G00 X300. Z5.", "N120 M05", "N130 M30");
        assertEquals("7:5:E051, 8:5:E048, 11:21:E101, 12:10:E015", check("generic", "thesis-2004", p));
    }

    @Test
    void aSpindleNeverStartedIsOneErrorWithANote() {
        String p = "G00 X42. Z2.\nG01 X40. F0.2\nG01 Z-10.\nG01 X44.\nG00 Z2.\nG01 X38.\nM30\n";
        assertEquals("2:1:E051, 2:1:E115", check("generic", "haas", p));
        assertTrue(messages("generic", "haas", p).contains("note[E115]: 3 later blocks have the same cause (lines 3, 4, 6)"),
                messages("generic", "haas", p));
    }

    @Test
    void aMistypedSpindleCodeIsNotEchoedByTheCuts() {
        // M93 for M03: reported once; the cuts are not blamed for a spindle gcnc could not read
        assertEquals("1:11:E012", check("generic", "haas", "G97 S1000 M93\n" + CUT + "M30\n"));
    }

    // ---- a missing decimal point ----

    @Test
    void aCoordinateWithoutPointFarFromItsNeighboursIsAWarning() {
        String p = "S1000 M03\nG00 X40. Z2.\nG01 X42 F0.2\nM30\n";
        assertEquals("3:5:E107", check("generic", "fanuc-a", p));
        assertTrue(messages("generic", "fanuc-a", p).contains(
                "warning[E107]: X42 has no decimal point: read as 0.042 mm (write X42. for 42 mm)"), messages("generic", "fanuc-a", p));
        assertEquals("", check("generic", "fanuc-a", "G00 X40000 Z2000\nG00 X0 Z-500\nM30\n"));
        // the thesis reads X42 as 42 mm: nothing to warn about on its machine
        assertEquals("", check("thesis-2004", null, "G00 X3000 Z-500\nG00 X42 Z-1\nM30\n"));
    }

    @Test
    void theShippedMachinesNameTheirControls() {
        assertEquals("haas", machine("haas", null).control().name());
        assertEquals("fanuc-a", machine("fanuc", null).control().name());
        assertEquals("fanuc-b", machine("fanuc", "fanuc-b").control().name());
        assertEquals(gcnc.machine.Units.INCH, machine("haas", null).units());
        assertEquals(new Point(0, 0).getClass(), machine("haas", null).machineZero().getClass());
    }
}
