package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.cli.Main;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import picocli.CommandLine;

/**
 * A compiled sample downloaded to the virtual controller (over loopback TCP) and run with XQ: it runs to
 * its end, and the path in the controller's trace is the simulator's, count for count: where each sequence
 * ends, in the order they run, against {@code gcnc simulate --trace} on the same DMC.
 */
class ControllerPathTest {
    /** What the generic profile says of its axes (tables/machines/generic.machine). */
    private record Axes(char zGalil, int zSign, double zCounts, int xSign, double xCounts) {
        static Axes generic() throws IOException {
            String p = Files.readString(Path.of("tables/machines/generic.machine"));
            return new Axes(value(p, "z.galil").charAt(0), Integer.parseInt(value(p, "z.sign")),
                    Double.parseDouble(value(p, "z.counts_per_mm")), Integer.parseInt(value(p, "x.sign")),
                    Double.parseDouble(value(p, "x.counts_per_mm")));
        }

        private static String value(String profile, String key) {
            Matcher m = Pattern.compile("(?m)^" + Pattern.quote(key) + "\\s*=\\s*(\\S+)").matcher(profile);
            assertTrue(m.find(), key);
            return m.group(1);
        }

        /** Galil (first, second plane axis) counts of machine X (radius) and Z in mm. */
        long[] galil(double xMm, double zMm) {
            long z = Math.round(zMm * zCounts * zSign);
            long x = Math.round(xMm * xCounts * xSign);
            return zGalil == 'X' || zGalil == 'A' ? new long[] {z, x} : new long[] {x, z};
        }
    }

    private static String gcnc(String... args) {
        StringWriter out = new StringWriter();
        CommandLine cl = Main.commandLine(args);
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(new StringWriter(), true));
        assertEquals(0, cl.execute(args), String.join(" ", args));
        return out.toString();
    }

    private static final Pattern AFTER = Pattern.compile("^(\\S+)[^\\t]*\\t; L\\d+ X(-?[0-9.]+) Z(-?[0-9.]+) .*");

    @ParameterizedTest
    @ValueSource(strings = {"arcs", "bishop", "dwell-css", "offsets", "turning"})
    void aDownloadedProgramRunsToTheEndOnTheSimulatorsPath(String sample) throws Exception {
        Path dir = Files.createTempDirectory("gcnc-path");
        Path dmc = dir.resolve(sample + ".dmc");
        Path trace = dir.resolve("trace.txt");
        gcnc("compile", "samples/" + sample + ".nc", "-o", dmc.toString());
        Axes axes = Axes.generic();
        long[] home = null;
        List<String> simulated = new ArrayList<>();
        for (String line : gcnc("simulate", dmc.toString(), "--trace").lines().toList()) {
            Matcher m = AFTER.matcher(line);
            if (!m.matches()) {
                continue;
            }
            long[] g = axes.galil(Double.parseDouble(m.group(2)), Double.parseDouble(m.group(3)));
            if (home == null) {
                home = g;
            }
            if (m.group(1).equals("BGS")) {
                simulated.add(g[0] + "," + g[1]);
            }
        }
        try (Links l = Links.open(Links.Kind.TCP, Model.named("DMC-4030").orElseThrow(), 200, List.of(), trace)) {
            HostLink h = l.host;
            assertEquals(":", h.send("DP " + home[0] + "," + home[1]), "the machine stands at the profile's home");
            String program = Files.readString(dmc).replace("\n", "\r\n");
            assertEquals("::", h.download(program));
            assertEquals(program, h.upload());
            assertEquals(":", h.send("XQ #GCNC"));
            assertTrue(h.awaitThreadEnd(0, 20), "the program ran to its EN");
            assertEquals("0\r\n:", h.send("TC1"), "without an error");
        }
        List<String> ran = new ArrayList<>();
        for (String line : Files.readAllLines(trace)) {
            Matcher m = Pattern.compile("# end \\d+ at (-?\\d+,-?\\d+) .*").matcher(line);
            if (m.matches()) {
                ran.add(m.group(1));
            }
        }
        assertEquals(simulated, ran);
        assertTrue(ran.size() >= 3, ran.toString()); // blended: the approach, the cut and the retract at least
        Files.walk(dir).sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
    }
}
