package gcnc.post;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.diag.Diagnostic;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * What gcnc answers today to each construct of the Haas and Fanuc 0i-TF manuals and the Fusion
 * 360 turning posts, as docs/language.md's table says: src/test/resources/post/language-probes.txt
 * holds one tiny program per row and control with the findings check gives it ("clean", or line
 * and code). A change in what gcnc accepts shows here, and the table's row is updated with it.
 */
class LanguageProbeTest {
    private static final Path PROBES = Path.of("src/test/resources/post/language-probes.txt");

    /** The machine and control of each control name the probes use (fanuc-b is the fanuc profile with control fanuc-b). */
    private static final Map<String, String[]> MACHINE = Map.of(
            "haas", new String[] {"haas", "haas"},
            "fanuc-a", new String[] {"fanuc", "fanuc-a"},
            "fanuc-b", new String[] {"fanuc", "fanuc-b"});

    /** What comes before a probe's lines: a program already running a tool at a first position outside the blank. */
    static final Map<String, String> HEAD = Map.of(
            "haas", "%\nO1000\nG20\nG50 S2000\nT0101\nG97 S500 M03\nG00 X2.2 Z0.1\n",
            "fanuc-a", "%\nO1000\nG21\nG50 S2000\nT0101\nG97 S500 M03\nG00 X70. Z2.\n",
            "fanuc-b", "%\nO1000\nG21\nG92 S2000\nT0101\nG97 S500 M03\nG00 X70. Z2.\n");
    private static final String TAIL = "M30\n%\n";

    private record Probe(String name, List<String> controls, boolean raw, String body, String expected) {
    }

    private static List<Probe> probes() throws Exception {
        List<Probe> out = new ArrayList<>();
        List<String> lines = Files.readAllLines(PROBES);
        for (int i = 0; i < lines.size(); i++) {
            String l = lines.get(i);
            if (!l.startsWith("== ")) {
                continue;
            }
            List<String> head = new ArrayList<>(List.of(l.substring(3).split(" ")));
            boolean raw = head.get(head.size() - 1).equals("raw");
            if (raw) {
                head.remove(head.size() - 1);
            }
            StringBuilder body = new StringBuilder();
            int j = i + 1;
            for (; !lines.get(j).startsWith("-> "); j++) {
                body.append(lines.get(j)).append('\n');
            }
            out.add(new Probe(head.get(0), head.subList(1, head.size()), raw, body.toString(), lines.get(j).substring(3)));
            i = j;
        }
        return out;
    }

    @TestFactory
    Stream<DynamicTest> eachConstructGetsTheAnswerTheTableGives() throws Exception {
        Map<String, Session> sessions = new HashMap<>();
        for (Map.Entry<String, String[]> e : MACHINE.entrySet()) {
            sessions.put(e.getKey(), Session.open(Session.Options.defaults().withMachine(e.getValue()[0])
                    .withControl(e.getValue()[1])));
        }
        List<Probe> probes = probes();
        assertTrue(probes.size() > 200, "the probes file has its rows: " + probes.size());
        List<DynamicTest> tests = new ArrayList<>();
        for (Probe p : probes) {
            for (String control : p.controls()) {
                tests.add(dynamicTest(p.name() + " on " + control, () -> {
                    String head = p.raw() ? "" : HEAD.get(control);
                    String program = p.raw() ? p.body() : head + p.body() + TAIL;
                    Compiler.Result r = sessions.get(control).check(new StringReader(program));
                    int offset = (int) head.chars().filter(c -> c == '\n').count();
                    TreeSet<String> found = new TreeSet<>((a, b) -> {
                        int c = Integer.compare(Integer.parseInt(a.split(":")[0]), Integer.parseInt(b.split(":")[0]));
                        return c != 0 ? c : a.compareTo(b);
                    });
                    for (Diagnostic d : r.diagnostics().sorted()) {
                        found.add((d.span().line() - offset) + ":" + d.code().id());
                    }
                    assertEquals(p.expected(), found.isEmpty() ? "clean" : String.join(" ", found), program);
                }));
            }
        }
        return tests.stream();
    }
}
