package gcnc.galil;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.dmc.Command;
import gcnc.dmc.DmcReader;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * {@code AV} is relative (command reference AV: "measured from the start of a coordinated move sequence
 * or from the last AV command"; DMC-40x0 User Manual p.86, "After Relative Vector distance"): the
 * {@code AV}s of a sequence add up to its last trip point, which must lie on its path. Held over every
 * DMC file the tests keep (the goldens, the cycles' and the nose compensation's expected output) and
 * over a G96 facing pass with several speed steps and a coolant switch in one blended sequence.
 */
public class AfterVectorSumTest {
    /** A G96 facing pass on the fanuc profile: six feed blocks, M08 and M09 on the way (the review's css.nc). */
    public static final String FACING = "G21 G98\nG50 S2500\nT0101\nG96 S150 M03\nG00 X62. Z2.\nG01 Z0. F150.\n"
            + "G01 X50. F100.\nG01 X40. M08\nG01 X30.\nG01 X20.\nG01 X10. M09\nG01 X0.\nG00 Z5.\nM05\nM30\n";

    /** One sequence of a DMC program: its path length (VP lengths, CR radius × sweep) and its AVs in order. */
    record Sequence(double length, List<Long> avs) {
        long sum() {
            return avs.stream().mapToLong(Long::longValue).sum();
        }
    }

    /** The sequences of DMC text, as the controller measures them. */
    static List<Sequence> sequences(List<String> lines) {
        List<Sequence> out = new ArrayList<>();
        double[] cursor = {0, 0};
        double[] origin = null;
        double length = 0;
        List<Long> avs = null;
        for (String line : lines) {
            for (String st : DmcReader.statements(line)) {
                Command c = DmcReader.read(st, (code, args) -> { });
                if (c instanceof Command.VectorPosition vp) {
                    if (origin == null) {
                        origin = cursor.clone();
                        length = 0;
                        avs = new ArrayList<>();
                    }
                    double[] to = {origin[0] + vp.first(), origin[1] + vp.second()};
                    length += Math.hypot(to[0] - cursor[0], to[1] - cursor[1]);
                    cursor = to;
                } else if (c instanceof Command.CircularArc cr) {
                    if (origin == null) {
                        origin = cursor.clone();
                        length = 0;
                        avs = new ArrayList<>();
                    }
                    double[] g = Command.CircularArc.geometry(cursor[0], cursor[1], cr.radius().value(),
                            cr.start().value(), cr.sweep().value());
                    length += cr.radius().value() * Math.toRadians(Math.abs(cr.sweep().value()));
                    cursor = new double[] {g[2], g[3]};
                } else if (c instanceof Command.AfterVector av && avs != null) {
                    avs.add(av.counts());
                } else if (c instanceof Command.AwaitSequence && origin != null) {
                    out.add(new Sequence(length, avs));
                    cursor = new double[] {Math.rint(cursor[0]), Math.rint(cursor[1])};
                    origin = null;
                    avs = null;
                }
            }
        }
        return out;
    }

    @Test
    void theAvsOfEverySequenceTheTestsKeepAddUpToAPointOnItsPath() throws Exception {
        List<Path> files;
        try (Stream<Path> s = Files.walk(Path.of("src/test/resources"))) {
            files = s.filter(p -> p.toString().endsWith(".dmc") || p.toString().endsWith(".stream")).sorted().toList();
        }
        int several = 0;
        for (Path f : files) {
            for (Sequence q : sequences(Files.readAllLines(f))) {
                assertTrue(q.sum() <= q.length() + 1, f + ": AVs " + q.avs() + " add up past the path's " + q.length());
                several += q.avs().size() >= 2 ? 1 : 0;
            }
        }
        assertTrue(several >= 5, "sequences with two AVs or more: " + several);
    }

    @Test
    void aFacingPassWithSpeedStepsAndCoolantTripsEachStepFromTheLast() throws Exception {
        List<String> dmc = new ArrayList<>();
        gcnc.Compiler.Result r = gcnc.Compiler.compile(new StringReader(FACING), new gcnc.Compiler.Settings(
                gcnc.tables.Tables.builtIn(), gcnc.machine.ProfileLoader.load("fanuc",
                gcnc.tables.TableSource.builtIn(), gcnc.tables.Tables.builtIn()), Dialect.Kind.GALIL,
                java.util.Optional.of(gcnc.sim.SimOptions.defaults())), l -> dmc.add(l.text()));
        assertEquals(List.of(), r.diagnostics().sorted(), String.join("\n", dmc));
        List<Sequence> cut = sequences(dmc).stream().filter(q -> q.avs().size() > 1).toList();
        assertEquals(1, cut.size(), String.join("\n", dmc));
        Sequence q = cut.get(0);
        // the Z move to the face (1,000 counts), then 3,000 for X62 to X50 and 2,500 a step of 10 mm in diameter:
        // each speed step and M08/M09 at its block's start, measured from the trip point before
        assertEquals(List.of(1000L, 3000L, 2500L, 2500L, 2500L, 2500L), q.avs(), String.join("\n", dmc));
        assertEquals(14000, q.sum());
        assertTrue(q.sum() <= q.length(), q.sum() + " within " + q.length());
        assertEquals(16500, q.length(), 1e-9);
    }
}
