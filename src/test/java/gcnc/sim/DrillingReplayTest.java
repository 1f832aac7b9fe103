package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Diagnostic;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileFile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * The drilling, boring and tapping cycles replayed on the blank (issue 31): a hole drilled on the
 * centreline with the cycles as each control runs them, reamed with G85 (G89, G86 on the Haas)
 * and tapped, all clean; the tap cuts only because the hole is there (the same tap into solid
 * material is E323), so the replay really drilled it. The shipped haas and fanuc machines with a
 * drill, a reamer (a drill of the hole's size) and a tap in the turret.
 */
class DrillingReplayTest {
    private static final Tables TABLES = Tables.builtIn();
    private static final String TOOLS = "station.4 = drill 8.5\nstation.6 = drill 8.5\nstation.10 = tap 10\n";

    private static MachineProfile machine(String name, String control) throws Exception {
        String text = Files.readString(Path.of("tables/machines/" + name + ".machine")) + TOOLS;
        return ProfileLoader.read(ProfileFile.parse(name + ".machine", text), TABLES, TableSource.builtIn(), control);
    }

    /** The findings of compiling and replaying {@code program}, "line:code" each. */
    private static String findings(MachineProfile p, String program) throws Exception {
        Compiler.Result r = Compiler.compile(new StringReader(program), new Compiler.Settings(TABLES, p, Dialect.Kind.GALIL,
                Optional.of(SimOptions.defaults())), l -> { });
        assertTrue(r.simulation().isPresent(), r.diagnostics().sorted().toString());
        return r.diagnostics().sorted().stream().map(d -> d.span().line() + ":" + d.code().id())
                .collect(Collectors.joining(" "));
    }

    @Test
    void haasDrillsPecksReamsAndTapsOnTheCentrelineClean() throws Exception {
        String program = "%\nO1000\nG21 G18 G40 G80 G98\nT404\nG97 S1200 M03\nG00 X0. Z5.\n"
                + "G83 X0. Z-25. R2. Q6. F120.\nG80\n"          // line 7: pecks of 6 mm
                + "T606\nG97 S600 M03\nG00 X0. Z5.\n"
                + "G85 X0. Z-20. R2. F60.\nG80\n"               // line 12: ream in and out
                + "G89 X0. Z-20. R2. P0.5 F60.\nG80\n"          // line 14
                + "G86 X0. Z-20. R2. F60.\nG80\n"               // line 16: spindle stopped at the bottom
                + "T1010\nG97 S300 M03\nG00 X0. Z5.\n"
                + "G84 X0. Z-15. R2. P0 F450.\nG80\n"           // line 20: M10 x 1.5 at 300 r/min
                + "G00 X100. Z100.\nM30\n%\n";
        assertEquals("", findings(machine("haas", "haas"), program));
    }

    @Test
    void fanucSeries15DrillingAndFaceBoringReplayClean() throws Exception {
        String program = "%\nO1000\nG21 G18 G40 G80 G99\nT0404\nG97 S1200 M03\nG00 X0. Z5.\n"
                + "G81 X0. Z-20. R-3. F0.1\nG80\n"               // line 7: R from the initial level (system A)
                + "G82 X0. Z-22. R-3. P500 F0.1\nG80\n"
                + "T0606\nG97 S600 M03\nG00 X0. Z5.\n"
                + "G85 X0. Z-18. R-3. P200 F0.05\nG80\n"        // line 14: face boring, its dwell, fed out
                + "T1010\nG97 S300 M03\nG00 X0. Z5.\n"
                + "G84 X0. Z-15. R-3. F1.5\nG80\n"              // line 18: the lead in G99
                + "G00 X100. Z100.\nM30\n%\n";
        assertEquals("", findings(machine("fanuc", "fanuc-a"), program));
    }

    @Test
    void theTapCutsOnlyBecauseTheHoleIsThere() throws Exception {
        String solid = "%\nO1000\nG21 G18 G40 G80 G99\nT1010\nG97 S300 M03\nG00 X0. Z5.\n"
                + "G84 X0. Z-15. R-3. F1.5\nG80\nG00 X100. Z100.\nM30\n%\n";
        String found = findings(machine("fanuc", "fanuc-a"), solid);
        assertTrue(found.contains("7:E323"), found);
    }
}
