package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gcnc.controller.InjectedFault;
import gcnc.controller.Model;
import gcnc.controller.VirtualController;
import gcnc.send.ProbeReport;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * {@code gcnc controller probe} against the virtual controller (issue 30 item 5): the report it writes,
 * a unit that answers against the reference (a fault) named by its row, the motion test's typed
 * confirmation, and {@code gcnc run --probe-report} refusing a contradicting unit until the profile
 * states it (galil.deviations).
 */
class ProbeCommandTest {
    private static Map<String, String> statuses(Path report) throws Exception {
        return ProbeReport.read(report).rows().stream()
                .collect(Collectors.toMap(r -> r.row().id(), r -> r.status().spelling()));
    }

    private static VirtualController vc(double speed, String... faults) throws Exception {
        List<InjectedFault> f = new java.util.ArrayList<>();
        for (String s : faults) {
            f.add(InjectedFault.parse(s));
        }
        return VirtualController.tcp(0, new VirtualController.Options(Model.standard(), speed, f, null));
    }

    @Test
    void overTcpTheVirtualControllerConfirmsWhatItIsAsked() throws Exception {
        Path report = Files.createTempDirectory("gcnc-probe").resolve("probe.json");
        try (VirtualController v = vc(20)) {
            RunOnControllerTest.Run r = RunOnControllerTest.gcnc("", "controller", "probe", "--machine", "haas",
                    "--tcp", "127.0.0.1:" + v.port(), "--report", report.toString());
            assertEquals(0, r.status(), r.all());
            Map<String, String> s = statuses(report);
            for (String id : List.of("rv-revision", "eo-no-echo-ethernet", "eo-serial-only", "cf-default-serial",
                    "cf-i-this-port", "tc1-code-text", "wt-not-in-terminal", "cs-clears-buffer", "lf-lr-readable",
                    "it-no-smoothing")) {
                assertEquals("confirmed", s.get(id), id + " in " + s);
            }
            assertEquals("not-checked", s.get("cs-from-zero"), "no motion asked for");
            assertEquals("not-checked", s.get("av-relative"));
            assertTrue(r.out().contains("report written to " + report), r.out());
        }
    }

    @Test
    void aUnitThatEchoesOverEthernetIsNamedByItsRow() throws Exception {
        Path report = Files.createTempDirectory("gcnc-probe").resolve("probe.json");
        try (VirtualController v = vc(20, "echo-ethernet=1")) {
            RunOnControllerTest.Run r = RunOnControllerTest.gcnc("", "controller", "probe", "--machine", "haas",
                    "--tcp", "127.0.0.1:" + v.port(), "--report", report.toString());
            assertEquals(1, r.status(), r.all());
            assertEquals("contradicted", statuses(report).get("eo-no-echo-ethernet"));
            assertTrue(r.err().contains("warning[E836]: the controller contradicts eo-no-echo-ethernet"), r.err());
        }
    }

    /** Garbage in the reply to ^R^V over Ethernet once threw NullPointerException; now the revision's row says so. */
    @Test
    void anUnreadableRevisionOverEthernetIsNamedByItsRow() throws Exception {
        Path report = Files.createTempDirectory("gcnc-probe").resolve("probe.json");
        try (VirtualController v = vc(20, "garbage-after=55")) { // the bytes before the reply to ^R^V
            RunOnControllerTest.Run r = RunOnControllerTest.gcnc("", "controller", "probe", "--machine", "haas",
                    "--tcp", "127.0.0.1:" + v.port(), "--report", report.toString());
            assertEquals(1, r.status(), r.all());
            assertFalse(r.all().contains("Exception"), r.all());
            Map<String, String> s = statuses(report);
            assertEquals("confirmed", s.get("eo-no-echo-ethernet"), s.toString());
            assertEquals("contradicted", s.get("rv-revision"), s.toString());
            assertTrue(r.err().contains("warning[E836]: the controller contradicts rv-revision"), r.err());
        }
    }

