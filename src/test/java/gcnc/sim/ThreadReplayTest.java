package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Diagnostics;
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
 * and the thesis dialect, which has no gearing, refuses a thread (E209).
 */
class ThreadReplayTest {
    private static final String PROGRAM = "(80.00 24.00)\nG21 G99\nT0707\nG97 S800 M03\nG00 X30. Z5. M08\n"
            + "G92 X23.2 Z-25. F1.5\nX22.8\nX22.5\nG00 X100. Z100. M09\nM30\n";

    private static Compiler.Result compile(MachineProfile p, String dialect, String program, StringBuilder dmc)
            throws java.io.IOException {
        Compiler.Settings s = new Compiler.Settings(Tables.builtIn(), p, dialect, Optional.of(SimOptions.defaults()),
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
                coarse, "galil", Optional.empty()));
        assertEquals("E208@6", ReplayTest.codes(checked.diagnostics()).get(0));
    }

    @Test
    void e209TheThesisDialectCannotWriteAThread() throws Exception {
        StringBuilder dmc = new StringBuilder();
        Compiler.Result r = compile(ReplayTest.profile("fanuc"), "thesis", PROGRAM, dmc);
        // the first thread pass is refused; the compile stops emitting at its first backend error
        assertEquals("E209@6", ReplayTest.codes(r.diagnostics()).get(0));
        assertTrue(!r.ok());
    }
}
