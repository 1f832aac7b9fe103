package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * check and compile give one verdict on arcs (issue 18): what the galil dialect cannot write within
 * the replay's tolerance (E202 from the backend, E308 from the simulator) check reports too, at the
 * same line with the same code. The cases pin {@link ArcVerdict}'s replay of a CR to the
 * simulator's ({@code DmcInterpreter.cr}): should one copy change, check and compile part here.
 */
class ArcVerdictTest {
    private static final Tables TABLES = Tables.builtIn();

    private static MachineProfile haas() throws Exception {
        return ProfileLoader.load("haas", TableSource.builtIn(), TABLES);
    }

    private static List<String> codes(Compiler.Result r) {
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            if (d.code() != Code.E316_SIM_NO_STOCK) {
                out.add(d.code().id() + "@" + d.span().line());
            }
        }
        return out;
    }

    private static List<String> check(String program) throws Exception {
        return codes(Compiler.check(new StringReader(program), new Compiler.Settings(TABLES, haas(), Dialect.Kind.GALIL, Optional.empty())));
    }

    private static List<String> compile(String program) throws Exception {
        return codes(Compiler.compile(new StringReader(program), new Compiler.Settings(TABLES, haas(), Dialect.Kind.GALIL,
                Optional.of(SimOptions.defaults().withoutBlank())), l -> { }));
    }

    /** An inch arc from X1.9 Z0 to X1.9+2*chord... on the Haas: one block, line 9. */
    private static String arc(String g, double radius, double chord) {
        return String.format(Locale.ROOT, "%%\nO1005\nG20 G18 G40 G54 G80 G99\nT0101\nG97 S1000 M03\nG00 X2.2 Z0.1\n"
                + "G01 X1.9 F0.005\nZ0.\n%s X%.4f Z-0.001 R%.3f\nG00 X2.2\nZ1.\nM30\n%%\n", g, 1.9 + 2 * chord, radius);
    }

    @Test
    void theLongRadiusOverAShortChordIsFoundByCheckAsByCompile() throws Exception {
        String program = Files.readString(Path.of("src/test/resources/gcnc/sim/arcs/long-radius-short-chord.nc"));
        assertEquals(List.of("E308@9"), check(program));
        assertEquals(List.of("E308@9"), compile(program));
    }

    @Test
    void aRadiusNoPrintableArcEndsOnIsE202InBoth() throws Exception {
        String program = arc("G03", 199, 0.045);
        assertEquals(List.of("E202@9"), check(program));
        assertEquals(List.of("E202@9"), compile(program));
    }

    /**
     * ArcVerdict remembers the arcs it judged clean (issue 23: a roughing program repeats them): the
     * same arc cut again is clean again, and an arc with a finding is reported at every line that
     * cuts it, as compile reports it, not once.
     */
    @Test
    void aRepeatedArcIsJudgedAtEveryLineItIsCut() throws Exception {
        String bad = "G03 X1.99 Z-0.001 R100.\n";
        String good = "G03 X2.1 Z-0.1 R0.1\n";
        String back = "G00 X2.2\nZ0.1\nG01 X1.9\nZ0.\n";
        String program = "%\nO1005\nG20 G18 G40 G54 G80 G99\nT0101\nG97 S1000 M03\nG00 X2.2 Z0.1\nG01 X1.9 F0.005\nZ0.\n"
                + good + back + good + back + bad + back + bad + back + good + "G00 X2.2\nZ1.\nM30\n%\n";
        List<String> expected = List.of("E308@19", "E308@24");
        assertEquals(expected, compile(program));
        assertEquals(expected, check(program));
    }

    /** Radii from a fraction of the chord's length to thousands of times it, both directions. */
    @ParameterizedTest(name = "{0} R{1} over {2}")
    @CsvSource({"G03,0.05,0.045", "G02,0.05,0.045", "G03,1.,0.045", "G03,10.,0.045", "G02,50.,0.045",
        "G03,80.,0.045", "G03,100.,0.045", "G02,100.,0.045", "G03,150.,0.045", "G03,199.,0.045",
        "G03,5.,0.2", "G02,40.,0.2", "G03,300.,0.2", "G03,2.,0.01", "G03,20.,0.01", "G02,60.,0.01"})
    void checkAndCompileAgree(String g, double radius, double chord) throws Exception {
        String program = arc(g, radius, chord);
        List<String> compiled = compile(program);
        assertEquals(compiled, check(program));
        // E224: a radius beyond what CR takes (6,000,000 counts), found by both as the controller's limit
        assertTrue(compiled.stream().allMatch(c -> c.equals("E202@9") || c.equals("E308@9") || c.equals("E224@9")),
                compiled.toString());
    }
}
