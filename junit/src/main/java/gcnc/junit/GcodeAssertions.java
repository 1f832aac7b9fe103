package gcnc.junit;

import gcnc.Compiler;
import gcnc.ProgramFiles;
import gcnc.Session;
import gcnc.diag.Diagnostic;
import gcnc.diag.GnuRenderer;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import java.io.IOException;
import java.io.UncheckedIOException;
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
        assertCompilesClean(program, session(machine));
    }

    /**
     * The same with every input the command line takes (tables, machine, control, dialect, blank):
     * {@code Session.open(Session.Options.defaults().withMachine("haas").withStock(...))}. The
     * verdict is the command line's {@code gcnc compile} on the same inputs.
     */
    public static void assertCompilesClean(Path program, Session session) {
        List<String> findings = findings(program, session);
        if (findings.stream().anyMatch(f -> f.contains(": error["))) {
            throw new AssertionError(program + " is not clean on " + session.profile().name() + ":\n"
                    + String.join("\n", findings));
        }
        sayWaived(program, session, findings);
    }

    /**
     * A clean program with waived findings ({@code (GCNC ALLOW E642: reason)}) passes, and says so on
     * standard output (the test's report shows it): which findings the shop's waivers accept, and why.
     */
    static void sayWaived(Path program, Session session, List<String> findings) {
        List<String> waived = findings.stream().filter(f -> f.contains("] waived: ")).toList();
        if (!waived.isEmpty()) {
            System.out.println("gcnc: " + program + " is clean on " + session.profile().name() + " with "
                    + waived.size() + " waived finding" + (waived.size() == 1 ? "" : "s") + ":\n"
                    + String.join("\n", waived));
        }
    }

    /** Fails unless the program has exactly these diagnostic codes, in order (e.g. "E037", "E101"). */
    public static void assertFindings(Path program, String machine, String... codes) {
        assertFindings(program, session(machine), codes);
    }

    /** Fails unless the program has exactly these diagnostic codes, in order, with these inputs. */
    public static void assertFindings(Path program, Session session, String... codes) {
        List<String> findings = findings(program, session);
        List<String> actual = new ArrayList<>();
        for (String f : findings) {
            int open = f.indexOf('[');
            actual.add(f.substring(open + 1, f.indexOf(']', open)));
        }
        if (!actual.equals(List.of(codes))) {
            throw new AssertionError("expected " + List.of(codes) + " but got:\n" + String.join("\n", findings));
        }
    }

    /**
     * The file names a shop's part programs have (any case) unless told otherwise: .nc, .ngc, .tap,
     * .gcode ({@link ProgramFiles#EXTENSIONS}, the list the command line and the Gradle plugin use).
     */
    public static final List<String> PROGRAM_EXTENSIONS = ProgramFiles.EXTENSIONS;

    /**
     * One dynamic test per part program below a folder: by the build's list when the Gradle plugin
     * runs the tests ({@code gcnc { extensions }}, {@link ProgramFiles#configured}), else
     * {@link #PROGRAM_EXTENSIONS}, any case.
     */
    public static Stream<DynamicTest> everyProgramIn(Path folder, String machine) {
        return everyProgramIn(folder, session(machine));
    }

    /**
     * One dynamic test per part program below a folder, named after its file; a folder with no
     * program in it is a failing test (a misspelt path must not pass a build).
     */
    public static Stream<DynamicTest> everyProgramIn(Path folder, Session session) {
        return everyProgramIn(folder, session, ProgramFiles.configured());
    }

    /**
     * The same for the shop's own file names: {@code everyProgramIn(dir, machine("haas"), List.of("gcode", "nc"))}
     * takes {@code *.gcode} and {@code *.nc} in any case.
     */
    public static Stream<DynamicTest> everyProgramIn(Path folder, Session session, List<String> extensions) {
        List<String> lower = ProgramFiles.normal(extensions);
        List<Path> programs;
        try {
            ProgramFiles.Scan scan = ProgramFiles.scan(folder, lower);
            programs = scan.programs();
            if (scan.skippedCount() > 0) {
                // the note the command line gives too: a program saved as .txt is not silently untested
                System.out.println("gcnc: " + folder + ": skipped " + scan.skippedCount() + " file"
                        + (scan.skippedCount() == 1 ? "" : "s") + " " + scan.skipped()
                        + ": not a program's extension (." + String.join(", .", lower) + ")");
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the folder " + folder, e);
        }
        if (programs.isEmpty()) {
            return Stream.of(DynamicTest.dynamicTest(folder.toString(), () -> {
                throw new AssertionError("no part program (" + String.join(", ", lower) + ") in " + folder);
            }));
        }
        return programs.stream().map(p -> DynamicTest.dynamicTest(folder.relativize(p).toString(),
                () -> assertCompilesClean(p, session)));
    }

    /** The built-in tables and a shipped machine profile (or a .machine file). */
    public static Session session(String machine) {
        try {
            return Session.open(Session.Options.defaults().withMachine(machine));
        } catch (TableException e) {
            throw new AssertionError("machine profile " + machine + ": " + e.getMessage(), e);
        }
    }

    private static List<String> findings(Path program, Session session) {
        GnuRenderer renderer = new GnuRenderer(session.tables().messages().in(ErrorMessages.Lang.EN));
        try {
            Compiler.Result r = session.compile(program);
            List<String> out = new ArrayList<>();
            for (Diagnostic d : r.diagnostics().sorted()) {
                out.add(renderer.render(program.toString(), d));
            }
            return out;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + program, e);
        }
    }
}
