package gcnc.path;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.sim.Drawing;
import gcnc.sim.SimOptions;
import java.io.IOException;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;

/**
 * gcnc path (issue 31 item 4; docs/path.md): the bishop, a G71/G70 part, a nose-compensated contour
 * and a macro loop with a subprogram call, each against its golden CSV, and each move's machine end
 * point against what the simulator replays of the DMC for the same source line, within a count.
 * {@code gradle junitPlatformTest -Ponly=PathTest -PupdateGolden} rewrites the goldens.
 */
class PathTest {
    /** One program on one machine, and its golden file under src/test/resources/golden/path/. */
    record Case(String program, String machine, String golden) {
        Path goldenPath() {
            return Path.of("src/test/resources/golden/path", golden);
        }
    }

    static final List<Case> CASES = List.of(
            new Case("samples/bishop.nc", "thesis-2004", "bishop.thesis-2004.csv"),
            new Case("src/test/resources/cycles/stock-removal.fanuc.nc", "fanuc", "stock-removal.fanuc.csv"),
            new Case("src/test/resources/nose/outside-g42.fanuc.nc", "fanuc", "outside-g42.fanuc.csv"),
            new Case("src/test/resources/fuzz/fanuc-macro-grooves.nc", "fanuc", "macro-grooves.fanuc.csv"));

    private static Session session(Case c) throws Exception {
        return Session.open(Session.Options.defaults().withMachine(c.machine()));
    }

    private static List<PathMove> path(Case c) throws Exception {
        Session s = session(c);
        List<PathMove> moves = new ArrayList<>();
        try (Reader in = Files.newBufferedReader(Path.of(c.program()))) {
            Compiler.Result r = s.path(in, new InterpretedPath(s.profile(), c.program(), moves::add));
            assertTrue(r.ok(), () -> c + ": " + r.diagnostics().sorted());
        }
        return moves;
    }

    private static String csv(List<PathMove> moves) {
        StringBuilder b = new StringBuilder(PathFormat.CSV.header()).append('\n');
        moves.forEach(m -> b.append(PathFormat.CSV.line(m)).append('\n'));
        return b.toString();
    }

    @TestFactory
    Stream<DynamicTest> eachPathMatchesItsGolden() {
        boolean update = Boolean.getBoolean("gcnc.updateGolden");
        return CASES.stream().map(c -> dynamicTest(c.golden(), () -> {
            String actual = csv(path(c));
            if (update) {
                Files.createDirectories(c.goldenPath().getParent());
                Files.writeString(c.goldenPath(), actual, StandardCharsets.UTF_8);
            }
            assertEquals(Files.readString(c.goldenPath(), StandardCharsets.UTF_8), actual);
        }));
    }

    /**
     * The simulator replays the DMC gcnc writes, never the G-code: each path move's machine end
     * point is a point of the replayed path of the same source line, within one count.
     */
    @TestFactory
    Stream<DynamicTest> eachMoveEndsWhereTheSimulatorsReplayOfItsLineGoes() {
        return CASES.stream().map(c -> dynamicTest(c.golden(), () -> {
            Session s = session(c);
            Compiler.Result r;
            try (Reader in = Files.newBufferedReader(Path.of(c.program()))) {
                // no blank: the replay's positions, whatever the stock (a finishing contour on a whole blank)
                r = s.compile(in, Optional.of(SimOptions.defaults().withoutBlank().withPath()), false, i -> { });
            }
            assertTrue(r.ok(), () -> c + ": " + r.diagnostics().sorted());
            Drawing d = r.simulation().orElseThrow().drawing();
            double kx = s.profile().x().countsPerMm();
            double kz = s.profile().z().countsPerMm();
            double centre = s.profile().model().centreX();
            int checked = 0;
            for (PathMove m : path(c)) {
                if (m.kind() == PathMove.Kind.DWELL) {
                    continue;
                }
                double x = Double.parseDouble(m.machineX());
                double z = Double.parseDouble(m.machineZ());
                boolean found = false;
                for (Drawing.Move replay : d.moves()) {
                    if (replay.line() != m.line()) {
                        continue;
                    }
                    for (int i = 0; i < replay.z().length && !found; i++) {
                        found = Math.abs(replay.z()[i] - z) * kz <= 1.0 + 1e-6
                                && Math.abs(replay.r()[i] + centre - x) * kx <= 1.0 + 1e-6;
                    }
                }
                assertTrue(found, c.program() + ":" + m.line() + " " + m.kind().written() + " to machine X" + m.machineX()
                        + " Z" + m.machineZ() + ": the replay of that line never goes there");
                checked++;
            }
            assertTrue(checked > 10, c + ": only " + checked + " moves");
        }));
    }

    @Test
    void jsonLinesCarryTheSameValuesAsTheCsv() throws Exception {
        PathMove m = path(CASES.get(2)).get(3);
        String json = PathFormat.JSON.line(m);
        com.fasterxml.jackson.databind.JsonNode o = new com.fasterxml.jackson.databind.ObjectMapper().readTree(json);
        List<String> values = m.values();
        for (int i = 0; i < PathMove.COLUMNS.size(); i++) {
            com.fasterxml.jackson.databind.JsonNode v = o.get(PathMove.COLUMNS.get(i));
            String name = PathMove.COLUMNS.get(i);
            if (values.get(i).isEmpty()) {
                assertTrue(v.isNull(), name);
            } else if (v.isNumber() && !name.equals("line") && !name.equals("tool")) {
                assertEquals(values.get(i), String.format(java.util.Locale.ROOT, "%.4f", v.asDouble()), name);
            } else {
                assertEquals(values.get(i), v.asText(), name);
            }
        }
        assertEquals("\"a,\"\"b\"\"\"", PathFormat.csvField("a,\"b\""));
    }
}
