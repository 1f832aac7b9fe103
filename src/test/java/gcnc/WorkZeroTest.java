package gcnc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.diag.Diagnostic;
import gcnc.sim.StockSize;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * The work zero a shop sets on the blank's face ({@code work.G54 = face}) follows the blank a run
 * is given ({@code --stock D,L,S}), and the run says so (E662); a profile that pins G54 elsewhere
 * is told (E663). The part: a 10 mm step turned from the face, Z0 = the face.
 */
class WorkZeroTest {
    private static final String PART = String.join("\n", "G21 G99", "G50 S2000", "T0101", "S1000 M03",
            "G00 X46. Z2.", "G01 Z-10. F0.2", "G00 X60. Z50.", "M30", "");

    private static List<String> codes(String machine, Optional<StockSize> blank, boolean compile) throws Exception {
        Session s = Session.open(Session.Options.defaults().withMachine(machine));
        if (blank.isPresent()) {
            s = s.withStock(blank.get());
        }
        Compiler.Result r = compile ? s.compile(new StringReader(PART), Optional.of(s.simulation()), false, l -> { })
                : s.check(new StringReader(PART));
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            out.add(d.span().line() + ":" + d.code().id());
        }
        return out;
    }

    @Test
    void theFaceOfTheRunsBlankIsTheWorkZero() throws Exception {
        // the fanuc profile's blank sticks out 100 mm; this one 80: G54 moves with it, the cut is clean
        assertEquals(List.of("1:E662"), codes("fanuc", Optional.of(new StockSize(50, 200, 80)), true));
        assertEquals(List.of("1:E662"), codes("fanuc", Optional.of(new StockSize(50, 200, 80)), false));
        // the profile's own stick-out: nothing moved, nothing to say
        assertEquals(List.of(), codes("fanuc", Optional.of(new StockSize(50, 200, 100)), true));
        assertEquals(List.of(), codes("fanuc", Optional.empty(), true));
    }

    @Test
    void aPinnedWorkZeroAwayFromTheBlanksFaceIsAWarning() throws Exception {
        // a shop profile that pins G54 at 100 mm: a 60 mm stick-out leaves Z0 40 mm in front of the face,
        // and the step's 2 mm approach and 10 mm cut are then in the air (no finding but the warning)
        java.nio.file.Path f = java.nio.file.Files.createTempFile("pinned", ".machine");
        java.nio.file.Files.writeString(f, java.nio.file.Files.readString(
                java.nio.file.Path.of("tables/machines/fanuc.machine")).replace("work.G54 = face", "work.G54 = 0, 100"));
        assertEquals(List.of("1:E663"), codes(f.toString(), Optional.of(new StockSize(50, 200, 60)), true));
        assertEquals(List.of("1:E663"), codes(f.toString(), Optional.of(new StockSize(50, 200, 60)), false));
        assertEquals(List.of(), codes(f.toString(), Optional.of(new StockSize(50, 200, 100)), true));
    }
}
