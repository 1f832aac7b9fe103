package gcnc.galil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.check.Checker;
import gcnc.diag.Diagnostics;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Motion;
import gcnc.ir.Point;
import gcnc.ir.RawBlock;
import gcnc.machine.Axis;
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
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Issue 3's independent check on every sample program: the tests' own {@link PathReader}
 * accumulates each emitted sequence (VP from the sequence start, CR by radius, start angle and
 * sweep) and every sequence must end within one count of where its G-code motion ends.
 */
class SamplePathTest {
    private static final List<String[]> SAMPLES = List.of(
            new String[] {"bishop", "thesis-2004"}, new String[] {"turning", "generic"},
            new String[] {"arcs", "generic"}, new String[] {"units", "generic"},
            new String[] {"offsets", "generic"}, new String[] {"home", "generic"},
            new String[] {"dwell-css", "generic"});

    @TestFactory
    Stream<DynamicTest> everySequenceEndsWhereItsBlockEnds() {
        return SAMPLES.stream().map(s -> dynamicTest("samples/" + s[0] + ".nc on " + s[1], () -> check(s[0], s[1])));
    }

    private static void check(String sample, String machine) throws Exception {
        Tables tables = Tables.builtIn();
        MachineProfile p = ProfileLoader.load(machine, TableSource.builtIn(), tables);
        Diagnostics d = new Diagnostics();
        Checker checker = new Checker(tables, p, d);
        Dialect galil = Dialect.create(Dialect.Kind.GALIL, p, d);
        long[] at = galil(p, p.home());
        PathReader reader = new PathReader(at[0], at[1]);
        int sequences = 0;
        try (Reader in = Files.newBufferedReader(Path.of("samples", sample + ".nc"))) {
            BlockReader blocks = new BlockReader(in, d);
            for (RawBlock raw = blocks.next(); raw != null; raw = blocks.next()) {
                Optional<CheckedBlock> b = checker.check(raw).stream().findFirst();
                assertTrue(b.isPresent(), () -> sample + ": " + d.sorted());
                List<String> lines = new ArrayList<>();
                galil.block(b.get(), l -> lines.add(l.text()));
                List<long[]> ends = reader.read(lines);
                for (Motion m : b.get().motions()) {
                    Point to = m instanceof Motion.Linear l ? l.to() : m instanceof Motion.Arc a ? a.to() : null;
                    Point from = m instanceof Motion.Linear l ? l.from() : m instanceof Motion.Arc a ? a.from() : null;
                    if (to == null || from.distanceTo(to) < 0.5) {
                        continue; // dwells, and motions that do not move, make no sequence
                    }
                    long[] want = galil(p, to);
                    long[] got = ends.get(sequences++);
                    String where = sample + " line " + raw.line();
                    assertTrue(Math.abs(got[0] - want[0]) <= 1 && Math.abs(got[1] - want[1]) <= 1,
                            () -> where + ": sequence ends at " + got[0] + "," + got[1] + ", block at " + want[0] + "," + want[1]);
                }
            }
        }
        assertEquals(List.of(), d.sorted(), sample);
        assertTrue(sequences > 3, sample + " has motions");
    }

    /** Machine counts to Galil plane coordinates, worked out here from the profile alone. */
    private static long[] galil(MachineProfile p, Point machine) {
        long x = Math.round(p.x().sign() * machine.x());
        long z = Math.round(p.z().sign() * machine.z());
        return channel(p.x()) < channel(p.z()) ? new long[] {x, z} : new long[] {z, x};
    }

    private static int channel(Axis a) {
        return "XYZW".indexOf(a.galil()) >= 0 ? "XYZW".indexOf(a.galil()) : "ABCDEFGH".indexOf(a.galil());
    }
}
