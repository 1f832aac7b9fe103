package gcnc;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.DynamicTest.dynamicTest;

import gcnc.dmc.Instruction;
import gcnc.galil.Dialect;
import gcnc.machine.ProfileLoader;
import gcnc.sim.SimOptions;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
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
 * Whole programs through the whole pipeline, compared byte for byte with reviewed output in
 * src/test/resources/golden/. After a deliberate change, regenerate with
 * {@code gradle junitPlatformTest -PupdateGolden} and review the diff before committing.
 */
class GoldenTest {
    /** sample program, machine profile, dialect. */
    record Case(String sample, String machine, String dialect) {
        Path golden() {
            return Path.of("src/test/resources/golden", sample + "." + machine + "." + dialect + ".dmc");
        }
    }

    static final List<Case> CASES = List.of(
            new Case("bishop", "thesis-2004", "thesis"),
            new Case("bishop", "thesis-2004", "galil"),
            new Case("turning", "generic", "galil"),
            new Case("arcs", "generic", "galil"),
            new Case("units", "generic", "galil"),
            new Case("offsets", "generic", "galil"),
            new Case("home", "generic", "galil"),
            new Case("dwell-css", "generic", "galil"));

    static String compile(Case c) throws Exception {
        Tables tables = Tables.builtIn();
        Compiler.Settings s = new Compiler.Settings(tables, ProfileLoader.load(c.machine(), TableSource.builtIn(), tables),
                Dialect.Kind.of(c.dialect()), c.dialect().equals("galil") ? Optional.of(SimOptions.defaults()) : Optional.empty());
        StringBuilder out = new StringBuilder();
        // the galil dialect's lines packed as gcnc compile writes its program form; the thesis's one a line
        gcnc.dmc.LinePacker packer = new gcnc.dmc.LinePacker(s.profile().controllerLimits().lineWidth(),
                l -> out.append(l.text()).append('\n'));
        java.util.function.Consumer<Instruction> sink = c.dialect().equals("galil") ? packer
                : l -> out.append(l.text()).append('\n');
        try (Reader in = Files.newBufferedReader(Path.of("samples", c.sample() + ".nc"))) {
            Compiler.Result r = Compiler.compile(in, s, sink);
            assertTrue(r.ok(), () -> c + " has findings: " + r.diagnostics().sorted());
        }
        packer.flush();
        return out.toString();
    }

    @TestFactory
    Stream<DynamicTest> everySampleMatchesItsGoldenFile() {
        boolean update = Boolean.getBoolean("gcnc.updateGolden");
        return CASES.stream().map(c -> dynamicTest(c.sample() + ".nc: " + c.golden().getFileName(), () -> {
            String actual = compile(c);
            if (update) {
                Files.createDirectories(c.golden().getParent());
                Files.writeString(c.golden(), actual, StandardCharsets.UTF_8);
            }
            assertEquals(Files.readString(c.golden(), StandardCharsets.UTF_8), actual);
        }));
    }

    @TestFactory
    Stream<DynamicTest> compilingTwiceGivesTheSameBytes() {
        return CASES.stream().map(c -> dynamicTest(c.golden().getFileName() + " twice", () -> assertEquals(compile(c), compile(c))));
    }

    /**
     * The bishop's golden in the thesis's dialect is the thesis's Table 5.2 (../shared/spec/bishop.expected.dmc),
     * byte for byte: so the goldens cover the table in a clone that has no ../shared beside it.
     */
    @Test
    void theThesisDialectsBishopIsTable52ByteForByte() throws IOException {
        Path table = Path.of("../shared/spec/bishop.expected.dmc");
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isRegularFile(table),
                "needs ../shared/spec/bishop.expected.dmc (the thesis's Table 5.2 beside the checkout); absent here");
        assertArrayEquals(Files.readAllBytes(table), Files.readAllBytes(CASES.get(0).golden()), CASES.get(0).golden().toString());
    }

    static List<String> lines(Path p) throws IOException {
        return new ArrayList<>(Files.readAllLines(p));
    }
}
