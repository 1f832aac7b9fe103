package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.model;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import gcnc.controller.VirtualController;
import gcnc.machine.Plane;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * {@code gcnc run}'s estimated time is {@code gcnc compile}'s cycle time, and the blocks it names the
 * blocks the compile counted, on every sample and doc example, on each shipped lathe: the run takes its time from the simulator's clock as the compile
 * replayed the program (CompiledRun), never from a timing of its own (issue 32: bushing on haas was
 * 85.3 s against 102.2 s when the sender timed a thread pass as nothing).
 */
class RunTimeTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    /** Every .nc under samples/ (the shop project's sources aside: a Gradle build's own) and docs/examples/. */
    static List<Path> programs() throws IOException {
        List<Path> all = new ArrayList<>();
        for (String root : List.of("samples", "docs/examples")) {
            try (Stream<Path> s = Files.walk(Path.of(root))) {
                s.filter(p -> p.toString().endsWith(".nc") && !p.toString().contains("shop-project")).sorted()
                        .forEach(all::add);
            }
        }
        return all;
    }

    /** The DP that defines the axes at {@code machine}'s home, as its homing routine leaves them. */
    static String home(String machine) throws Exception {
        gcnc.machine.MachineProfile p = gcnc.Session.open(gcnc.Session.Options.defaults().withMachine(machine)).profile();
        Plane plane = Plane.of(p);
        double[] g = plane.galil(p.home().x(), p.home().z());
        String[] at = new String[plane.second() + 1];
        java.util.Arrays.fill(at, "");
        at[plane.first()] = Long.toString(Math.round(g[0]));
        at[plane.second()] = Long.toString(Math.round(g[1]));
        return "DP " + String.join(",", at);
    }

    /** The run's {@code started} event ({@code --format json}), which it must have printed. */
    static JsonNode started(RunOnControllerTest.Run r) throws IOException {
        JsonNode started = null;
        for (String l : r.out().split("\n")) {
            if (l.startsWith("{\"event\":\"started\"")) {
                started = JSON.readTree(l);
            }
        }
        assertTrue(started != null, r.all());
        return started;
    }

    @Test
    void theRunsEstimateIsTheCompilesCycleTimeOnEverySample() throws Exception {
        List<String> compared = new ArrayList<>();
        for (Path sample : programs()) {
            for (String machine : List.of("haas", "fanuc", "generic")) {
                // a copy of the program's folder (its called programs beside it): run writes FILE.dmc there
                Path dir = Files.createTempDirectory("gcnc-time");
                try (Stream<Path> s = Files.list(sample.getParent())) {
                    for (Path f : (Iterable<Path>) s.filter(Files::isRegularFile)::iterator) {
                        Files.copy(f, dir.resolve(f.getFileName()));
                    }
                }
                Path p = dir.resolve(sample.getFileName());
                RunOnControllerTest.Run c = gcnc("", "compile", p.toString(), "--machine", machine, "--format", "json", "-o",
                        dir.resolve("c.dmc").toString());
                JsonNode report = JSON.readTree(c.out());
                JsonNode sims = report.get("simulations");
                if (c.status() != 0 || sims == null || sims.isEmpty()) {
                    continue; // not clean on this machine (mistakes.nc): run refuses it before any estimate
                }
                double cycle = sims.get(0).get("cycleSeconds").asDouble();
                try (VirtualController vc = RunOnControllerTest.fast(model(
                        gcnc.Session.open(gcnc.Session.Options.defaults().withMachine(machine)).profile().galilModel().name()))) {
                    assertEquals(":", RunOnControllerTest.tell(vc, home(machine)), machine);
                    RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", machine, "--tcp", RunOnControllerTest.tcp(vc),
                            "--dry-run", "--format", "json");
                    JsonNode started = started(r);
                    assertEquals(cycle, started.get("seconds").asDouble(), 0.0015, sample + " on " + machine);
                    // and its blocks are the blocks the compile counted ("N blocks -> c.dmc")
                    java.util.regex.Matcher counted = java.util.regex.Pattern.compile(": ([0-9,]+) blocks? -> ").matcher(c.err());
                    assertTrue(counted.find(), c.err());
                    assertEquals(Long.parseLong(counted.group(1).replace(",", "")), started.get("blocks").asLong(),
                            sample + " on " + machine);
                    compared.add(sample.getFileName() + " " + machine);
                }
            }
        }
        // every sample, and the doc examples that are not made to show a finding, on some lathe; the
        // issue's bushing on haas among them
        java.util.Set<String> programs = new java.util.TreeSet<>();
        compared.forEach(c -> programs.add(c.substring(0, c.indexOf(' '))));
        java.util.Set<String> expected = new java.util.TreeSet<>(List.of("bushing.nc", "cam-chords.nc", "g65-grooves.nc"));
        try (Stream<Path> s = Files.list(Path.of("samples"))) {
            s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".nc")).forEach(expected::add);
        }
        assertEquals(expected, programs, compared.toString());
        assertTrue(compared.contains("bushing.nc haas"), compared.toString());
    }
}
