package gcnc.galil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Severity;
import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.sim.SimOptions;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.OptionalDouble;
import java.util.OptionalInt;
import org.junit.jupiter.api.Test;

/**
 * The machine around the motion (docs/galil.md): tiny programs, one behaviour each, compiled and
 * replayed in the simulator (which must find nothing), with the DMC lines that carry the behaviour.
 */
class MachineCodeTest {
    private static final Tables TABLES = Tables.builtIn();

    /**
     * A program in the generic machine's language: start the spindle, approach, one feed, stop.
     * {@code gline} holds the file's line (N10 is line 2, the M03 line 6, the feed line 8).
     */
    private static final String TURN = "O1\nN10 G21 G90 G98\nN20 G50 S2500\nN30 M11\nN40 T0101\nN50 S1200 M03\n"
            + "N60 G00 X42. Z2.\nN70 G01 X40. F120.\nN80 G00 X60. Z5.\nN90 M05\nN100 M30\n";

    /**
     * The generic lathe on an eight-axis DMC-4080 (16 outputs: room for the turret's five) with a
     * Modbus analog output for the spindle, an at-speed input and an indexed turret.
     */
    private static final String WIRED = "spindle.output = AO 3001\nspindle.at_speed = IN3\nspindle.at_speed_timeout = 8\n"
            + "turret.station_outputs = 9, 10, 11, 12\nturret.strobe = 13\nturret.in_position = 4\nturret.timeout = 5\n";

    private static String generic() throws Exception {
        return Files.readString(Path.of("tables/machines/generic.machine"));
    }

    private static String wired() throws Exception {
        return generic().replace("galil.model = DMC-4030", "galil.model = DMC-4080") + WIRED;
    }

    private static MachineProfile profile(String text) throws Exception {
        return ProfileLoader.read(ProfileFile.parse("t.machine", text), TABLES);
    }

    /** Compiles and replays: the simulator must find nothing, and only the expected warnings are there. */
    private static List<String> compile(String program, MachineProfile p, Diagnostics[] seen) throws Exception {
        List<String> out = new ArrayList<>();
        Compiler.Result r = Compiler.compile(new StringReader(program),
                new Compiler.Settings(TABLES, p, Dialect.Kind.GALIL, Optional.of(SimOptions.defaults().withoutBlank())),
                (Instruction l) -> out.add(l.text()));
        assertTrue(r.ok(), () -> r.diagnostics().sorted().toString());
        assertEquals(0, r.simulation().orElseThrow().findings(), () -> r.diagnostics().sorted().toString());
        if (seen != null) {
            seen[0] = r.diagnostics();
        }
        return out;
    }

    private static List<String> compile(String program, MachineProfile p) throws Exception {
        return compile(program, p, null);
    }

    /**
     * The whole program on the wired machine (analog spindle output, at-speed input, turret): every
     * form of the machine code in one golden file, which RoundTripTest also reads back.
     */
    @Test
    void theWiredMachinesProgramMatchesItsGoldenFile() throws Exception {
        Path golden = Path.of("src/test/resources/golden/machine-wired.generic.galil.dmc");
        String program = TURN.replace("T0101", "T0505").replace("N80 G00", "N75 G04 P1\nN80 G00");
        String actual = String.join("\n", compile(program, profile(wired() + "homing.check = IN7\n"))) + "\n";
        if (Boolean.getBoolean("gcnc.updateGolden")) {
            Files.writeString(golden, actual);
        }
        assertEquals(Files.readString(golden), actual);
    }

    @Test
    void m05ZeroesTheSpindleAfterItsOutputs() throws Exception {
        List<String> out = compile(TURN, profile(generic()));
        int stop = out.indexOf("gline=10");
        assertEquals(List.of("gline=10", "CB1", "OF ,,0.0000"), out.subList(stop, stop + 3));
        // already zero: EN follows without another zero
        assertEquals(stop + 3, out.indexOf("EN"));
    }

