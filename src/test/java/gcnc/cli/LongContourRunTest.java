package gcnc.cli;

import static gcnc.cli.RunOnControllerTest.gcnc;
import static gcnc.cli.RunOnControllerTest.homed;
import static gcnc.cli.RunOnControllerTest.model;
import static gcnc.cli.RunOnControllerTest.part;
import static gcnc.cli.RunOnControllerTest.tcp;
import static gcnc.cli.RunOnControllerTest.traced;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.controller.VirtualController;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Issue 33's proof: a finishing contour of 1,000 chords, with its coolant switched on and off on the
 * way (M08 at chord 300, M09 at chord 800: AV trip points while the buffer is fed), is one vector
 * sequence in both forms and runs as one on the virtual Galil: one BGS, no stop between its first
 * and last chord (every chord run at about its feed), both trip points tripped where their chords
 * start; with a slow host (the stream form) or a slow program thread (the program form) the run
 * reports the starvation (E890) at its segment and block, never a normal end.
 */
class LongContourRunTest {
    static final int CHORDS = 1000;
    /** The chords' compiled feed on the haas: F0.2 mm/rev at 1200 r/min is 240 mm/min, 3936 counts/s. */
    static final double FEED = 3936;

    /** The contour: rapid in, the feed to Z0, the chords along a wave, coolant on and off on the way, rapid out. */
    static String contour() {
        StringBuilder b = new StringBuilder("%\nO3301 (FINISH 1000 CHORDS)\nG21 G18 G40 G99\nT0101\nG97 S1200 M03\n"
                + "G00 X48. Z1.\nG01 Z0. F0.2\n");
        for (int k = 1; k <= CHORDS; k++) {
            b.append(String.format(java.util.Locale.ROOT, "X%.3f Z%.3f%s%n", 46 + Math.sin(k / 40.0), -k * 0.05,
                    k == 300 ? " M08" : k == 800 ? " M09" : ""));
        }
        return b.append("G00 X60.\nZ5.\nM05\nM30\n%\n").toString();
    }

    /** The trace's segments of the sequence that holds the chords: {sequence, segment, end1, end2, time}. */
    static List<double[]> longest(Path trace) throws Exception {
        List<List<double[]>> bySequence = new ArrayList<>();
        for (String l : Files.readAllLines(trace)) {
            if (l.startsWith("#") || l.isBlank()) {
                continue;
            }
            String[] f = l.split(" ");
            int s = Integer.parseInt(f[0]);
            while (bySequence.size() < s) {
                bySequence.add(new ArrayList<>());
            }
            bySequence.get(s - 1).add(new double[] {s, Integer.parseInt(f[1]), Double.parseDouble(f[3]),
                    Double.parseDouble(f[4]), Double.parseDouble(f[6])});
        }
        return bySequence.stream().max(java.util.Comparator.comparingInt(List::size)).orElseThrow();
    }

