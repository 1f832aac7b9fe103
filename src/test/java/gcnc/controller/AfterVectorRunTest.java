package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.galil.AfterVectorSumTest;
import gcnc.galil.Dialect;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * The G96 facing pass with its speed steps and a coolant switch in one blended sequence
 * ({@link AfterVectorSumTest#FACING}), compiled, downloaded to the virtual controller and run: every
 * {@code AV} trips at the start of its block, the trace's trip point being the joint of the segments
 * there (AV measures "from the last AV command", command reference AV), and none waits in vain.
 */
class AfterVectorRunTest {
    private static final Pattern TRIP = Pattern.compile("# av (\\d+) tripped at (\\d+) of path \\(trip point (\\d+)\\) .*");
    private static final Pattern END = Pattern.compile("# \\w+ \\d+ at (-?\\d+),(-?\\d+) .*");

    @Test
    void everySpeedStepAndTheCoolantTripAtTheirBlocksStart() throws Exception {
        List<String> dmc = new ArrayList<>();
        gcnc.Compiler.Result r = gcnc.Compiler.compile(new StringReader(AfterVectorSumTest.FACING), new gcnc.Compiler.Settings(
                gcnc.tables.Tables.builtIn(), gcnc.machine.ProfileLoader.load("fanuc", gcnc.tables.TableSource.builtIn(),
                gcnc.tables.Tables.builtIn()), Dialect.Kind.GALIL, java.util.Optional.of(gcnc.sim.SimOptions.defaults())),
                l -> dmc.add(l.text()));
        assertEquals(List.of(), r.diagnostics().sorted());
        String program = String.join("\r\n", dmc) + "\r\n";
        Matcher home = Pattern.compile("_TPX-(\\d+)\\]>\\d+\\r\\nJP #NOHOME,@ABS\\[_TPY-(\\d+)").matcher(program);
        assertTrue(home.find(), program);
        Path trace = Files.createTempDirectory("gcnc-av").resolve("trace.txt");
        try (Links l = Links.open(Links.Kind.TCP, Model.named("DMC-4040").orElseThrow(), 200, List.of(), trace)) {
            HostLink h = l.host;
            assertEquals(":", h.send("DP " + home.group(1) + "," + home.group(2)), "the machine stands at home");
            assertEquals("::", h.download(program));
            assertEquals(":", h.send("XQ #GCNC"));
            assertTrue(h.awaitThreadEnd(0, 30), "the program ran to its EN: no AV waited in vain");
            assertEquals("0\r\n:", h.send("TC1"), "without an error");
        }
        // the joints of each sequence's segments, counts of path from its start, as the trace has them
        List<String> lines = Files.readAllLines(trace);
        List<Long> trips = new ArrayList<>();
        List<List<Double>> sequences = new ArrayList<>();
        List<Double> joints = new ArrayList<>();
        double[] at = {Double.parseDouble(home.group(1)), Double.parseDouble(home.group(2))};
        double along = 0;
        for (String line : lines) {
            Matcher e = END.matcher(line);
            Matcher t = TRIP.matcher(line);
            if (t.matches()) {
                long trip = Long.parseLong(t.group(3));
                long ran = Long.parseLong(t.group(2));
                assertTrue(ran >= trip && ran <= trip + 2, "the thread goes on within a sample of its trip point: " + line);
                trips.add(trip);
            } else if (e.matches()) {
                at = new double[] {Double.parseDouble(e.group(1)), Double.parseDouble(e.group(2))};
                sequences.add(joints);
                joints = new ArrayList<>();
                along = 0;
            } else if (!line.startsWith("#")) {
                String[] f = line.split(" ");
                double[] to = {Double.parseDouble(f[3]), Double.parseDouble(f[4])};
                along += Math.hypot(to[0] - at[0], to[1] - at[1]);
                joints.add(along);
                at = to;
            }
        }
        assertEquals(List.of(1000L, 4000L, 6500L, 9000L, 11500L, 14000L), trips, String.join("\n", lines));
        // each at a joint: the start of its block (the Z move to the face, then the facing steps)
        List<List<Double>> cut = sequences.stream().filter(q -> q.size() == 7).toList();
        assertEquals(1, cut.size(), String.join("\n", lines));
        assertEquals(List.of(1000.0, 4000.0, 6500.0, 9000.0, 11500.0, 14000.0, 16500.0), cut.get(0),
                String.join("\n", lines));
    }
}
