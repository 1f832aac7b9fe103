package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Diagnostics;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.BufferedReader;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * Thread passes through the backend and the simulator (docs/threading.md): the geared sequence
 * replays as one cutting pass ending where the program's pass ends; a replay of the DMC by itself
 * finds what the compile found; a pass whose gearing starts without GA is E318, without the
 * wait for the whole revolution E319, one whose ratios miss the end is E317; a ratio past GR's range is E208
 * and the thesis dialect, which has no gearing, refuses a thread (E209). A chamfered pull-out (Haas
 * M23) is a second geared segment of the pass: the ratios change at an MF/MR on Z (E301 without it).
 */
class ThreadReplayTest {
    private static final String PROGRAM = "(80.00 24.00)\nG21 G99\nT0707\nG97 S800 M03\nG00 X30. Z5. M08\n"
            + "G92 X23.2 Z-25. F1.5\nX22.8\nX22.5\nG00 X100. Z100. M09\nM30\n";

    private static Compiler.Result compile(MachineProfile p, String dialect, String program, StringBuilder dmc)
            throws java.io.IOException {
        Compiler.Settings s = new Compiler.Settings(Tables.builtIn(), p, Dialect.Kind.of(dialect), Optional.of(SimOptions.defaults()),
                false);
        return Compiler.compile(new StringReader(program), s, l -> dmc.append(l.text()).append('\n'));
    }

    private static List<String> replay(String dmc, MachineProfile p) {
        Diagnostics d = new Diagnostics();
        DmcReplay.replay(new BufferedReader(new StringReader(dmc)), p, SimOptions.defaults(), d);
        return ReplayTest.codes(d);
    }

    @Test
    void aCompiledThreadReplaysCleanAloneAndCutsThePart() throws Exception {
        MachineProfile fanuc = ReplayTest.profile("fanuc");
        StringBuilder dmc = new StringBuilder();
        Compiler.Result r = compile(fanuc, "galil", PROGRAM, dmc);
        assertTrue(r.ok(), r.diagnostics().sorted().toString());
        assertEquals(0, r.simulation().orElseThrow().findings());
        assertEquals(3, dmc.toString().split("GA C,C", -1).length - 1, dmc.toString());
        assertEquals(List.of(), replay(dmc.toString(), fanuc));
    }

    @Test
    void e318E319GearingWithoutItsMasterOrTheWaitForTheWholeRevolution() throws Exception {
        MachineProfile fanuc = ReplayTest.profile("fanuc");
        StringBuilder dmc = new StringBuilder();
        compile(fanuc, "galil", PROGRAM, dmc);
        String[] lines = dmc.toString().split("\n");
        int mf = -1;
        for (int i = 0; i < lines.length && mf < 0; i++) {
            mf = lines[i].equals("MF ,,gsp") ? i + 1 : -1;
        }
        assertTrue(mf > 0, dmc.toString());
        String cut = dmc.toString().replaceFirst("MF ,,gsp\n", "");
        assertEquals(List.of("E319@" + mf), replay(cut, fanuc)); // at the GR, now where the MF was
        String noMaster = dmc.toString().replaceFirst("GA C,C\n", "");
        assertEquals(List.of("E318@" + mf), replay(noMaster, fanuc)); // the GR, a line up again
    }

    @Test
    void e317RatiosThatMissThePassesEnd() throws Exception {
        MachineProfile fanuc = ReplayTest.profile("fanuc");
        StringBuilder dmc = new StringBuilder();
        compile(fanuc, "galil", PROGRAM, dmc);
        String good = dmc.toString();
        int gr = good.indexOf("\nGR -0.1831,0.0000\n");
        assertTrue(gr > 0, good);
        // a taper nobody asked for: X follows the spindle too, and ends 35 counts off
        String wrong = good.replaceFirst("\nGR -0\\.1831,0\\.0000\n", "\nGR -0.1831,0.0010\n");
        List<String> found = replay(wrong, fanuc);
        assertEquals(1, found.size(), found.toString());
        assertTrue(found.get(0).startsWith("E317@"), found.toString());
    }

