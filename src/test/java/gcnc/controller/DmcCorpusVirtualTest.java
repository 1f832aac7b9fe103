package gcnc.controller;

import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.DmcCorpus;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The shared DMC corpus ({@link DmcCorpus}) on the virtual controller, the independent implementation
 * that plays a real Galil: each program downloaded (DL), started with {@code XQ #CORPUS,0} and run a
 * millisecond at a time until its thread ends and nothing moves; the path and the trips read from its
 * trace (docs/virtual-controller.md, "Trace"), the outputs watched each millisecond, a refusal read
 * from {@code TC1} and {@code _ED} (the line of the error, counted from 0).
 */
class DmcCorpusVirtualTest {
    private static final Pattern SEGMENT = Pattern.compile("\\d+ \\d+ (VP|CR|PA) (-?\\d+) (-?\\d+) .*");
    private static final Pattern TRIP = Pattern.compile("# av \\d+ tripped at \\d+ of path \\(trip point (\\d+)\\).*");

    static List<DmcCorpus.Case> cases() {
        return DmcCorpus.cases();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void theVirtualControllerRunsTheCorpus(DmcCorpus.Case c) throws GalilException {
        StringWriter trace = new StringWriter();
        VirtualGalil g = new VirtualGalil(Model.standard(), List.of(), trace);
        g.download(c.program().replace("\n", "\r"), false);
        g.command("XQ #CORPUS,0");
        List<String> outputs = new ArrayList<>();
        boolean[] was = new boolean[9];
        double start = g.time();
        do {
            g.advance(0.001);
            for (int n = 1; n <= 8; n++) {
                if (g.output(n) != was[n]) {
                    was[n] = !was[n];
                    outputs.add((was[n] ? "SB " : "CB ") + n);
                }
            }
            assertTrue(g.time() - start < 600, c.name() + ": still running after 600 s of controller time");
        } while (g.operand("XQ0") >= 0 || g.moving());
        List<String> ran = new ArrayList<>();
        for (String line : trace.toString().lines().toList()) {
            Matcher s = SEGMENT.matcher(line);
            Matcher t = TRIP.matcher(line);
            if (s.matches()) {
                ran.add(s.group(1) + " " + s.group(2) + " " + s.group(3));
            } else if (t.matches()) {
                ran.add("AV " + t.group(1));
            }
        }
        ran.addAll(outputs);
        if (!g.command("TC1").startsWith("0")) {
            ran.add("! " + (Math.round(g.operand("ED")) + 1));
        }
        DmcCorpus.assertRan(c, "the virtual controller", ran);
    }
}