    @Test
    void aProgramEndingWithTheSpindleOnZeroesItBeforeEn() throws Exception {
        List<String> out = compile(TURN.replace("N90 M05\n", ""), profile(generic()));
        assertEquals("OF ,,0.0000", out.get(out.indexOf("EN") - 1));
    }

    @Test
    void m03ThenFeedWaitsForSpeedBeforeTheFeedNotTheRapid() throws Exception {
        List<String> out = compile(TURN, profile(generic()));
        // the rapid approach runs while the spindle runs up; the feed waits the profile's 2 s
        int rapid = out.indexOf("gline=7");
        assertEquals("VS 100000", out.get(rapid + 1));
        int feed = out.indexOf("gline=8");
        assertEquals(List.of("gline=8", "WT 2000", "VS 2000"), out.subList(feed, feed + 3));
        assertEquals(1, out.stream().filter(l -> l.startsWith("WT")).count(), "one wait: the start");
    }

    @Test
    void anAtSpeedInputIsWaitedForWithATimeout() throws Exception {
        List<String> out = compile(TURN, profile(wired()));
        int feed = out.indexOf("gline=8");
        assertEquals(List.of("gline=8", "JS #SPWAIT", "VS 2000"), out.subList(feed, feed + 3));
        int w = out.indexOf("#SPWAIT");
        assertEquals(List.of("#SPWAIT", "twt=TIME+8000", "#SPW", "JP #SPOK,@IN[3]=1", "JP #SPW,TIME<twt",
                "MG \"SPINDLE NOT AT SPEED AT G-CODE LINE\",gline", "JP #FAULT", "#SPOK", "EN"), out.subList(w, w + 9));
        // the drive's reference is AO 3001 (handle C's first point): set, zeroed at M05, the OF of C left alone
        assertTrue(out.contains("AO 3001,2.9268"), out.toString()); // 1200 r/min at 410 per volt
        assertEquals("AO 3001,0.0000", out.get(out.indexOf("gline=10") + 2));
        assertTrue(out.stream().noneMatch(l -> l.startsWith("OF") || l.startsWith("KP")), out.toString());
    }

    @Test
    void aToolChangeIndexesTheTurretAndWaitsForItsAnswer() throws Exception {
        List<String> out = compile(TURN.replace("T0101", "T0505"), profile(wired()));
        int t = out.indexOf("gline=5");
        // station 5 = 0101 on outputs 9 (lsb) .. 12, the strobe, the wait, then TOOL=5
        assertEquals(List.of("gline=5", "SB9", "CB10", "SB11", "CB12", "SB13", "JS #TURRET", "TOOL=5"),
                out.subList(t, t + 8));
        int r = out.indexOf("#TURRET");
        assertEquals(List.of("#TURRET", "twt=TIME+5000", "#TUW", "JP #TUOK,@IN[4]=1", "JP #TUW,TIME<twt", "CB13",
                "MG \"TURRET NOT IN POSITION AT G-CODE LINE\",gline", "JP #FAULT", "#TUOK", "CB13", "EN"),
                out.subList(r, r + 11));
    }

    @Test
    void theSmallStepsOfG96AlongACutAreNotWaitedFor() throws Exception {
        // G96 S150: 1137 r/min at X42, 1194 at X40 (+5%), 1224 at X39 (+2.6%): the start is waited
        // for before the first feed, the steps are followed on the move
        String css = "O1\nN10 G21 G90 G98\nN20 G50 S2500\nN30 M11\nN40 T0101\nN50 G96 S150 M03\n"
                + "N60 G00 X42. Z2.\nN70 G01 X40. F120.\nN80 G01 X39.\nN90 G00 X60. Z5.\nN100 M05\nN110 M30\n";
        List<String> out = compile(css, profile(wired()));
        assertEquals(List.of("JS #SPWAIT"), out.stream().filter(l -> l.startsWith("JS #SP")).toList());
        int feed = out.indexOf("gline=8");
        assertEquals(List.of("gline=8", "AO 3001,2.9114", "JS #SPWAIT", "VS 2000"), out.subList(feed, feed + 4),
                "the block's speed (1194 r/min at 410 per volt), then the wait, then the first feed");
        // a speed per block (M03's at home, X42, X40, X39, X60): the retract's -33% is waited for
        // only before a next feed, and there is none
        assertEquals(5, out.stream().filter(l -> l.startsWith("AO 3001,") && !l.equals("AO 3001,0.0000")).count(),
                out.toString());
    }

