package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.dmc.Instruction;
import java.io.BufferedReader;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * E340 (docs/threading.md, "One groove"): a thread whose passes start off the helix by more than
 * two counts, which a DMC without the phase correction ({@code IP gpu} after each engagement)
 * does. The warning comes once a thread, and a thread is its line in its file: the same line
 * number in a called program's file is another thread.
 */
class ThreadPhaseWarningTest {
    private static final String THREAD = "G76 X48.6 Z-25. K0.9 D0.3 F1.5\n";
    /** Line 6 is a thread; line 8 calls O1000, whose line 6 is another. */
    private static final String MAIN = "G21 G40 G99\nG50 S2000\nT0101\nG97 S800 M03\nG00 X54. Z5.\n" + THREAD
            + "G00 X54. Z5.\nM98 P1000\nG00 X100. Z100.\nM30\n";
    private static final String CALLED = "O1000\nG00 X54. Z5.\nG00 X54. Z4.\nG00 X54. Z5.\nG00 X54. Z5.\n" + THREAD + "M99\n";

    /** The compiled DMC's lines, each with where it came from. */
    private static List<Instruction> compile(Session s) throws Exception {
        List<Instruction> dmc = new ArrayList<>();
        Compiler.Result r = s.compile(new StringReader(MAIN), Optional.of(s.simulation()), false, dmc::add);
        assertTrue(r.ok(), r.diagnostics().sorted().toString());
        assertTrue(r.diagnostics().sorted().stream().noneMatch(d -> d.code() == Code.E340_SIM_THREAD_PHASE));
        return dmc;
    }

    /** E340s of a replay of {@code dmc} with each line at its compile's source, as "O1000.nc:6" or "main:6". */
    private static List<String> phaseWarnings(Session s, List<Instruction> dmc, List<String> text) {
        Diagnostics d = new Diagnostics();
        DmcReplay.replay(new BufferedReader(new StringReader(String.join("\n", text) + "\n")), s.profile(),
                s.simulation(), d, (dmcLine, statement) -> dmc.get(dmcLine - 1).source());
        List<String> out = new ArrayList<>();
        for (Diagnostic f : d.sorted()) {
            if (f.code() == Code.E340_SIM_THREAD_PHASE) {
                String file = f.origin().file() == null ? "main" : Path.of(f.origin().file()).getFileName().toString();
                out.add(file + ":" + f.span().line());
            }
        }
        return out;
    }

    @Test
    void eachThreadWithoutThePhaseCorrectionIsWarnedOfOnceInItsOwnFile() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-phase");
        Files.writeString(dir.resolve("O1000.nc"), CALLED);
        Session s = Session.open(Session.Options.defaults().withMachine("haas")).withPrograms(Optional.of(dir));
        List<Instruction> dmc = compile(s);
        List<String> text = new ArrayList<>();
        dmc.forEach(i -> text.add(i.text()));
        assertEquals(List.of(), phaseWarnings(s, dmc, text)); // as compiled: each pass on the helix
        long corrections = text.stream().filter(t -> t.startsWith("IP gpu")).count();
        assertTrue(corrections >= 4, String.join("\n", text)); // several passes in each of the two threads
        // an older gcnc's DMC: no correction after the engagement (NO keeps every line where the map has it)
        text.replaceAll(t -> t.startsWith("IP gpu") ? "NO" : t);
        assertEquals(List.of("main:6", "O1000.nc:6"), phaseWarnings(s, dmc, text));
    }
}