    @Test
    void e208ARatioBeyondGalilsRange() throws Exception {
        Path f = Path.of("tables/machines/fanuc.machine");
        String text = Files.readString(f).replace("spindle.encoder = 4096", "spindle.encoder = 4");
        MachineProfile coarse = ProfileLoader.read(ProfileFile.parse("coarse.machine", text), Tables.builtIn(),
                TableSource.builtIn(), null);
        StringBuilder dmc = new StringBuilder();
        Compiler.Result r = compile(coarse, "galil", PROGRAM, dmc);
        // 1.5 mm x 500 counts/mm = 750 Z counts per revolution over 4 encoder counts: 187.5, found by
        // the checker already (check and compile give one verdict)
        assertEquals("E208@6", ReplayTest.codes(r.diagnostics()).get(0));
        Compiler.Result checked = Compiler.check(new StringReader(PROGRAM), new Compiler.Settings(Tables.builtIn(),
                coarse, Dialect.Kind.GALIL, Optional.empty()));
        assertEquals("E208@6", ReplayTest.codes(checked.diagnostics()).get(0));
    }

    /** The same G92 on the haas machine, where M23 (the chamfered pull-out) is in force at power-up. */
    private static final String CHAMFERED = "(80.00 24.00)\nG21 G99\nT303\nG97 S800 M03\nG00 X30. Z5. M08\n"
            + "G92 X23.2 Z-25. F1.5\nX22.8\nX22.5\nG00 X100. Z100. M09\nM30\n";

    private static int count(String text, String piece) {
        return text.split(java.util.regex.Pattern.quote(piece), -1).length - 1;
    }

    @Test
    void aChamferedPullOutIsASecondGearedSegmentAndReplaysCleanAlone() throws Exception {
        MachineProfile haas = ReplayTest.profile("haas");
        StringBuilder dmc = new StringBuilder();
        Compiler.Result r = compile(haas, "galil", CHAMFERED, dmc);
        assertTrue(r.ok(), r.diagnostics().sorted().toString());
        assertEquals(0, r.simulation().orElseThrow().findings());
        String text = dmc.toString();
        // each pass: engage, wait for Z at the chamfer's start (one lead, 1476 counts, before the
        // end), the chamfer's ratios (X out as fast as Z goes on: 45 degrees), wait for the end
        assertEquals(3, count(text, "GA C,C"), text);
        // (one ratio for every pass, from the lead: issue 30; the phase correction after the engagement)
        java.util.regex.Matcher pass = java.util.regex.Pattern.compile(
                "\nGR -0\\.3604,0\\.0000\ngpu=\\(_TPC-gsp\\)\\*_GRX-\\(_RPX-\\d+\\)\nIP gpu\nMR 124508"
                + "\nGR -0\\.3604,0\\.3604\nMR 123031\nGR 0,0\n").matcher(text);
        int passes = 0;
        while (pass.find()) {
            passes++;
        }
        assertEquals(3, passes, text);
        assertEquals(List.of(), replay(text, haas));
        // under M24 each pass is one geared segment again
        StringBuilder square = new StringBuilder();
        assertTrue(compile(haas, "galil", CHAMFERED.replace("M08\n", "M08 M24\n"), square).ok());
        assertEquals(0, count(square.toString(), "GR -0.3604,0.3604"), square.toString());
        assertEquals(3, count(square.toString(), "\nIP gpu\nMR 123031\nGR 0,0\n"), square.toString());
    }

    @Test
    void e317E301AChamferTheGearingDoesNotCut() throws Exception {
        MachineProfile haas = ReplayTest.profile("haas");
        StringBuilder dmc = new StringBuilder();
        compile(haas, "galil", CHAMFERED, dmc);
        String good = dmc.toString();
        // the chamfer's X ratio 17% short: the pass ends 250 counts inside its settling move
        List<String> shallow = replay(good.replaceFirst("\nGR -0\\.3604,0\\.3604\n", "\nGR -0.3604,0.3000\n"), haas);
        assertEquals(1, shallow.size(), shallow.toString());
        assertTrue(shallow.get(0).startsWith("E317@"), shallow.toString());
        // the ratios changed without an MF/MR saying where: E301 at that GR
        List<String> nowhere = replay(good.replaceFirst("\nMR 124508\n", "\n"), haas);
        assertTrue(nowhere.size() >= 1 && nowhere.get(0).startsWith("E301@"), nowhere.toString());
    }

