package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * The shared corpus of DMC programs (src/test/resources/gcnc/dmccorpus), each with the trace Galil's
 * manuals give it, that both of gcnc's readings of the controller run: the simulator's controller
 * (gcnc.sim.DmcCorpusSimTest, the reading gcnc's own checks rest on) and the virtual controller
 * (gcnc.controller.DmcCorpusVirtualTest, which plays the real one). Two implementations held to one
 * corpus, as two interpreters of one language run one test suite: where they read the manual
 * differently, one of them fails against the manual's numbers, not merely against the other.
 *
 * <p>A case is {@code NAME.dmc}, a program that starts at label {@code #CORPUS} with the axes at
 * (0,0) on the plane XY, and {@code NAME.trace}, what it must do, one event a line ({@code '}
 * lines say where the numbers come from):
 * <pre>
 * VP e1 e2 | CR e1 e2   a segment ran and ended at (e1,e2), whole counts from the controller's zero
 * PA e1 e2              a thread pass's settling move ended at (e1,e2)
 * AV t                  the path reached trip point t (the sum of the AV distances) and the thread went on
 * SB n | CB n           output n was set or cleared
 * ! n                   the statement on line n (from 1) was refused
 * </pre>
 * Each kind is compared in its order (the path, the trips, the outputs, the refusals): the two
 * controllers report a sequence's segments and its trips at different moments, but in the same order.
 */
public final class DmcCorpus {
    public static final Path DIR = Path.of("src/test/resources/gcnc/dmccorpus");

    /** One program of the corpus: its name, its text and the trace expected of it. */
    public record Case(String name, String program, List<String> expected) {
        @Override
        public String toString() {
            return name;
        }
    }

    private DmcCorpus() {
    }

    /** Every case of the corpus, by name. */
    public static List<Case> cases() {
        List<Case> cases = new ArrayList<>();
        try (Stream<Path> s = Files.list(DIR)) {
            for (Path p : s.filter(f -> f.toString().endsWith(".dmc")).sorted().toList()) {
                String name = p.getFileName().toString().replaceFirst("\\.dmc$", "");
                Path trace = DIR.resolve(name + ".trace");
                assertTrue(Files.exists(trace), name + ": no " + trace.getFileName());
                List<String> expected = Files.readAllLines(trace).stream()
                        .filter(l -> !l.isBlank() && !l.startsWith("'")).map(String::strip).toList();
                cases.add(new Case(name, Files.readString(p), expected));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        assertTrue(cases.size() >= 9, "the corpus has " + cases.size() + " cases");
        return cases;
    }

    /** What a case's run did ({@code ran}, in the trace's notation) is what the corpus expects of it. */
    public static void assertRan(Case c, String controller, List<String> ran) {
        for (String kind : List.of("path", "trips", "outputs", "refusals")) {
            assertEquals(of(kind, c.expected()), of(kind, ran), c.name() + " on " + controller + ": " + kind
                    + " (all it did: " + ran + ")");
        }
        for (String line : ran) {
            assertTrue(kind(line) != null, c.name() + " on " + controller + ": not an event of the corpus: " + line);
        }
    }

    private static List<String> of(String kind, List<String> events) {
        return events.stream().filter(e -> kind.equals(kind(e))).toList();
    }

    private static String kind(String event) {
        String word = event.split(" ")[0];
        return switch (word) {
            case "VP", "CR", "PA" -> "path";
            case "AV" -> "trips";
            case "SB", "CB" -> "outputs";
            case "!" -> "refusals";
            default -> null;
        };
    }
}
