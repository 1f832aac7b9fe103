package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import gcnc.Session;
import gcnc.controller.InjectedFault;
import gcnc.controller.Model;
import gcnc.controller.VirtualController;
import gcnc.machine.MachineProfile;
import gcnc.machine.Plane;
import gcnc.send.DmcProgram;
import gcnc.send.MapReader;
import gcnc.sim.Sequence;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * {@code gcnc run} against the virtual Galil ({@code gcnc controller --virtual}, branch vc) over
 * loopback TCP and over a socat pty pair: a clean run, refusals, and the faults of issue 20 with
 * the exit status, the diagnostic and the blocks each names; a stopped run resumed to the end.
 */
class RunOnControllerTest {
    /** A Haas-style part: a facing approach, a turn, a G02 corner, a face-out and a retract (6 motions). */
    static final String PART = String.join("\n",
            "O1002 (RUN TEST PART)",
            "G21 G99",
            "G50 S2500",
            "T0101",
            "G97 S1200 M03",
            "G00 X42. Z2.",
            "G01 X40. F0.2",
            "G01 Z-30.",
            "G02 X46. Z-33. R3.",
            "G01 X50.",
            "G00 X60. Z5.",
            "M05",
            "M30", "");

    record Run(int status, String out, String err) {
        String all() {
            return out + err;
        }
    }