    @Test
    void withoutTurretOutputsATooChangeIsTheToolVariableOnly() throws Exception {
        List<String> out = compile(TURN, profile(generic()));
        int t = out.indexOf("gline=5");
        assertEquals(List.of("gline=5", "TOOL=1", "gline=6"), out.subList(t, t + 3));
        assertTrue(!out.contains("#TURRET"));
    }

    @Test
    void softLimitsAreTheTravelInCountsPerShippedProfile() {
        // generic: Z 0..350 mm and X -2..110 mm at 1000 counts/mm; fanuc: Z -10..570, X -5..215 at
        // 500; haas: Z -20..513, X -4..212 at 984.25 counts/mm (25000 per inch)
        assertLimits("generic", "BL 0,-2000", "FL 350000,110000");
        assertLimits("fanuc", "BL -5000,-2500", "FL 285000,107500");
        assertLimits("haas", "BL -19685,-3937", "FL 504921,208661");
    }

    @Test
    void softLimitsFollowTheAxisSign() {
        // lathe X counting against the machine axis: its Galil range is -110 mm .. +2 mm
        MachineProfile minus = Fixtures.mapped(Fixtures.profile("generic"), 'Y', -1, 'X', 1, new Point(105000, 340000));
        List<String> out = Fixtures.run("galil", minus, new Diagnostics());
        assertTrue(out.contains("BL 0,-110000"), out.toString());
        assertTrue(out.contains("FL 350000,2000"), out.toString());
        assertTrue(out.contains("JP #NOHOME,@ABS[_TPY+105000]>10"), out.toString());
    }

    private static void assertLimits(String machine, String bl, String fl) {
        List<String> out = Fixtures.run("galil", Fixtures.profile(machine), new Diagnostics());
        assertTrue(out.contains(bl), machine + ": " + out);
        assertTrue(out.contains(fl), machine + ": " + out);
        assertTrue(out.indexOf(fl) < out.indexOf("EN"));
    }

    @Test
    void theProgramRefusesToStartAwayFromHomeBeforeItsFirstMove() throws Exception {
        List<String> out = compile(TURN, profile(generic()));
        int first = out.indexOf("VS 100000");
        assertTrue(out.indexOf("JP #NOHOME,@ABS[_TPX-340000]>10") < first);
        assertTrue(out.indexOf("JP #NOHOME,@ABS[_TPY-105000]>10") < first);
        int r = out.indexOf("#NOHOME");
        assertEquals(List.of("#NOHOME", "MG \"NOT AT HOME: HOME THE MACHINE THEN START AGAIN\"", "EN"),
                out.subList(r, r + 3));
        List<String> input = compile(TURN, profile(generic() + "homing.check = IN7\n"));
        assertTrue(input.contains("JP #NOHOME,@IN[7]=0"), input.toString());
        List<String> none = compile(TURN, profile(generic() + "homing.check = none\n"));
        assertTrue(none.stream().noneMatch(l -> l.contains("NOHOME")), none.toString());
    }