    @Test
    void conformanceHoldsAChamferedPassToItsCorner() {
        List<String> found = new java.util.ArrayList<>();
        Conformance c = new Conformance((code, line, args) -> found.add(code.id() + " " + args[0]), null, 1.5, 5);
        gcnc.ir.Point from = new gcnc.ir.Point(1000, 5000);
        gcnc.ir.Point corner = new gcnc.ir.Point(1000, 1500);
        gcnc.ir.Point end = new gcnc.ir.Point(2500, 0);
        gcnc.ir.Motion.Thread t = new gcnc.ir.Motion.Thread(from, end, 1500, 800, false, new gcnc.ir.Feed(1.5, 20000),
                corner);
        assertEquals(null, c.check(t, List.of(line(from, corner), line(corner, end)), gcnc.dmc.Source.line(6)));
        assertEquals(List.of(), found);
        // the ratios change 10 counts late along Z, and the chamfer still ends where it should
        gcnc.ir.Point late = new gcnc.ir.Point(1000, 1490);
        c.check(t, List.of(line(from, late), line(late, end)), gcnc.dmc.Source.line(6));
        assertEquals(List.of("E308 start of the thread's chamfer"), found);
        found.clear();
        // one straight geared move where the pass has a chamfer
        c.check(t, List.of(line(from, end)), gcnc.dmc.Source.line(6));
        assertEquals(List.of("E308 path (a chamfered thread pass is two straight geared moves)"), found);
    }

    private static Segment line(gcnc.ir.Point a, gcnc.ir.Point b) {
        return new Segment(a.x(), a.z(), b.x(), b.z(), false, 0, 0, 0, 0, 0, null);
    }

    @Test
    void e209TheThesisDialectCannotWriteAThread() throws Exception {
        StringBuilder dmc = new StringBuilder();
        Compiler.Result r = compile(ReplayTest.profile("fanuc"), "thesis", PROGRAM, dmc);
        // the first thread pass is refused; the compile stops emitting at its first backend error
        assertEquals("E209@6", ReplayTest.codes(r.diagnostics()).get(0));
        assertTrue(!r.ok());
    }

    @Test
    void aStartAngleWaitsThatMuchPastTheWholeRevolutionAndReplaysCleanAlone() throws Exception {
        MachineProfile fanuc = ReplayTest.profile("fanuc");
        StringBuilder dmc = new StringBuilder();
        // a two-start thread: the second start 180 degrees on (2048 of the encoder's 4096 counts)
        String program = PROGRAM.replace("G92 X23.2 Z-25. F1.5\nX22.8\nX22.5\n",
                "G92 X23.2 Z-25. Q0 F3.\nX22.8\nG92 X23.2 Z-25. Q180000 F3.\nX22.8\n");
        Compiler.Result r = compile(fanuc, "galil", program, dmc);
        assertTrue(r.ok(), r.diagnostics().sorted().toString());
        assertEquals(0, r.simulation().orElseThrow().findings());
        String text = dmc.toString();
        assertEquals(2, text.split("gsp=\\(@INT\\[_TPC/4096\\]\\+1\\)\\*4096\n", -1).length - 1, text);
        assertEquals(2, text.split("gsp=\\(@INT\\[_TPC/4096\\]\\+1\\)\\*4096\\+2048\n", -1).length - 1, text);
        assertEquals(List.of(), replay(text, fanuc));
        // under M04 the spindle counts down: the start is that many counts below the whole revolution
        StringBuilder reverse = new StringBuilder();
        assertTrue(compile(fanuc, "galil", program.replace("M03", "M04"), reverse).ok());
        assertTrue(reverse.toString().contains("gsp=(@INT[_TPC/4096]-1)*4096-2048\n"), reverse.toString());
        // a phase of a whole revolution or more is not what the backend writes: the replay refuses it
        List<String> whole = replay(text.replaceFirst("\\*4096\\+2048\n", "*4096+4096\n"), fanuc);
        assertTrue(whole.get(0).startsWith("E300@"), whole.toString());
    }
}