    /**
     * A link that fails while the probe asks is said in the probe's words (they once ended with a run's
     * "last block completed: none; executing: none"), and a refused command is not called a dropped
     * link: its TC1 says why. No report is written.
     */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "reject=28 | error[E844]: the controller refused the probe's 'SH XY' | (TC1: 1 Unrecognized command); no report was written",
        "reject=38 | note: the motion test had started (BGS): axis X may stand up to 1200 counts (3 x --distance) from where"
                + " it was, or still move; ST before anything else | error[E844]: the controller refused the probe's 'MG _CSS,_AVS,_BGS'",
        "disconnect-after=60 | error[E841]: the link to the controller closed while the probe asked | ; no report was written",
        "slow=1500 | error[E842]: the controller did not answer the probe's | in time (nothing); no report was written",
        "garbage-after=80 | error[E843]: the controller's reply to the probe's | is not Galil protocol"})
    void aLinkThatFailsWhileTheProbeAsksIsSaidInTheProbesWords(String fault, String says, String then) throws Exception {
        Path report = Files.createTempDirectory("gcnc-probe").resolve("probe.json");
        try (VirtualController v = vc(20, fault)) {
            // the motion test's commands (SH XY the 28th) are the ones the probe cannot do without
            RunOnControllerTest.Run r = RunOnControllerTest.gcnc("move\n", "controller", "probe", "--machine", "haas",
                    "--tcp", "127.0.0.1:" + v.port(), "--report", report.toString(), "--timeout", "500", "--allow-motion",
                    "--confirm-from-stdin", "--distance", "400", "--speed", "1000");
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains(says), r.err());
            assertTrue(r.err().contains(then), r.err());
            assertFalse(r.all().contains("last block completed"), r.all());
            assertFalse(Files.exists(report), "no report");
        }
    }

    @Test
    void theMotionTestNeedsTheTypedWordAndMovesNothingWithoutIt() throws Exception {
        Path report = Files.createTempDirectory("gcnc-probe").resolve("probe.json");
        try (VirtualController v = vc(20)) {
            RunOnControllerTest.Run piped = RunOnControllerTest.gcnc("move\n", "controller", "probe", "--machine", "haas",
                    "--tcp", "127.0.0.1:" + v.port(), "--report", report.toString(), "--allow-motion");
            assertEquals(2, piped.status(), piped.all());
            assertTrue(piped.err().contains("error[E834]"), piped.err());
            RunOnControllerTest.Run wrong = RunOnControllerTest.gcnc("yes\n", "controller", "probe", "--machine", "haas",
                    "--tcp", "127.0.0.1:" + v.port(), "--report", report.toString(), "--allow-motion", "--confirm-from-stdin");
            assertEquals(2, wrong.status(), wrong.all());
            assertTrue(wrong.err().contains("'yes' was typed"), wrong.err());
            assertFalse(Files.exists(report), "nothing asked, nothing written");
            assertEquals(0, v.controller().position(0));
        }
    }

    @Test
    void theMotionTestReadsCssAndAvsOnTheWay() throws Exception {
        Path report = Files.createTempDirectory("gcnc-probe").resolve("probe.json");
        boolean fromZero = firstSegmentReadsZero();
        try (VirtualController v = vc(1)) {
            RunOnControllerTest.Run r = RunOnControllerTest.gcnc("move\n", "controller", "probe", "--machine", "haas",
                    "--tcp", "127.0.0.1:" + v.port(), "--report", report.toString(), "--allow-motion", "--confirm-from-stdin",
                    "--distance", "400", "--speed", "1000");
            Map<String, String> s = statuses(report);
            assertEquals("confirmed", s.get("avs-from-start"), r.all());
            // the manual's _CS counts from 0 during the first segment; the probe says what this controller does
            assertEquals(fromZero ? "confirmed" : "contradicted", s.get("cs-from-zero"), r.all());
            assertEquals(fromZero ? 0 : 1, r.status(), r.all());
            assertEquals(0, v.controller().position(0), "three segments out, then back");
        }
    }

    /** What the virtual controller's _CSS reads during the first of three segments, asked directly. */
    private static boolean firstSegmentReadsZero() throws Exception {
        try (VirtualController v = VirtualController.tcp(0, new VirtualController.Options(Model.standard(), 0, List.of(), null))) {
            for (String c : List.of("SH XY", "VM XY", "VS 1000", "VP 400,0", "VP 800,0", "VP 1200,0", "VE", "BGS")) {
                assertEquals(":", RunOnControllerTest.tell(v, c), c);
            }
            v.controller().advance(0.2);
            return RunOnControllerTest.tell(v, "MG _CSS").startsWith(" 0.");
        }
    }

    @Test
    void aRunRefusesAUnitWhoseReportContradictsWhatItReliesOnUntilTheProfileStatesIt() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-probe");
        Path report = dir.resolve("probe.json");
        try (VirtualController v = vc(20)) {
            RunOnControllerTest.gcnc("", "controller", "probe", "--machine", "haas", "--tcp", "127.0.0.1:" + v.port(),
                    "--report", report.toString());
        }
        // the same report, with the unit's IT found burned in below 1 (smoothing the simulator did not verify)
        String text = Files.readString(report).replaceFirst("(\"id\": \"it-no-smoothing\",\\s*\"status\": \")confirmed",
                "$1contradicted");
        Files.writeString(report, text);
        Path part = RunOnControllerTest.part(RunOnControllerTest.PART);
        try (VirtualController v = RunOnControllerTest.fast(RunOnControllerTest.model("DMC-4040"))) {
            RunOnControllerTest.homed(v);
            RunOnControllerTest.Run r = RunOnControllerTest.gcnc("", "run", part.toString(), "--machine", "haas",
                    "--tcp", RunOnControllerTest.tcp(v), "--probe-report", report.toString());
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains("error[E832]") && r.err().contains("it-no-smoothing"), r.err());
            Path profile = dir.resolve("haas-smoothing.machine");
            Files.writeString(profile, Files.readString(Path.of("tables/machines/haas.machine"))
                    + "\ngalil.deviations = it-no-smoothing\n");
            RunOnControllerTest.Run ok = RunOnControllerTest.gcnc("", "run", part.toString(), "--machine", profile.toString(),
                    "--tcp", RunOnControllerTest.tcp(v), "--probe-report", report.toString(), "--poll", "20");
            assertEquals(0, ok.status(), ok.all());
        }
    }

    @Test
    void overAPtyTheFactoryEchoIsConfirmed() throws Exception {
        assumeTrue(gcnc.PtyPair.available(), "socat (setup.sh installs it)");
        Path report = Files.createTempDirectory("gcnc-probe").resolve("probe.json");
        try (gcnc.PtyPair pty = gcnc.PtyPair.open(Files.createTempDirectory("gcnc-pty"), "");
             VirtualController v = VirtualController.pty(pty.controller,
                     new VirtualController.Options(Model.standard(), 20, List.of(), null))) {
            RunOnControllerTest.Run r = RunOnControllerTest.gcnc("", "controller", "probe", "--machine", "haas",
                    "--port", pty.host.toString(), "--handshake", "none", "--report", report.toString());
            assertEquals(0, r.status(), r.all());
            Map<String, String> s = statuses(report);
            assertEquals("confirmed", s.get("eo-echo-serial"), s.toString());
            assertEquals("confirmed", s.get("eo-zero-stops-echo"), s.toString());
            assertEquals("confirmed", s.get("cf-i-this-port"), s.toString());
        }
    }
}