    static Run gcnc(String input, String... args) {
        InputStream in = new ByteArrayInputStream(input.getBytes(StandardCharsets.UTF_8));
        CommandLine cl = Main.commandLine(new Main.Streams(in, System.out), gcnc.tables.ErrorMessages.Lang.EN, args);
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(err, true));
        int status = cl.execute(args);
        return new Run(status, out.toString(), err.toString());
    }

    static Path part(String text) throws IOException {
        Path p = Files.createTempDirectory("gcnc-run").resolve("part.nc");
        Files.writeString(p, text);
        return p;
    }

    static MachineProfile haas() throws Exception {
        return Session.open(Session.Options.defaults().withMachine("haas")).profile();
    }

    /** The haas profile's home in Galil counts of the plane: where the program was verified to start. */
    static long[] home() throws Exception {
        MachineProfile p = haas();
        double[] g = Plane.of(p).galil(p.home().x(), p.home().z());
        return new long[] {Math.round(g[0]), Math.round(g[1])};
    }

    /** A model of tables/galil_models.csv as the virtual controller plays it. */
    static Model model(String name) {
        return Model.named(name).orElseThrow();
    }

    /**
     * How much faster than real time the controller of a test runs whose faults, operator keys or stall
     * watch happen in real time: the part's motion then lasts about 2.6 s, long enough for them.
     */
    static final double SPEED = 5;
    /**
     * The speed of a run that nothing interrupts in real time (to the end, or step by step): its path,
     * end and events do not depend on the clock, and the host still polls it some thirty times.
     */
    static final double FAST = 20;

    static VirtualController controller(Model model, String... faults) throws IOException {
        return traced(model, null, faults);
    }

    /** A virtual controller at {@link #FAST} speed (no faults, no trace). */
    static VirtualController fast(Model model) throws IOException {
        return VirtualController.tcp(0, new VirtualController.Options(model, FAST, List.of(), null));
    }

    /** A virtual controller that writes the end of every segment it executes to {@code trace}. */
    static VirtualController traced(Model model, Path trace, String... faults) throws IOException {
        return traced(SPEED, model, trace, faults);
    }

    static VirtualController traced(double speed, Model model, Path trace, String... faults) throws IOException {
        List<InjectedFault> f = new ArrayList<>();
        for (String s : faults) {
            f.add(InjectedFault.parse(s));
        }
        return VirtualController.tcp(0, new VirtualController.Options(model, speed, f, trace));
    }

    /** {@link #uninterruptedPath}, run once for the test JVM. */
    private static List<String> uninterrupted;

    /**
     * The segment ends of {@link #PART} run to the end without a stop on the DMC-4040 (program form),
     * homed: what a stopped and resumed run must repeat. The ends are the segments' programmed end
     * points, whatever the clock, so the run is made once, at {@link #FAST} speed, for every test
     * that compares with it (this class's and RunBlendedTest's).
     */
    static synchronized List<String> uninterruptedPath() throws Exception {
        if (uninterrupted == null) {
            Path p = part(PART);
            Path trace = p.resolveSibling("whole.trace");
            try (VirtualController vc = traced(FAST, model("DMC-4040"), trace)) {
                homed(vc);
                Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc));
                assertEquals(0, r.status(), r.all());
            }
            uninterrupted = List.copyOf(path(trace));
        }
        return uninterrupted;
    }

    /** The end points of the segments a controller executed, in order ("END1 END2" of its trace). */
    static List<String> path(Path trace) throws IOException {
        List<String> ends = new ArrayList<>();
        for (String l : Files.readAllLines(trace)) {
            if (!l.startsWith("#") && !l.isBlank()) {
                String[] f = l.split(" ");
                ends.add(f[3] + " " + f[4]);
            }
        }
        return ends;
    }

    /** One command to the controller on a connection of its own, its reply. */
    static String tell(VirtualController vc, String command) throws IOException {
        try (Socket s = new Socket("127.0.0.1", vc.port())) {
            s.setSoTimeout(3000);
            s.getOutputStream().write((command + "\r").getBytes(StandardCharsets.ISO_8859_1));
            StringBuilder b = new StringBuilder();
            InputStream in = s.getInputStream();
            for (int c = in.read(); c >= 0; c = in.read()) {
                b.append((char) c);
                if ((c == ':' || c == '?') && (b.length() == 1 || b.charAt(b.length() - 2) == '\n')) {
                    break;
                }
            }
            return b.toString();
        }
    }

    /** The controller's axes defined at home (DP), as the machine's homing routine leaves them. */
    static void homed(VirtualController vc) throws Exception {
        long[] h = home();
        assertEquals(":", tell(vc, "DP " + h[0] + "," + h[1]));
    }

    static long[] axes(VirtualController vc) {
        return new long[] {vc.controller().position(0), vc.controller().position(1)};
    }

    /** Where the compiled program's last motion ends, Galil counts. */
    static long[] programEnd(Path part) throws Exception {
        Path dmc = part.resolveSibling("part.dmc");
        DmcProgram p = DmcProgram.read(Files.readAllLines(dmc), MapReader.read(Files.newBufferedReader(
                part.resolveSibling("part.dmc.map"))), haas());
        List<Sequence> s = p.sequences();
        double[] e = s.get(s.size() - 1).end();
        return new long[] {Math.round(e[0]), Math.round(e[1])};
    }

    static String tcp(VirtualController vc) {
        return "127.0.0.1:" + vc.port();
    }

    @Test
    void aProgramThatIsNotCleanIsRefusedAndNothingIsSent() throws Exception {
        // turning without closing the chuck first (Haas M10): E038, so not one byte may reach the controller
        Path p = part(PART.replace("G00 X42. Z2.", "M11\nG00 X42. Z2."));
        try (ServerSocket server = new ServerSocket(0)) {
            server.setSoTimeout(300);
            Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", "127.0.0.1:" + server.getLocalPort());
            assertEquals(1, r.status(), r.all());
            assertTrue(r.err().contains("error[E038]"), r.err());
            assertTrue(r.err().contains("nothing was sent"), r.err());
            assertThrowsTimeout(server);
        }
    }

    @Test
    void theRunSpeaksSpanish() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = controller(model("DMC-4040"), "reject=45")) {
            homed(vc);
            Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--lang", "es", "--poll", "50");
            assertEquals(3, r.status(), r.all());
            assertTrue(r.err().contains("error[E820]: el controlador rechazó"), r.err());
            assertTrue(r.out().contains("detenido: último bloque terminado: línea "), r.out());
            assertTrue(r.out().contains("para reanudar: gcnc run "), r.out());
        }
    }

    private static void assertThrowsTimeout(ServerSocket server) throws IOException {
        try (Socket s = server.accept()) {
            throw new AssertionError("gcnc connected to the controller for a program with errors");
        } catch (java.net.SocketTimeoutException expected) {
            // nobody connected
        }
    }

    @Test
    void runsToTheEndOverTcp() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = fast(model("DMC-4040"))) {
            homed(vc);
            Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--poll", "20");
            assertEquals(0, r.status(), r.all());
            int lines = Files.readAllLines(p.resolveSibling("part.dmc")).size();
            assertTrue(r.out().contains("downloaded " + lines + " lines (DL), read back identical (UL)"), r.out());
            assertTrue(r.out().contains("ran to the end"), r.out());
            // the motors are off at power-up: a warning, the program's SH turns them on
            assertTrue(r.err().contains("warning[E829]"), r.err());
            assertArrayEquals(programEnd(p), axes(vc));
            assertEquals(String.join("\n", Files.readAllLines(p.resolveSibling("part.dmc"))) + "\n",
                    vc.controller().programText().replace("\r\n", "\n").replace("\r", "\n"));
        }
    }

    private static void assertArrayEquals(long[] expected, long[] actual) {
        assertEquals(Arrays.toString(expected), Arrays.toString(actual));
    }

    @Test
    void theJsonEventStreamIsOneObjectPerLine() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = fast(model("DMC-4040"))) {
            homed(vc);
            Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--format", "json", "--poll", "20");
            assertEquals(0, r.status(), r.all());
            List<String> events = new ArrayList<>();
            for (String line : r.out().split("\n")) {
                com.google.gson.JsonObject o = com.google.gson.JsonParser.parseString(line).getAsJsonObject();
                events.add(o.get("event").getAsString());
                if (o.get("event").getAsString().equals("status")) {
                    assertTrue(o.has("line") && o.has("program") && o.has("progress") && o.has("secondsLeft"), line);
                }
            }
            assertEquals("connected", events.get(0));
            assertEquals("preflight", events.get(1));
            assertTrue(events.contains("block") && events.contains("status"), events.toString());
            assertEquals("finished", events.get(events.size() - 1));
        }
    }

    @Test
    void runsToTheEndOverAPtyPair() throws Exception {
        assumeTrue(gcnc.PtyPair.available(), "socat (setup.sh installs it)");
        try (gcnc.PtyPair pty = gcnc.PtyPair.open(Files.createTempDirectory("gcnc-pty"), "")) {
            Path a = pty.controller;
            Path b = pty.host;
            Path p = part(PART);
            try (VirtualController vc = VirtualController.pty(a, new VirtualController.Options(model("DMC-4040"), FAST, List.of(), null))) {
                Run dp = gcnc("", "run", p.toString(), "--machine", "haas", "--port", b.toString(), "--dry-run");
                // not homed yet: refused before anything moves, and the link worked (pre-flight read the axes)
                assertEquals(2, dp.status(), dp.all());
                assertTrue(dp.err().contains("error[E826]"), dp.err());
                definePosition(b, home());
                Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--port", b.toString(), "--poll", "20");
                assertEquals(0, r.status(), r.all());
                assertTrue(r.out().contains("ran to the end"), r.out());
                assertArrayEquals(programEnd(p), axes(vc));
            }
        }
    }

    /**
     * What an operator's terminal left on the serial line (commands sent, their echoes and replies never
     * read) is not taken for the run's replies: the pre-flight once read the stale ':' as the answer to
     * its own commands and stopped with E823 ("'DMC4040 Rev 1.2d' where only : or ? belongs").
     */
    @Test
    void whatATerminalLeftOnTheSerialLineIsNotTakenForAReply() throws Exception {
        assumeTrue(gcnc.PtyPair.available(), "socat (setup.sh installs it)");
        try (gcnc.PtyPair pty = gcnc.PtyPair.open(Files.createTempDirectory("gcnc-pty"), "")) {
            Path p = part(PART);
            try (VirtualController vc = VirtualController.pty(pty.controller,
                    new VirtualController.Options(model("DMC-4040"), FAST, List.of(), null))) {
                long[] h = home();
                try (var io = java.nio.channels.FileChannel.open(pty.host, java.nio.file.StandardOpenOption.WRITE)) {
                    // echoed until EO 0, then ':' each: nothing reads them
                    io.write(java.nio.ByteBuffer.wrap(("EO 0\rDP " + h[0] + "," + h[1] + "\rMG 1\r")
                            .getBytes(StandardCharsets.ISO_8859_1)));
                }
                Thread.sleep(500);
                Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--port", pty.host.toString(), "--poll", "20");
                assertEquals(0, r.status(), r.all());
                assertTrue(r.out().contains("ran to the end"), r.out());
                assertArrayEquals(programEnd(p), axes(vc));
            }
        }
    }

    /**
     * DP over the pty, as an operator's terminal would send it; the virtual controller echoes it, as a
     * factory unit does until a host sends EO 0 (COMALL EO); after a gcnc run has sent it, no echo.
     */
    static void definePosition(Path host, long[] h) throws Exception {
        try (var io = java.nio.channels.FileChannel.open(host, java.nio.file.StandardOpenOption.READ,
                java.nio.file.StandardOpenOption.WRITE)) {
            String dp = "DP " + h[0] + "," + h[1] + "\r";
            io.write(java.nio.ByteBuffer.wrap(dp.getBytes(StandardCharsets.ISO_8859_1)));
            java.nio.ByteBuffer reply = java.nio.ByteBuffer.allocate(64);
            long until = System.currentTimeMillis() + 3000;
            while ((reply.position() == 0 || reply.get(reply.position() - 1) != ':') && System.currentTimeMillis() < until) {
                io.read(reply);
            }
            String got = new String(reply.array(), 0, reply.position(), StandardCharsets.ISO_8859_1);
            assertTrue(got.equals(dp + ":") || got.equals(":"), "the echo (until EO 0), then the colon: " + got);
        }
    }

    @Test
    void aPortThatDoesNotExistIsExit2() throws Exception {
        Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--port", "/dev/ttyUSB-gcnc-none");
        assertEquals(2, r.status(), r.all());
        assertTrue(r.err().contains("error[E815]: the serial port /dev/ttyUSB-gcnc-none does not exist"), r.err());
    }

    @Test
    void aPortHeldByAnotherProgramIsExit2() throws Exception {
        assumeTrue(gcnc.PtyPair.available() && Files.isExecutable(Path.of("/usr/bin/flock")));
        Process holder = null;
        try (gcnc.PtyPair pty = gcnc.PtyPair.open(Files.createTempDirectory("gcnc-pty"), "")) {
            Path b = pty.host;
            // another program holds the port as serial programs do (an exclusive lock on the device)
            holder = new ProcessBuilder("flock", "-n", b.toString(), "sleep", "30").start();
            Thread.sleep(300);
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--port", b.toString());
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains("error[E816]"), r.err());
            assertTrue(r.err().contains("another program holds it"), r.err());
        } finally {
            if (holder != null) {
                holder.descendants().forEach(ProcessHandle::destroy);
                holder.destroy();
            }
        }
    }

    @Test
    void noControllerAtTheAddressIsExit2() throws Exception {
        int port;
        try (ServerSocket s = new ServerSocket(0)) {
            port = s.getLocalPort();
        }
        Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", "127.0.0.1:" + port);
        assertEquals(2, r.status(), r.all());
        assertTrue(r.err().contains("error[E817]: no connection to the controller at 127.0.0.1:" + port), r.err());
    }

    @Test
    void aControllerOfAnotherModelIsExit2AndNothingMoves() throws Exception {
        try (VirtualController vc = controller(model("DMC-4020"))) {
            homed(vc);
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", tcp(vc));
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains("error[E818]: the controller is a DMC4020 Rev 1.2d: the machine profile haas is for a DMC-4040"),
                    r.err());
            assertArrayEquals(home(), axes(vc));
        }
    }

    /**
     * The profile counts on firmware 1.2a's 4,000 program lines (galil.firmware), so the program compiles;
     * the controller says Rev 1.0h (2,000 lines): refused before a byte of the program is sent.
     */
    @Test
    void aProgramLargerThanTheControllersMemoryIsExit2() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-small");
        Path machine = dir.resolve("haas-12a.machine");
        Files.writeString(machine, Files.readString(Path.of("tables/machines/haas.machine"))
                .replace("galil.model = DMC-4040", "galil.model = DMC-4040\ngalil.firmware = 1.2a"));
        StringBuilder b = new StringBuilder("O1003\nG21 G99\nG50 S2500\nT0101\nG97 S1200 M03\nG00 X42. Z2.\n");
        for (int i = 0; i < 1100; i++) { // a packed line a block: some 2,200 lines, for a 4,000-line memory
            b.append("G01 X40. F0.2\nG00 X42.\n");
        }
        b.append("M05\nM30\n");
        long[] h = home();
        try (ServerSocket server = new ServerSocket(0)) {
            List<String> downloaded = new ArrayList<>();
            Thread t = new Thread(() -> script(server, h, "DMC4040 Rev 1.0h", downloaded));
            t.setDaemon(true);
            t.start();
            Run r = gcnc("", "run", part(b.toString()).toString(), "--machine", machine.toString(), "--tcp",
                    "127.0.0.1:" + server.getLocalPort());
            assertEquals(2, r.status(), r.all());
            java.util.regex.Matcher m = java.util.regex.Pattern.compile(
                    "error\\[E819\\]: the program needs (\\d+) program lines and the controller has 2000 \\(DMC4040 Rev 1.0h\\)")
                    .matcher(r.err());
            assertTrue(m.find(), r.err());
            assertTrue(Integer.parseInt(m.group(1)) > 2000 && Integer.parseInt(m.group(1)) <= 4000, m.group());
            assertTrue(downloaded.isEmpty(), downloaded.toString());
        }
    }

    @Test
    void axesNotAtHomeAreExit2() throws Exception {
        try (VirtualController vc = controller(model("DMC-4040"))) {
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", tcp(vc));
            assertEquals(2, r.status(), r.all());
            long[] h = home();
            // in program terms first (the first motion's frame), the counts after
            assertTrue(java.util.regex.Pattern.compile("error\\[E826\\]: the axes are at X-?\\d+\\.\\d{3} Z-?\\d+\\.\\d{3} "
                    + "\\(Galil counts 0,0\\) but the program was verified from home at X-?\\d+\\.\\d{3} Z-?\\d+\\.\\d{3} "
                    + "\\(Galil counts " + h[0] + "," + h[1] + "\\)").matcher(r.err()).find(), r.err());
        }
    }

    @Test
    void aProgramStillRunningOnTheControllerIsNotCutOff() throws Exception {
        try (VirtualController vc = controller(model("DMC-4040"))) {
            homed(vc);
            try (Socket s = new Socket("127.0.0.1", vc.port())) {
                s.getOutputStream().write("DL\r#BUSY\rWT 20000\rEN\r\\XQ #BUSY,0\r".getBytes(StandardCharsets.ISO_8859_1));
                Thread.sleep(300);
            }
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", tcp(vc));
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains("error[E825]: the controller cannot run the program: a program is running in thread 0"), r.err());
        }
    }

    @Test
    void theDryRunDoesEverythingButMotion() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = controller(model("DMC-4040"))) {
            homed(vc);
            Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--dry-run");
            assertEquals(0, r.status(), r.all());
            assertTrue(r.out().contains("read back identical"), r.out());
            assertTrue(r.out().contains("nothing moved"), r.out());
            assertArrayEquals(home(), axes(vc));
        }
    }

    /**
     * A run stopped by a fault: exit 3, the blocks named, and the resume command that finishes the part
     * along the same path, segment end for segment end, as a run that was never stopped.
     */
    @Test
    void aRejectedCommandStopsMotionAndSpindleAndTheResumeFinishesThePart() throws Exception {
        Path p = part(PART);
        Path stopped = Files.createTempDirectory("gcnc-trace").resolve("stopped.trace");
        try (VirtualController vc = traced(model("DMC-4040"), stopped, "reject=45")) {
            homed(vc);
            Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--poll", "50");
            assertEquals(3, r.status(), r.all());
            Matcher m = Pattern.compile("part\\.nc:(\\d+):1: error\\[E820\\]: the controller refused (MG _XQ0,_CSS|TP): error 1"
                    + " \\(Unrecognized command\\); motion and spindle were stopped").matcher(r.err());
            assertTrue(m.find(), r.err());
            int line = Integer.parseInt(m.group(1));
            assertTrue(r.out().contains("executing: line " + line), r.out());
            // where the axes stopped, in the program's terms and then the counts the controller holds
            Matcher where = Pattern.compile("(?m)^axes at X-?[0-9.]+ Z-?[0-9.]+ \\(Galil counts (-?\\d+),(-?\\d+)\\)$")
                    .matcher(r.out());
            assertTrue(where.find(), r.out());
            long[] stood = axes(vc);
            assertEquals(stood[0], Long.parseLong(where.group(1)), r.out());
            assertEquals(stood[1], Long.parseLong(where.group(2)), r.out());
            assertFalse(vc.controller().moving());
            assertEquals(0.0, vc.controller().offset(2), "the spindle reference OF on C is back to 0 V");
            assertFalse(vc.controller().output(1), "M05's output (CB1)");
            String resume = resumeCommand(r.out());
            assertTrue(resume.endsWith("--resume-at " + line) || resume.contains("--resume-at " + line + ":"), resume);
            Run again = gcnc("", resumeArgs(resume));
            assertEquals(0, again.status(), again.all());
            assertTrue(again.out().contains("from line " + line), again.out());
            assertArrayEquals(programEnd(p), axes(vc));
        }
        assertEquals(uninterruptedPath(), path(stopped));
        assertEquals(6, uninterruptedPath().size());
    }

    static String resumeCommand(String out) {
        Matcher m = Pattern.compile("resume with: (gcnc .*)").matcher(out);
        assertTrue(m.find(), out);
        return m.group(1);
    }

    static String[] resumeArgs(String command) {
        String[] w = command.split(" ");
        return Arrays.copyOfRange(w, 1, w.length);
    }

    /**
     * A poll refused while the program runs far ahead of the last poll (a hundred times real time,
     * ten seconds of program a poll): the report and the resume name the block where the machine
     * stopped, found from the axes, not the last poll's. The resume it printed once named the rapid
     * from home (line 9) with the axes in the roughing passes, and was refused (E827); with the first
     * poll refused it named no block and the program's first; now it finishes the part.
     */
    @org.junit.jupiter.params.ParameterizedTest
    @org.junit.jupiter.params.provider.ValueSource(strings = {"reject=27", "reject=30"}) // the first poll's TP; a later one
    void aRefusedPollNamesTheBlockWhereTheMachineStopped(String fault) throws Exception {
        Path p = part(Files.readString(Path.of("docs/examples/bushing.nc")));
        try (VirtualController vc = traced(100, model("DMC-4040"), null, fault)) {
            homed(vc);
            String[] stock = {"--machine", "haas", "--stock", "1.5in,200mm,150mm", "--tcp", tcp(vc)};
            Run r = gcnc("", concat(new String[] {"run", p.toString(), "--form", "program"}, stock));
            assertEquals(3, r.status(), r.all());
            assertTrue(r.err().contains("error[E820]: the controller refused TP") || r.err().contains("error[E820]: the controller refused MG _XQ0,_CSS"), r.err());
            String resume = resumeCommand(r.out());
            Run again = gcnc("", resumeArgs(resume));
            assertEquals(0, again.status(), again.all());
            assertTrue(again.out().contains("ran to the end"), again.out());
        }
    }

    private static String[] concat(String[] a, String[] b) {
        String[] all = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, all, a.length, b.length);
        return all;
    }

    @Test
    void aDroppedConnectionNamesTheLastCompletedAndTheExecutingBlock() throws Exception {
        try (VirtualController vc = controller(model("DMC-4040"), "disconnect-after=1300")) {
            homed(vc);
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", tcp(vc), "--poll", "50");
            assertEquals(3, r.status(), r.all());
            // after the start the controller may run on without the host: E851 says so, and nothing says "stopped"
            Matcher m = Pattern.compile("error\\[E851\\]: the link to the controller dropped \\(the link closed\\) while it"
                    + " ran the program: the controller may run on without its host .*; at the last poll the last block"
                    + " completed was line (\\d+) and line (\\d+) was executing").matcher(r.err());
            assertTrue(m.find(), r.err());
            assertFalse(r.out().contains("stopped:"), r.out());
            assertTrue(r.out().contains("the link dropped; the controller may run on without the host"), r.out());
            // the position is the last poll's, and said so (the controller may have moved on)
            assertTrue(Pattern.compile("(?m)^axes last seen at X-?[0-9.]+ Z-?[0-9.]+ \\(Galil counts -?\\d+,-?\\d+\\)"
                    + " \\(the controller may have moved them since\\)$").matcher(r.out()).find(), r.out());
            assertTrue(Integer.parseInt(m.group(1)) < Integer.parseInt(m.group(2)), r.err());
            assertTrue(r.out().contains("resume with: gcnc run"), r.out());
        }
    }

    @Test
    void garbageFromTheControllerStopsTheRun() throws Exception {
        try (VirtualController vc = controller(model("DMC-4040"), "garbage-after=1600")) {
            homed(vc);
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", tcp(vc), "--poll", "50");
            assertEquals(3, r.status(), r.all());
            assertTrue(r.err().contains("error[E823]: the controller's reply to"), r.err());
            assertTrue(r.err().contains("is not Galil protocol"), r.err());
            // where the axes are: read after the stop, or (the link garbled past reading) the last poll's, said so
            assertTrue(Pattern.compile("(?m)^axes (at|last seen at) X-?[0-9.]+ Z-?[0-9.]+ \\(Galil counts -?\\d+,-?\\d+\\)"
                    + "( \\(the controller may have moved them since\\))?$").matcher(r.out()).find(), r.out());
            assertFalse(vc.controller().moving());
        }
    }

    @Test
    void aControllerThatDoesNotAnswerInTimeIsExit2BeforeMotion() throws Exception {
        try (VirtualController vc = controller(model("DMC-4040"), "slow=1500")) {
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", tcp(vc), "--timeout", "500");
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains("error[E822]: the controller did not answer '\\x12\\x16' in time"), r.err());
        }
    }

    @Test
    void aStalledSequenceIsStopped() throws Exception {
        try (VirtualController vc = controller(model("DMC-4040"), "stall=3")) {
            homed(vc);
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", tcp(vc), "--stall", "1", "--poll", "50");
            assertEquals(3, r.status(), r.all());
            assertTrue(r.err().contains("error[E825]: the controller cannot run the program: the axes stood still for 1 s during line 8"),
                    r.err());
            assertTrue(r.out().contains("resume with: gcnc run"), r.out());
        }
    }

    @Test
    void resumingWhereTheAxesAreNotIsRefused() throws Exception {
        try (VirtualController vc = controller(model("DMC-4040"))) {
            homed(vc);
            // the axes are at home, nowhere on line 9's arc
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", tcp(vc), "--resume-at", "9");
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains("part.nc:9:1: error[E827]: cannot resume at 9: the axes are at "), r.err());
            // the way there in program terms: X clear first, then Z, then in to line 9's start at X40 Z-30
            assertTrue(r.err().contains("(Galil counts " + home()[0] + "," + home()[1] + "), not on the path of line 9 (X40.000 Z-30.000 (Galil counts "),
                    r.err());
            assertTrue(r.err().contains("then X, to X40.000 Z-30.000 (Galil counts "), r.err());
            assertTrue(!r.err().contains("jog them to"), r.err());
            assertArrayEquals(home(), axes(vc));
        }
    }

    @Test
    void stepModeRunsOneBlockPerEnterToTheEnd() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = fast(model("DMC-4040"))) {
            homed(vc);
            Run r = gcnc("\n".repeat(20), "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--step", "--poll", "20");
            assertEquals(0, r.status(), r.all());
            // each block is a program of its own: one download (and read-back) per block
            int downloads = r.out().split("read back identical", -1).length - 1;
            assertEquals(9, downloads, r.out());
            assertTrue(r.out().contains("next: line 8 - press Enter to run it"), r.out());
            assertArrayEquals(programEnd(p), axes(vc));
        }
    }

    @Test
    void theOperatorStopsAStepRun() throws Exception {
        try (VirtualController vc = controller(model("DMC-4040"))) {
            homed(vc);
            Run r = gcnc("\nq\n", "run", part(PART).toString(), "--machine", "haas", "--tcp", tcp(vc), "--step");
            assertEquals(3, r.status(), r.all());
            assertTrue(r.err().contains("warning[E828]: stopped by the operator"), r.err());
            assertTrue(r.out().contains("resume with: gcnc run"), r.out());
        }
    }

    /** Feed hold (h, as the first Ctrl-C), Enter to resume, + for the override: VR 0, VR 1, VR 1.1 on the controller. */
    @Test
    void feedHoldAndOverrideGoToTheController() throws Exception {
        Path p = part(PART);
        try (VirtualController vc = controller(model("DMC-4040"))) {
            homed(vc);
            java.io.PipedOutputStream keys = new java.io.PipedOutputStream();
            java.io.PipedInputStream in = new java.io.PipedInputStream(keys);
            Thread operator = new Thread(() -> {
                try {
                    Thread.sleep(900);
                    keys.write("h\n".getBytes(StandardCharsets.UTF_8));
                    keys.flush();
                    Thread.sleep(600);
                    keys.write("\n+\n".getBytes(StandardCharsets.UTF_8));
                    keys.flush();
                    Thread.sleep(200);
                    keys.close();
                } catch (IOException | InterruptedException e) {
                    throw new IllegalStateException(e);
                }
            });
            operator.start();
            String[] args = {"run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--poll", "20"};
            CommandLine cl = Main.commandLine(new Main.Streams(in, System.out), gcnc.tables.ErrorMessages.Lang.EN, args);
            StringWriter out = new StringWriter();
            StringWriter err = new StringWriter();
            cl.setOut(new PrintWriter(out, true));
            cl.setErr(new PrintWriter(err, true));
            int status = cl.execute(args);
            operator.join();
            assertEquals(0, status, out + "" + err);
            String o = out.toString();
            assertTrue(o.contains("feed hold (VR 0): Enter resumes, Ctrl-C again stops"), o);
            assertTrue(o.indexOf("feed at 110% (VR 1.10)") > o.indexOf("feed hold"), o);
            assertArrayEquals(programEnd(p), axes(vc));
        }
    }

    /** A controller whose buffer still holds segments after CS S is refused before anything is sent (E831). */
    @Test
    void aBufferThatCsSDoesNotEmptyIsRefused() throws Exception {
        long[] h = home();
        try (ServerSocket server = new ServerSocket(0)) {
            List<String> downloaded = new ArrayList<>();
            Thread t = new Thread(() -> script(server, h, "DMC4040 Rev 1.2d", downloaded, 509));
            t.setDaemon(true);
            t.start();
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", "127.0.0.1:" + server.getLocalPort());
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains("error[E831]: the controller's vector buffer is not empty after CS S: _LMS reads 509"
                    + " where the model's empty buffer reads 511"), r.err());
            assertTrue(downloaded.isEmpty(), downloaded.toString());
        }
    }

    /** Segments a stopped sequence left in the buffer are cleared (CS S) at pre-flight, never run first. */
    @Test
    void segmentsLeftInTheBufferAreClearedBeforeTheRun() throws Exception {
        Path p = part(PART);
        Path trace = p.resolveSibling("left.trace");
        try (VirtualController vc = traced(FAST, model("DMC-4040"), trace)) {
            homed(vc);
            assertEquals(":", tell(vc, "VM XY"));
            assertEquals(":", tell(vc, "VP 30000,30000"));
            Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--tcp", tcp(vc), "--poll", "20");
            assertEquals(0, r.status(), r.all());
            assertEquals(uninterruptedPath(), path(trace), "the left segment never ran");
        }
    }

    /** A bus card (DMC-1700, ISA: the thesis-2004 profile's) is refused by gcnc run; gcnc compile still takes it. */
    @Test
    void aBusOnlyModelIsRefusedBeforeAnythingIsOpened() throws Exception {
        Path p = part("G21\nG00 X10. Z5.\nM30\n");
        try (ServerSocket server = new ServerSocket(0)) {
            server.setSoTimeout(300);
            Run r = gcnc("", "run", p.toString(), "--machine", "thesis-2004", "--tcp", "127.0.0.1:" + server.getLocalPort());
            assertEquals(2, r.status(), r.all());
            assertTrue(r.err().contains("error[E830]: the profile thesis-2004 names galil.model = DMC-1700; a bus card (ISA;"),
                    r.err());
            assertThrowsTimeout(server);
        }
        Run c = gcnc("", "compile", p.toString(), "--machine", "thesis-2004", "-o", p.resolveSibling("t.dmc").toString());
        assertEquals(0, c.status(), c.all());
    }

    /** A tiny scripted controller for one reply sequence: the program it reads back is not the one sent. */
    @Test
    void aReadBackThatDiffersIsNotRun() throws Exception {
        long[] h = home();
        try (ServerSocket server = new ServerSocket(0)) {
            Thread t = new Thread(() -> script(server, h, "DMC4040 Rev 1.2d", new ArrayList<>()));
            t.setDaemon(true);
            t.start();
            Run r = gcnc("", "run", part(PART).toString(), "--machine", "haas", "--tcp", "127.0.0.1:" + server.getLocalPort());
            assertEquals(2, r.status(), r.all());
            // the first spindle voltage read back with a digit more
            assertTrue(java.util.regex.Pattern.compile("error\\[E824\\]: the program read back from the controller \\(UL\\)"
                    + " differs from the one downloaded at DMC line \\d+: sent '[^']*OF ,,([0-9.]+)[^']*' and read '[^']*OF ,,\\11[^']*'")
                    .matcher(r.err()).find(), r.err());
        }
    }

    /** Answers a pre-flight, takes a download and uploads it with one digit changed; XQ would be an error. */
    private static void script(ServerSocket server, long[] home, String revision, List<String> program) {
        script(server, home, revision, program, 511);
    }

    /** As above, with {@code _LMS} answering {@code lms} (511: the DMC-4040's empty buffer). */
    private static void script(ServerSocket server, long[] home, String revision, List<String> program, int lms) {
        try (Socket s = server.accept()) {
            InputStream in = s.getInputStream();
            OutputStream out = s.getOutputStream();
            boolean download = false;
            StringBuilder line = new StringBuilder();
            for (int c = in.read(); c >= 0; c = in.read()) {
                if (download && c == '\\') {
                    download = false;
                    out.write("::".getBytes(StandardCharsets.ISO_8859_1));
                    continue;
                }
                if (c != '\r') {
                    line.append((char) c);
                    continue;
                }
                String cmd = line.toString();
                line.setLength(0);
                if (download) {
                    synchronized (program) {
                        program.add(cmd);
                    }
                    continue;
                }
                String reply = switch (cmd) {
                    case "\u0012\u0016" -> revision + "\r\n:";
                    case "TC1" -> "0\r\n:";
                    case "TP" -> home[0] + ", " + home[1] + ", 0, 0\r\n:";
                    case "MG _XQ0" -> "-1.0000\r\n:";
                    case "MG _LFX", "MG _LRX", "MG _LFY", "MG _LRY" -> " 1.0000\r\n:";
                    case "MG _MOX", "MG _MOY", "MG _BGS" -> " 0.0000\r\n:";
                    case "MG _DL", "MG _UL" -> " 510.0000\r\n:";
                    case "MG _LMS" -> " " + lms + ".0000\r\n:";
                    case "MG 20261127" -> " 20261127.0000\r\n:";
                    case "DL" -> "";
                    case "UL" -> String.join("\r\n", program).replaceFirst("(OF ,,[0-9.]+)", "$11") + "\r\n\\:";
                    default -> cmd.startsWith("XQ") ? "?" : cmd.startsWith("MG") ? " 0.0000\r\n:" : ":";
                };
                download = cmd.equals("DL");
                out.write(reply.getBytes(StandardCharsets.ISO_8859_1));
            }
        } catch (IOException e) {
            // the test ends the connection
        }
    }
}
