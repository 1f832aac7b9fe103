package gcnc.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.galil.Dialect;
import gcnc.machine.MachineProfile;
import gcnc.tables.Tables;
import java.io.BufferedReader;
import java.io.StringReader;
import java.util.List;
import java.util.Optional;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;

/**
 * Continuous G32 threads (docs/threading.md, "Continuous threads"): consecutive G32 blocks are
 * one geared sequence, synchronised once, the ratios changing at each joint; the compile and a
 * replay of its DMC alone are clean; a G32 that continues a thread across a block with an M, S or
 * T word is E627, one with another lead E628.
 */
class ThreadContinuousTest {
    private static final String HEAD = "(80.00 24.00)\nG21 G99\nT0303\nG97 S700 M03\nG00 X30. Z5.\nX23.\n";

    private static Compiler.Result compile(String program, StringBuilder dmc) throws Exception {
        MachineProfile p = ReplayTest.profile("fanuc");
        Compiler.Settings s = new Compiler.Settings(Tables.builtIn(), p, Dialect.Kind.GALIL, Optional.of(SimOptions.defaults()),
                false);
        return Compiler.compile(new StringReader(program), s, l -> dmc.append(l.text()).append('\n'));
    }

    private static String errors(Compiler.Result r) {
        return r.diagnostics().sorted().stream().filter(d -> d.severity() == gcnc.diag.Severity.ERROR)
                .map(d -> d.span().line() + ":" + d.code().id()).collect(Collectors.joining(", "));
    }

    private static long count(String dmc, String what) {
        return dmc.lines().filter(l -> l.startsWith(what)).count();
    }

    @Test
    void aThreadAndItsPullOutAreOneGearedSequence() throws Exception {
        StringBuilder dmc = new StringBuilder();
        // the straight thread, its 45-degree pull-out (modal G32), then the thread's third block
        Compiler.Result r = compile(HEAD + "G32 Z-25. F1.5\nX26. Z-26.5\nX27. Z-27.5\nG00 X30.\nZ5.\nM30\n", dmc);
        assertEquals("", errors(r), r.diagnostics().sorted()::toString);
        assertEquals(0, r.simulation().orElseThrow().findings());
        String d = dmc.toString();
        assertEquals(1, count(d, "GA "), d); // geared once, synchronised once
        assertEquals(1, count(d, "gsp="), d);
        assertEquals(4, count(d, "GR "), d); // three segments and the disengagement
        assertEquals(1, count(d, "PA "), d);
        Diagnostics alone = new Diagnostics();
        DmcReplay.replay(new BufferedReader(new StringReader(d)), ReplayTest.profile("fanuc"), SimOptions.defaults(),
                alone);
        assertEquals(List.of(), ReplayTest.codes(alone));
        // two passes written apart (a rapid between): two geared sequences, as before
        StringBuilder two = new StringBuilder();
        assertEquals("", errors(compile(HEAD + "G32 Z-25. F1.5\nG00 X30.\nZ5.\nX22.6\nG32 Z-25.\nG00 X30.\nZ5.\nM30\n",
                two)));
        assertEquals(2, count(two.toString(), "GA "));
    }

    /** Blocks with only an N or an F may stand between the thread's blocks (Fanuc programs number every block). */
    @Test
    void aBlockWithoutAMoveOrAnMBetweenKeepsTheThread() throws Exception {
        StringBuilder dmc = new StringBuilder();
        Compiler.Result r = compile(HEAD + "N10 G32 Z-25. F1.5\nN20\nN30 X26. Z-26.5\nG00 X30.\nZ5.\nM30\n", dmc);
        assertEquals("", errors(r));
        assertEquals(1, count(dmc.toString(), "GA "));
    }

    @Test
    void anMBetweenIsE627AndAnotherLeadE628() throws Exception {
        assertEquals("9:E627", errors(compile(HEAD + "G32 Z-25. F1.5\nM08\nX26. Z-26.5\nG00 X30.\nZ5.\nM30\n",
                new StringBuilder())));
        assertEquals("8:E628", errors(compile(HEAD + "G32 Z-25. F1.5\nX26. Z-26.5 F1.25\nG00 X30.\nZ5.\nM30\n",
                new StringBuilder())));
        List<Diagnostic> none = compile(HEAD + "G32 Z-25. F1.5\nG00 X30.\nM30\n", new StringBuilder()).diagnostics()
                .sorted();
        assertTrue(none.stream().noneMatch(x -> x.severity() == gcnc.diag.Severity.ERROR), none::toString);
    }
}
