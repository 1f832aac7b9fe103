package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.dmc.Instruction;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class ReplayTest {
    static MachineProfile profile(String name) throws Exception {
        return ProfileLoader.load(name, TableSource.builtIn(), Tables.builtIn());
    }

    static List<String> codes(Diagnostics d) {
        List<String> out = new ArrayList<>();
        for (Diagnostic x : d.sorted()) {
            out.add(x.code().id() + "@" + x.span().line());
        }
        return out;
    }

    /**
     * Table 5.2 replayed by itself on the thesis's machine: the three zero-sweep CRs (N240, N260,
     * N410) are flagged where they are; nothing else is wrong with the moves before the first of them.
     */
    @Test
    void thesisTableFiveTwoReplayedAlone() throws Exception {
        Diagnostics d = new Diagnostics();
        try (BufferedReader in = new BufferedReader(new InputStreamReader(
                ReplayTest.class.getResourceAsStream("bishop.thesis.dmc"), StandardCharsets.UTF_8))) {
            SimReport r = DmcReplay.replay(in, profile("thesis-2004"), SimOptions.defaults(), d);
            assertTrue(r.sequences() > 50);
        }
        List<String> c = codes(d);
        long zero = c.stream().filter(s -> s.startsWith("E309")).count();
        assertEquals(3, zero, c.toString());
        int firstZero = d.sorted().stream().filter(x -> x.code().id().equals("E309")).findFirst().orElseThrow().span().line();
        assertTrue(d.sorted().stream().noneMatch(x -> x.span().line() < firstZero), c.toString());
    }

    @Test
    void sourceMapCommentsLocateFindings() throws Exception {
        Diagnostics d = new Diagnostics();
        String dmc = "#GCNC\nSH XY\nVM XY\nNO L12\nVS 100000\nFOO\nEN\n";
        DmcReplay.replay(new BufferedReader(new StringReader(dmc)), profile("generic"), SimOptions.defaults(), d);
        assertEquals(List.of("E300@12"), codes(d));
    }

    @Test
    void withoutSourceMapFindingsAreAtTheDmcLine() throws Exception {
        Diagnostics d = new Diagnostics();
        DmcReplay.replay(new BufferedReader(new StringReader("#GCNC\nSH XY\nVM XY\nFOO 1\nEN\n")),
                profile("generic"), SimOptions.defaults(), d);
        assertEquals(List.of("E300@4"), codes(d));
    }

    /**
     * A DMC file by itself is held to the controller's limits as a compile's output is: a hand-edited
     * CR of radius 9 (COMALL CR: n0 from 10) is E224 at its line and counts as a finding of the replay.
     */
    @Test
    void aDmcFileAloneIsHeldToTheControllersLimits() throws Exception {
        Diagnostics d = new Diagnostics();
        String dmc = "#GCNC\nSH XY\nVM XY\nVS 20000\nCR 9,0,90;VE;BGS;AMS\nEN\n";
        SimReport r = DmcReplay.replay(new BufferedReader(new StringReader(dmc)), profile("generic"),
                SimOptions.defaults(), d);
        assertEquals(List.of("E224@5"), codes(d));
        assertEquals(1, r.findings());
    }

    @Test
    void shippedProfilesHaveASimulatorModel() throws Exception {
        for (String name : new String[] {"generic", "thesis-2004"}) {
            SimMachine m = SimMachine.read(profile(name));
            assertTrue(m.stock().isPresent(), name);
            assertEquals(2, m.chuck().length, name);
        }
    }

    /** Compiles with the simulator on and returns the DMC text (the program must be clean). */
    static String compile(String program, String machine) throws Exception {
        StringBuilder dmc = new StringBuilder();
        gcnc.Compiler.Result r = gcnc.Compiler.compile(new StringReader(program), new gcnc.Compiler.Settings(
                Tables.builtIn(), profile(machine), Dialect.Kind.GALIL, java.util.Optional.of(SimOptions.defaults())),
                l -> dmc.append(l.text()).append('\n'));
        assertEquals(List.of(), codes(r.diagnostics()), program);
        return dmc.toString();
    }

    static List<String> replay(String dmc, String machine) throws Exception {
        Diagnostics d = new Diagnostics();
        DmcReplay.replay(new BufferedReader(new StringReader(dmc)), profile(machine), SimOptions.defaults(), d);
        return codes(d);
    }

    /**
     * The header sets IT 1 on both plane axes (no smoothing: a unit with IT below 1 burned in would round
     * the corners the replay verified); the replay models IT 1 only and refuses a smaller value (E336).
     */
    @Test
    void theHeaderTurnsSmoothingOffAndTheReplayRefusesAnyOther() throws Exception {
        String dmc = compile("G21 G98\nG00 X40. Z2.\nM30\n", "generic");
        List<String> header = dmc.lines().flatMap(l -> gcnc.dmc.DmcReader.statements(l).stream()).toList();
        assertTrue(header.containsAll(List.of("IT 1", "IT ,1")), header.toString());
        assertTrue(header.indexOf("IT 1") > header.indexOf("VM XY"), header.toString());
        String head = "#GCNC\nSH XY\nVM XY\n";
        assertEquals(List.of(), replay(head + "IT 1\nIT ,1\nEN\n", "generic"));
        assertEquals(List.of("E336@4"), replay(head + "IT 0.5\nEN\n", "generic"));
    }

    /**
     * The command reference's AV replayed by the simulator: "measured from the start of a coordinated move
     * sequence or from the last AV command", so in a 3,000-count sequence AV 1000 then AV 1500 trips at
     * 2,500 counts (on the path), and AV 1000 then AV 2500 at 3,500: past its end (E334), though 2,500
     * alone would be on it.
     */
    @Test
    void anAvMeasuresFromTheLastAvAndTheirSumMustBeOnThePath() throws Exception {
        String head = "#GCNC\nSH XY\nVM XY\nVS 10000\nVP 1000,0\nVP 2000,0\nVP 3000,0\nVE\nBGS\nAV 1000\n";
        assertEquals(List.of(), replay(head + "AV 1500\nAMS\nEN\n", "generic"));
        assertEquals(List.of("E334@11"), replay(head + "AV 2500\nAMS\nEN\n", "generic"));
        assertEquals(List.of(), replay(head + "AMS\nVS 10000\nVP 3000,0\nVE\nBGS\nAV 2500\nAMS\nEN\n", "generic"),
                "a new sequence measures from its own start");
    }

    /**
     * On thesis-2004 a feed of F1000 has the VS of a rapid: the DMC marks it (NO G01), so that a
     * replay of the DMC by itself cuts with it instead of reporting a rapid into the blank.
     */
    @Test
    void aFeedAsFastAsARapidIsMarkedAndReplayedAsAFeed() throws Exception {
        String program = "N100 G00 X+3234 Z+00500\nG50 S5000 M11 M03 F150\nN130 G00 X+2034 Z+00100\n"
                + "N135 G01 Z-01000 F1000\nN137 G00 X+2234 Z+00100\nN140 G00 X+3234 Z+00500\nM05\nM30\n";
        String dmc = compile(program, "thesis-2004");
        assertEquals(1, dmc.split("\nNO G01\n", -1).length - 1, dmc);
        assertEquals(List.of(), replay(dmc, "thesis-2004"));
        List<String> unmarked = replay(dmc.replace("NO G01\n", ""), "thesis-2004");
        assertEquals(1, unmarked.size(), "without the mark: a rapid into the blank " + unmarked);
        assertTrue(unmarked.get(0).startsWith("E305@"), unmarked.toString());
    }

    /** The blank of a program's stock header goes into the DMC, and a replay cuts that blank, not the profile's. */
    @Test
    void theProgramsBlankTravelsWithTheDmc() throws Exception {
        // a D30 blank: the pass at X36. runs in the air; the generic profile's D44 blank would be hit
        String program = "(100 30)\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1000 M03\nG00 X36. Z2.\n"
                + "G00 Z-20.\nG00 X60.\nM05\nM30\n";
        String dmc = compile(program, "generic");
        assertTrue(dmc.contains("\nNO STOCK D30 L100 S100\n"), dmc);
        assertEquals(List.of(), replay(dmc, "generic"));
        List<String> profiles = replay(dmc.replace("NO STOCK D30 L100 S100\n", ""), "generic");
        assertTrue(profiles.size() == 1 && profiles.get(0).startsWith("E305@"), "the profile's D44 blank is in the way: "
                + profiles);
    }

    @Test
    void aSourceMapFileLocatesReplayFindingsAtGcodeLines() throws Exception {
        gcnc.dmc.SourceMap.Table t = gcnc.dmc.SourceMap.read(new BufferedReader(new StringReader(
                "# source part.nc\n1 0\n6 4\n9 7\n")));
        assertEquals(java.util.Optional.of("part.nc"), t.source());
        java.util.function.IntUnaryOperator line = n -> t.lines().apply(n) == null ? 0 : t.lines().apply(n).line();
        assertEquals(List.of(0, 0, 4, 4, 4, 7, 7), List.of(line.applyAsInt(1), line.applyAsInt(5),
                line.applyAsInt(6), line.applyAsInt(7), line.applyAsInt(8), line.applyAsInt(9),
                line.applyAsInt(500)));
    }

    @Test
    void aSourceMapEntryNamesTheFileOfACalledProgram() throws Exception {
        gcnc.dmc.SourceMap.Table t = gcnc.dmc.SourceMap.read(new BufferedReader(new StringReader(
                "# source grooves.nc\n1 0\n6 4\n40 4 O2000.nc\n47 9\n")));
        assertEquals(null, t.lines().apply(6).file());
        assertEquals(4, t.lines().apply(40).line());
        assertEquals("O2000.nc", t.lines().apply(46).file());
        assertEquals(null, t.lines().apply(47).file());
    }
}