    @Test
    void everyHandlerStopsTheMotionZeroesTheSpindleAndSaysTheLine() throws Exception {
        List<String> out = compile(TURN, profile(generic()));
        int fault = out.indexOf("#FAULT");
        // the common stop: decelerate, wait, zero volts, the M05 outputs, end the program (ZS: no return)
        assertEquals(List.of("#FAULT", "ST", "AM XY", "OF ,,0.0000", "CB1", "ZS", "EN"), out.subList(fault, out.size()));
        for (String h : MachineCode.HANDLERS) {
            int at = out.indexOf("#" + h);
            assertTrue(at > out.indexOf("EN") && at < fault, h);
            List<String> body = new ArrayList<>();
            for (int i = at + 1; !out.get(i).startsWith("#"); i++) {
                body.add(out.get(i));
            }
            assertEquals("JP #FAULT", body.get(body.size() - 1), h);
            assertTrue(body.stream().anyMatch(l -> l.startsWith("MG ") && l.endsWith(",gline") || l.contains(",gline,")), h);
            // a following or amplifier fault aborts at once; a limit or command error decelerates (ST in #FAULT)
            assertEquals(h.equals("POSERR") || h.equals("AMPERR"), body.get(0).equals("AB 1"), h);
        }
        // the line a handler reports is set where each block starts
        assertTrue(out.indexOf("gline=0") < out.indexOf("gline=4"));
    }

    @Test
    void aDwellBelowTwoMillisecondsWaitsTwoWithAWarning() {
        Diagnostics d = new Diagnostics();
        CheckedBlock p1 = new CheckedBlock(7, OptionalDouble.empty(), OptionalInt.empty(), List.of(),
                List.of(new Motion.Dwell(0.001)), List.of(), Point.ORIGIN);
        CheckedBlock p0 = new CheckedBlock(8, OptionalDouble.empty(), OptionalInt.empty(), List.of(),
                List.of(new Motion.Dwell(0)), List.of(), Point.ORIGIN);
        List<String> out = Fixtures.run("galil", Fixtures.profile("generic"), d, p1, p0);
        assertEquals(List.of("WT 2"), out.stream().filter(l -> l.startsWith("WT")).toList());
        assertEquals(1, d.size());
        Diagnostic w = d.sorted().get(0);
        assertEquals(Code.E250_DWELL_BELOW_WT, w.code());
        assertEquals(Severity.WARNING, w.severity());
        assertEquals(7, w.span().line());
        assertTrue(!out.contains("gline=8"), "a zero dwell writes nothing");
    }

    @Test
    void g04P1InAProgramIsWarnedAndReplaysClean() throws Exception {
        Diagnostics[] seen = new Diagnostics[1];
        List<String> out = compile(TURN.replace("N80 G00", "N75 G04 P1\nN80 G00"), Fixtures.profile("generic"), seen);
        assertEquals(List.of("gline=9", "WT 2"), out.subList(out.indexOf("gline=9"), out.indexOf("gline=9") + 2));
        assertTrue(seen[0].sorted().stream().anyMatch(x -> x.code() == Code.E250_DWELL_BELOW_WT), seen[0].sorted().toString());
    }

    @Test
    void anAnalogSpindleAboveTenVoltsIsAnErrorAndJustBelowIsClamped() throws Exception {
        MachineProfile p = profile(wired());
        Diagnostics d = new Diagnostics();
        List<String> out = Fixtures.run("galil", p, d,
                new CheckedBlock(5, OptionalDouble.of(4400), OptionalInt.empty(), List.of(), List.of(), List.of(), Point.ORIGIN),
                new CheckedBlock(6, OptionalDouble.of(4100), OptionalInt.empty(), List.of(), List.of(), List.of(), Point.ORIGIN));
        assertTrue(out.contains("AO 3001,9.9980"), out.toString());
        List<Diagnostic> all = d.sorted();
        assertEquals(Code.E251_SPINDLE_AO_VOLTS, all.get(0).code());
        assertEquals(Code.E252_SPINDLE_AO_CLAMPED, all.get(1).code());
        assertEquals(Severity.WARNING, all.get(1).severity());
    }
}
