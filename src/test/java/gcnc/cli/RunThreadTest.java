package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.homed;
import static gcnc.cli.RunOnControllerTest.model;
import static gcnc.cli.RunOnControllerTest.part;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gcnc.controller.VirtualController;
import gcnc.machine.MachineProfile;
import gcnc.machine.Plane;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * A threading program in a Haas shop's style (an M20×1.5 thread cut with G76 after its approach,
 * Haas M23's chamfered pull-out, on a 20 mm blank) sent with {@code gcnc run} to the virtual Galil
 * over loopback TCP: every pass geared to the simulated spindle encoder runs to its end, and the
 * executed path (where each sequence and each pass ends, in order) is the simulator's, count for count.
 */
class RunThreadTest {
    static final String THREAD = String.join("\n",
            "O2001 (M20X1.5 THREAD)",
            "(T1 OD THREAD 60 DEG)",
            "G21 G99",
            "G50 S2000",
            "T0101",
            "G97 S600 M03",
            "G00 X22. Z5.",
            "G00 X20.5 Z3.",
            "M23",
            "G76 X18.16 Z-20. K0.92 D0.35 F1.5 A60",
            "G00 X40. Z20.",
            "M05",
            "M30", "");

    /** The same thread cut with G92 (one block a pass) after a spring pass, then a G32 pass of its own (Fanuc style). */
    static final String G92_G32 = String.join("\n",
            "O2002 (G92 AND G32 THREADS)",
            "G21 G99",
            "G50 S2000",
            "T0101",
            "G97 S500 M03",
            "G00 X22. Z5.",
            "G92 X19.5 Z-15. F1.5",
            "X19.2",
            "X19.0",
            "X18.5",
            "G00 X22. Z2.",
            "G32 Z-10. F1.5",
            "G00 X40.",
            "Z20.",
            "M05",
            "M30", "");

    private static final Pattern SIMULATED = Pattern.compile("^(BGS|BG XY)\\t; L\\d+ X(-?[0-9.]+) Z(-?[0-9.]+) .*");
    private static final Pattern RAN = Pattern.compile("# (?:end|pass) \\d+ at (-?\\d+,-?\\d+) .*");

    @ParameterizedTest
    @ValueSource(strings = {"G76", "G92 G32"})
    void aThreadingProgramRunsToTheEndOnTheSimulatorsPathOverTcp(String cycle) throws Exception {
        Path p = part(cycle.equals("G76") ? THREAD : G92_G32);
        Path trace = p.resolveSibling("run.trace");
        try (VirtualController vc = VirtualController.tcp(0,
                new VirtualController.Options(model("DMC-4040"), 20, List.of(), trace))) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--stock", "20,50",
                    "--tcp", "127.0.0.1:" + vc.port(), "--poll", "20");
            assertEquals(0, r.status(), r.all());
            assertTrue(r.out().contains("ran to the end"), r.out());
        }
        assertOnTheSimulatorsPath(p, trace);
    }

    @Test
    void aThreadingProgramRunsToTheEndOnTheSimulatorsPathOverAPty() throws Exception {
        assumeTrue(gcnc.PtyPair.available(), "socat (setup.sh installs it)");
        Path p = part(THREAD);
        Path trace = p.resolveSibling("run.trace");
        try (gcnc.PtyPair pty = gcnc.PtyPair.open(Files.createTempDirectory("gcnc-pty"), "")) {
            Path b = pty.host;
            try (VirtualController vc = VirtualController.pty(pty.controller,
                    new VirtualController.Options(model("DMC-4040"), 20, List.of(), trace))) {
                RunOnControllerTest.definePosition(b, RunOnControllerTest.home());
                RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--stock", "20,50",
                        "--port", b.toString(), "--poll", "20");
                assertEquals(0, r.status(), r.all());
            }
        }
        assertOnTheSimulatorsPath(p, trace);
    }

    /** Where each sequence and each pass ended on the controller, in order, against gcnc simulate --trace. */
    private static void assertOnTheSimulatorsPath(Path p, Path trace) throws Exception {
        // the simulator's replay of the same DMC: where each sequence (BGS) and each pass (BG XY) leaves the axes
        MachineProfile haas = RunOnControllerTest.haas();
        Plane plane = Plane.of(haas);
        List<String> simulated = new ArrayList<>();
        for (String line : gcnc("", "simulate", p.resolveSibling("part.dmc").toString(), "--machine", "haas", "--trace")
                .out().lines().toList()) {
            Matcher m = SIMULATED.matcher(line);
            if (m.matches()) {
                double[] g = plane.galil(Double.parseDouble(m.group(2)) * haas.x().countsPerMm(),
                        Double.parseDouble(m.group(3)) * haas.z().countsPerMm());
                simulated.add(Math.round(g[0]) + "," + Math.round(g[1]));
            }
        }
        List<String> ran = new ArrayList<>();
        int passes = 0;
        for (String line : Files.readAllLines(trace)) {
            Matcher m = RAN.matcher(line);
            if (m.matches()) {
                ran.add(m.group(1));
                passes += line.startsWith("# pass") ? 1 : 0;
            }
        }
        assertEquals(simulated, ran);
        assertTrue(passes >= 5, "G76's passes, each geared: " + passes);
    }
}
