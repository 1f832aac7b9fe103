package gcnc.junit;

import gcnc.Compiler;
import gcnc.diag.Diagnostic;
import gcnc.diag.GnuRenderer;
import gcnc.galil.LineSink;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.sim.SimOptions;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;

/**
 * JUnit 5 fixtures for a shop's own tests: part programs kept under version control are checked,
 * translated and simulated like any other source, and a failure lists every finding GCC-style.
 *
 * <pre>
 * &#64;TestFactory
 * Stream&lt;DynamicTest&gt; partPrograms() {
 *     return GcodeAssertions.everyProgramIn(Path.of("programs"), "lathes/okuma.machine");
 * }
 * </pre>
 */
public final class GcodeAssertions {
    private GcodeAssertions() {
    }

    /**
     * Fails with every finding unless the program compiles and simulates without an error on the
     * machine (warnings and notes, like the command line's exit status 0, do not fail it).
     */
    public static void assertCompilesClean(Path program, String machine) {
        List<String> findings = findings(program, machine);
        if (findings.stream().anyMatch(f -> f.contains(": error["))) {
            throw new AssertionError(program + " is not clean on " + machine + ":\n" + String.join("\n", findings));
        }
    }

    /** Fails unless the program has exactly these diagnostic codes, in order (e.g. "E037", "E101"). */
    public static void assertFindings(Path program, String machine, String... codes) {
        List<String> findings = findings(program, machine);
        List<String> actual = new ArrayList<>();
        for (String f : findings) {
            int open = f.indexOf('[');
            actual.add(f.substring(open + 1, f.indexOf(']', open)));
        }
        if (!actual.equals(List.of(codes))) {
            throw new AssertionError("expected " + List.of(codes) + " but got:\n" + String.join("\n", findings));
        }
    }

    /** One dynamic test per {@code *.nc} file below a folder. */
    public static Stream<DynamicTest> everyProgramIn(Path folder, String machine) {
        try (Stream<Path> files = Files.walk(folder)) {
            List<Path> programs = files.filter(p -> p.toString().endsWith(".nc")).sorted().toList();
            return programs.stream().map(p -> DynamicTest.dynamicTest(p.toString(), () -> assertCompilesClean(p, machine)));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static List<String> findings(Path program, String machine) {
        Tables tables = Tables.builtIn();
        MachineProfile profile;
        try {
            profile = ProfileLoader.load(machine, TableSource.builtIn(), tables);
        } catch (TableException e) {
            throw new AssertionError("machine profile " + machine + ": " + e.getMessage(), e);
        }
        GnuRenderer renderer = new GnuRenderer(tables.messages().in(ErrorMessages.Lang.EN));
        LineSink discard = line -> { };
        try (Reader in = Files.newBufferedReader(program)) {
            Compiler.Result r = Compiler.compile(in, new Compiler.Settings(tables, profile, "galil",
                    java.util.Optional.of(SimOptions.defaults())), discard);
            List<String> out = new ArrayList<>();
            for (Diagnostic d : r.diagnostics().sorted()) {
                out.add(renderer.render(program.toString(), d));
            }
            return out;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