    @ParameterizedTest
    @ValueSource(strings = {"program", "stream"})
    void aThousandChordFinishRunsAsOneSequenceWithoutAStop(String form) throws Exception {
        Path p = part(contour());
        Path trace = p.resolveSibling(form + ".trace");
        try (VirtualController vc = traced(RunOnControllerTest.FAST, model("DMC-4040"), trace)) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--form", form, "--tcp",
                    tcp(vc), "--poll", "10", "--format", "json");
            assertEquals(0, r.status(), r.all());
            assertTrue(r.out().contains("\"event\":\"finished\""), r.all());
        }
        // compiled: one sequence for the chords (the map's stops: rapid in, the chords, rapid out)
        List<String> stops = Files.readAllLines(p.resolveSibling(form.equals("stream") ? "part.stream.map" : "part.dmc.map")).stream()
                .filter(l -> l.startsWith("# stop ")).map(l -> l.substring(l.lastIndexOf(' ') + 1)).toList();
        assertEquals(List.of("rapid-feed", "rapid-feed", "output"), stops);
        List<String> lines = Files.readAllLines(trace);
        List<double[]> cut = longest(trace);
        assertTrue(cut.size() >= CHORDS, "the chords in one sequence: " + cut.size());
        int sequence = (int) cut.get(0)[0];
        assertTrue(lines.stream().anyMatch(l -> l.startsWith("# end " + sequence + " at ")),
                "the sequence ran to its VE, no underrun: " + lines.stream().filter(l -> l.startsWith("# ")).toList());
        // no stop between the first chord and the last: each chord's average speed is near the feed
        // (a chord begun and ended at rest averages half its top speed at most)
        for (int k = 5; k < cut.size() - 5; k++) {
            double[] a = cut.get(k - 1);
            double[] b = cut.get(k);
            double v = Math.hypot(b[2] - a[2], b[3] - a[3]) / (b[4] - a[4]);
            assertTrue(v > 0.8 * FEED, "segment " + (int) b[1] + " at " + Math.round(v) + " counts/s");
        }
        // both outputs tripped on the way: in the program form, two AV trips while the sequence ran (the
        // stream form's host waits for them itself, polling _AVS: the controller sees no AV)
        for (String l : lines) {
            java.util.regex.Matcher m = java.util.regex.Pattern.compile("^# av \\d+ tripped at (\\d+) of path \\(trip point (\\d+)\\)")
                    .matcher(l);
            if (m.find()) { // the thread went on where the trip point is, within a chord (50 counts), not late
                long late = Long.parseLong(m.group(1)) - Long.parseLong(m.group(2));
                assertTrue(late >= 0 && late < 50, l);
            }
        }
        assertEquals(form.equals("program") ? 2 : 0, lines.stream().filter(l -> l.startsWith("# av ") && l.contains(" tripped at ")).count(),
                lines.stream().filter(l -> l.startsWith("# av")).toList().toString());
    }

    /**
     * A feeder slower than the chords, in each form: in the stream form the host, every reply of the
     * controller taking 5 ms while a chord runs in 2.5 ms (12.7 ms of controller time at five times real
     * time); in the program form thread 0, every statement taking 50 ms of controller time (at twenty
     * times real time). Neither can keep the buffer fed: the controller's buffer runs dry before VE (its
     * trace: an underrun, not an end), and gcnc says so, E890 at the segment where the axes stopped and
     * its block, never a normal end (in the program form not the E825 of a program ended away from its
     * end either).
     */
    @ParameterizedTest
    @org.junit.jupiter.params.provider.CsvSource({"stream, 5, slow=5", "program, 20, slow-thread=50"})
    void aFeederTooSlowForTheChordsReportsTheStarvationAtItsSegment(String form, double speed, String fault) throws Exception {
        Path p = part(contour());
        Path trace = p.resolveSibling("slow.trace");
        try (VirtualController vc = traced(speed, model("DMC-4040"), trace, fault)) {
            homed(vc);
            RunOnControllerTest.Run r = gcnc("", "run", p.toString(), "--machine", "haas", "--form", form, "--tcp",
                    tcp(vc), "--poll", "10");
            assertEquals(3, r.status(), r.all()); // the run failed on the machine (docs/run.md)
            java.util.regex.Matcher m = java.util.regex.Pattern.compile(
                    "error\\[E890\\]: the vector buffer ran dry before VE at segment (\\d+) of the sequence \\(line (\\d+)\\)")
                    .matcher(r.all());
            assertTrue(m.find(), r.all());
            assertTrue(!r.all().contains("finished"), r.all());
            List<String> lines = Files.readAllLines(trace);
            List<double[]> cut = longest(trace);
            int sequence = (int) cut.get(0)[0];
            assertTrue(lines.stream().anyMatch(l -> l.startsWith("# underrun " + sequence + " at ")), lines.stream()
                    .filter(l -> l.startsWith("# ")).toList().toString());
            // the segment named is the last the controller ran, and its block is that chord's line
            int segment = Integer.parseInt(m.group(1));
            assertEquals((int) cut.get(cut.size() - 1)[1], segment, r.all());
            assertTrue(segment > 510 && segment < CHORDS, "ran dry after the first fill, before the last chord: " + segment);
            assertEquals(6 + segment, Integer.parseInt(m.group(2)), "segment 1 is G01 Z0. on line 7, chord k on line 7 + k");
        }
    }
}
