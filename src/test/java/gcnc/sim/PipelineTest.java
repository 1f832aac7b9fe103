package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
import java.io.Reader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The whole pipeline on the samples: parse, check, write DMC, replay it. */
class PipelineTest {
    /** Runs a sample through every stage; returns the simulator's findings as "E309@36". */
    static List<String> simulate(String sample, String machine, String dialect, SimOptions options,
                                 SimReport[] report) throws Exception {
        Tables tables = Tables.builtIn();
        MachineProfile profile = ProfileLoader.load(machine, TableSource.builtIn(), tables);
        Diagnostics d = new Diagnostics();
        String first = Files.readAllLines(Path.of("samples", sample)).get(0);
        Simulator sim = new Simulator(profile, gcnc.Compiler.withStockHeader(first, profile, options), d);
        Dialect out = Dialect.create(Dialect.Kind.of(dialect), profile, d);
        Checker checker = new Checker(tables, profile, d);
        List<Instruction> buf = new ArrayList<>();
        out.begin(buf::add);
        sim.begin(buf);
        int last = 1;
        try (Reader in = Files.newBufferedReader(Path.of("samples", sample))) {
            BlockReader reader = new BlockReader(in, d);
            for (RawBlock b = reader.next(); b != null; b = reader.next()) {
                last = b.line();
                for (CheckedBlock cb : checker.check(b)) {
                    buf.clear();
                    out.block(cb, buf::add);
                    sim.block(cb, buf);
                }
            }
        }
        checker.finish(last);
        buf.clear();
        out.end(buf::add);
        sim.end(buf);
        if (report != null) {
            report[0] = sim.report();
        }
        List<String> codes = new ArrayList<>();
        for (Diagnostic x : d.sorted()) {
            codes.add(x.code().id() + "@" + x.span().line());
        }
        return codes;
    }

    @Test
    void bishopInTheGalilDialectSimulatesClean() throws Exception {
        SimReport[] r = new SimReport[1];
        assertEquals(List.of(), simulate("bishop.nc", "thesis-2004", "galil", SimOptions.defaults(), r));
        assertEquals(57, r[0].sequences());
    }

    /** Table 5.2's three zero-sweep arcs: N240, N260 and N410, nothing else. */
    @Test
    void bishopInTheThesisDialectHasExactlyTheThreeZeroSweepArcs() throws Exception {
        List<String> src = Files.readAllLines(Path.of("samples", "bishop.nc"));
        List<String> expected = List.of("E309@" + (lineOf(src, "N240") + 1), "E309@" + (lineOf(src, "N260") + 1),
                "E309@" + (lineOf(src, "N410") + 1));
        assertEquals(expected, simulate("bishop.nc", "thesis-2004", "thesis", SimOptions.defaults(), null));
    }

    @Test
    void turningOnTheGenericLatheSimulatesClean() throws Exception {
        SimReport[] r = new SimReport[1];
        assertEquals(List.of(), simulate("turning.nc", "generic", "galil", SimOptions.defaults(), r));
        assertEquals(20, r[0].xMinMm(), 1e-9);  // X40. as a radius
        assertTrue(r[0].cycleSeconds() > 0);
    }

    /** Arcs in every quadrant, G28/G29, offsets and units: the machine does what each block says. */
    @Test
    void otherGenericSamplesSimulateClean() throws Exception {
        for (String sample : new String[] {"arcs.nc", "home.nc", "units.nc"}) {
            assertEquals(List.of(), simulate(sample, "generic", "galil", SimOptions.defaults(), null), sample);
        }
        // its T0303: the generic machine describes station 1 only, so station 3 is checked as the
        // default insert and the run says so, once (E321 at the T0303 block)
        assertEquals(List.of("E321@12"), simulate("offsets.nc", "generic", "galil", SimOptions.defaults(), null));
    }

    /**
     * samples/bishop.svg is this drawing, byte for byte (after a deliberate change of the drawing,
     * {@code gradle junitPlatformTest -PupdateGolden} writes it again: review it before committing).
     */
    @Test
    void bishopSvgIsTheCommittedSample() throws Exception {
        SimReport[] r = new SimReport[1];
        simulate("bishop.nc", "thesis-2004", "galil", SimOptions.defaults().withPath(), r);
        java.io.StringWriter w = new java.io.StringWriter();
        String number;
        try (java.io.Reader in = Files.newBufferedReader(Path.of("samples", "bishop.nc"))) {
            number = gcnc.ProgramNumber.of(in).orElse(null);
        }
        SvgWriter.write(r[0], "samples/bishop.nc", number, w, true);
        if (Boolean.getBoolean("gcnc.updateGolden")) {
            Files.writeString(Path.of("samples", "bishop.svg"), w.toString());
        }
        assertEquals(Files.readString(Path.of("samples", "bishop.svg")), w.toString());
    }

    private static int lineOf(List<String> src, String prefix) {
        for (int i = 0; i < src.size(); i++) {
            if (src.get(i).startsWith(prefix)) {
                return i;
            }
        }
        throw new AssertionError(prefix);
    }
}
