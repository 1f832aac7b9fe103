package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.check.Checker;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.galil.Dialect;
import gcnc.dmc.Instruction;
import gcnc.ir.CheckedBlock;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.parse.BlockReader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The compiler runs the simulator on a thread of its own; that must change nothing but the time:
 * the same findings, in the same order, and the same summary as replaying block after block on one
 * thread, also when a program's blocks span many of the thread's batches.
 */
class SimulatorThreadTest {
    @Test
    void everySampleGivesWhatASingleThreadGives() throws Exception {
        for (String sample : List.of("arcs.nc", "bishop.nc", "dwell-css.nc", "home.nc", "offsets.nc", "turning.nc",
                "units.nc")) {
            String program = Files.readString(Path.of("samples", sample));
            for (String machine : List.of("generic", "thesis-2004")) {
                assertSame(program, machine, sample + " on " + machine);
            }
        }
    }

    /** 3000 blocks, every 50th pass dives into material no pass has cut: findings across many batches. */
    @Test
    void findingsOfALongProgramComeInOrderAcrossBatches() throws Exception {
        StringBuilder p = new StringBuilder("O1\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1200 M03\nG00 X50. Z2.\n");
        int line = 8;
        List<Integer> dives = new ArrayList<>();
        for (int pass = 0; pass < 600; pass++) {
            if (pass % 50 == 49) {
                p.append("G00 X30. Z").append(-100 - pass / 50).append(".\nG00 X50.\nG00 Z2.\n");
                dives.add(line);
                line += 3;
            } else {
                p.append("G00 X43.5 Z2.\nG01 Z-40. F120.\nG01 X50.\nG00 Z2.\nG00 X50.\n");
                line += 5;
            }
        }
        p.append("M05\nM30\n");
        List<Integer> found = new ArrayList<>();
        for (String f : assertSame(p.toString(), "generic", "generated")) {
            int at = Integer.parseInt(f.substring(f.indexOf('@') + 1, f.indexOf(':')));
            assertTrue(f.startsWith("E305@") && (dives.contains(at) || dives.contains(at - 1)), f);
            found.add(dives.contains(at) ? at : at - 1);
        }
        assertEquals(dives, found.stream().distinct().toList(), "one dive and its way out, each found");
    }

    @Test
    void aBugInTheSimulatorIsRethrownToTheCaller() throws Exception {
        SimulatorThread t = new SimulatorThread(profile("generic"), SimOptions.defaults());
        t.block(null, List.of());
        assertThrows(NullPointerException.class, t::finish);
    }

    /** Compiles on two threads and replays on one; both must agree. Returns the findings. */
    private static List<String> assertSame(String program, String machine, String what) throws Exception {
        Tables tables = Tables.builtIn();
        MachineProfile profile = profile(machine);
        Compiler.Result threaded = Compiler.compile(new StringReader(program),
                new Compiler.Settings(tables, profile, Dialect.Kind.GALIL, Optional.of(SimOptions.defaults())), l -> { });

        Diagnostics d = new Diagnostics();
        Simulator sim = new Simulator(profile, Compiler.withStockHeader(program.lines().findFirst().orElse(""), profile,
                SimOptions.defaults()), d);
        Dialect out = Dialect.create(Dialect.Kind.GALIL, profile, d);
        gcnc.plan.Planner planner = gcnc.plan.Planner.forProfile(profile);
        Checker checker = new Checker(tables, profile, d);
        List<Instruction> buf = new ArrayList<>();
        out.begin(buf::add);
        sim.begin(buf);
        BlockReader reader = new BlockReader(new StringReader(program), d);
        for (RawBlock b = reader.next(); b != null; b = reader.next()) {
            for (CheckedBlock cb : checker.check(b)) {
                if (d.errorCount() > sim.report().findings()) {
                    break; // as the compiler does: after a checker error, check only
                }
                buf.clear();
                planner.accept(cb, step -> out.lower(step, buf::add));
                sim.block(cb, buf, !planner.holding());
            }
        }
        checker.finish(reader.lines());
        boolean translated = d.errorCount() == sim.report().findings();
        if (translated) {
            buf.clear();
            planner.finish(step -> out.lower(step, buf::add));
            out.end(buf::add);
            sim.end(buf);
        }

        List<String> expected = render(d);
        // the compile also holds its DMC against the controller's memory (LimitCheck): E238 is not the simulator's
        assertEquals(expected, render(threaded.diagnostics()).stream().filter(x -> !x.startsWith("E238@")).toList(), what);
        assertEquals(translated ? Optional.of(sim.report()) : Optional.empty(), threaded.simulation(), what);
        return expected;
    }

    /**
     * The simulator's thread writes the DMC after replaying each block: the lines, their order and
     * the source map are those a compile without the simulator writes, for a long program across
     * many batches and for one with a backend error (lines written after it, not replayed).
     */
    @Test
    void theSimulatorsThreadWritesTheLinesACompileWithoutItWrites() throws Exception {
        StringBuilder p = new StringBuilder("O1\nG21 G90 G98\nG50 S2500\nM11\nT0101\nS1200 M03\nG00 X50. Z2.\n");
        for (int pass = 0; pass < 700; pass++) {
            p.append("G00 X").append(49 - pass % 40 * 0.5).append(" Z2.\nG01 Z-40. F120.\nG01 U1.\nG00 Z2.\n");
        }
        String clean = p + "M05\nM30\n";
        String late = p + "G01 Z-10. F0.001\nG00 Z2.\nM05\nM30\n"; // a feed under a count per second: E207
        for (String program : List.of(clean, late)) {
            List<String> withSim = new ArrayList<>();
            List<String> mapWithSim = new ArrayList<>();
            List<String> without = new ArrayList<>();
            List<String> mapWithout = new ArrayList<>();
            Compiler.Result r = Compiler.compile(new StringReader(program), new Compiler.Settings(Tables.builtIn(),
                    profile("generic"), Dialect.Kind.GALIL, Optional.of(SimOptions.defaults())),
                    new gcnc.dmc.SourceMap(mapWithSim::add).wrap(l -> withSim.add(l.text())));
            Compiler.compile(new StringReader(program), new Compiler.Settings(Tables.builtIn(), profile("generic"),
                    Dialect.Kind.GALIL, Optional.empty()), new gcnc.dmc.SourceMap(mapWithout::add).wrap(l -> without.add(l.text())));
            assertTrue(withSim.size() > 3000, "lines: " + withSim.size());
            assertEquals(without, withSim);
            assertEquals(mapWithout, mapWithSim);
            assertEquals(program == clean, r.ok(), r.diagnostics().sorted().toString());
        }
    }

    private static List<String> render(Diagnostics d) {
        List<String> out = new ArrayList<>();
        for (Diagnostic x : d.sorted()) {
            out.add(x.code().id() + "@" + x.span().line() + ":" + x.span().column() + " " + x.args());
        }
        return out;
    }

    private static MachineProfile profile(String name) throws Exception {
        return ProfileLoader.load(name, TableSource.builtIn(), Tables.builtIn());
    }
}
