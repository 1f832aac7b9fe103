package gcnc.flow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.ir.RawBlock;
import gcnc.machine.ProfileLoader;
import gcnc.parse.BlockReader;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.StringReader;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * Endless macro loops end within the run's stated budget (issue 35: a GOTO loop of a 70-line Haas
 * program went 100,000 passes, 21.5 s and 493 MB, before E149). Bounded in blocks gone through, not
 * in time: {@link ProgramFlow#STEP_LIMIT}; a loop that changes nothing is endless at its second pass.
 */
class LoopBudgetTest {
    /** What a run of the flow did: the blocks it handed on, its own count, and what it reported. */
    record Run(long handedOn, long steps, List<Diagnostic> found) {
    }

    private static Run run(String control, String program) throws IOException {
        Diagnostics d = new Diagnostics();
        ProgramFlow flow;
        try {
            gcnc.machine.MachineProfile m = ProfileLoader.load("generic", TableSource.builtIn(), Tables.builtIn(), control);
            gcnc.machine.Control c = m.control();
            flow = new ProgramFlow(BlockReader.forControl(new StringReader(program), d, c.macros(), c.lineComments()), m, d,
                    Optional.empty());
        } catch (gcnc.tables.TableException e) {
            throw new AssertionError(e);
        }
        long n = 0;
        for (RawBlock b = flow.next(); b != null; b = flow.next()) {
            n++;
        }
        return new Run(n, flow.steps(), d.sorted());
    }

    private static long budget(String program) {
        return ProgramFlow.STEP_LIMIT;
    }

    /** A 70-line program whose GOTO 1 loops back to its N1 (issue 35's reproduction), the body changing {@code change}. */
    private static String gotoLoop(String change) {
        // held from its first macro statement on, as the flow holds a main program (a GOTO can jump back to it)
        StringBuilder p = new StringBuilder("#1 = 0\nN1 G00 X52. Z2.\n");
        for (int i = 3; i <= 67; i++) {
            p.append("G01 Z-").append(i % 20).append(". F0.2\n");
        }
        p.append(change).append("\nGOTO 1\nM30\n");
        assertEquals(70, p.toString().split("\n").length);
        return p.toString();
    }

    @Test
    void aGotoLoopThatChangesNothingIsEndlessAtItsSecondPass() throws IOException {
        // the flow depends on the variables alone: the same variables at the same GOTO run the same pass for ever
        Run r = run("haas", gotoLoop("G00 X52."));
        List<Diagnostic> loops = r.found().stream().filter(d -> d.code() == Code.E149_MACRO_ENDLESS_LOOP).toList();
        assertEquals(1, loops.size(), r.found().toString());
        Diagnostic e = loops.get(0);
        assertEquals(69, e.span().line(), "at the GOTO");
        assertEquals("GOTO 1", e.args().get(0));
        assertEquals("2", e.args().get(2), "its passes");
        assertTrue(r.handedOn() <= 3 * 70, "blocks handed on " + r.handedOn());
    }

    @Test
    void aGotoLoopOfASeventyLineProgramThatNeverEndsEndsWithinItsBudgetNamingTheLoopAndItsPasses() throws IOException {
        // a counter that goes up for ever: each pass differs, so the run's budget ends it
        String program = gotoLoop("#1 = #1 + 1");
        Run r = run("haas", program);
        List<Diagnostic> loops = r.found().stream().filter(d -> d.code() == Code.E710_MACRO_BUDGET).toList();
        assertEquals(1, loops.size(), r.found().toString());
        Diagnostic e = loops.get(0);
        assertEquals(69, e.span().line(), "at the GOTO");
        assertEquals("GOTO 1", e.args().get(0));
        int passes = Integer.parseInt(e.args().get(2));
        long perPass = 68; // the 66 moves, the counter and the GOTO
        assertTrue(Math.abs(passes - budget(program) / perPass) <= 2, "passes " + passes);
        // bounded in blocks: the budget, and a pass's worth past it at most
        assertTrue(r.steps() <= budget(program) + 1, "steps " + r.steps());
        assertTrue(r.handedOn() <= budget(program) + 70, "blocks handed on " + r.handedOn());
    }

    @Test
    void aNestedWhileThatChangesNothingIsEndlessAtTheInnerLoop() throws IOException {
        String program = "#1 = 0\nWHILE [#1 LT 1] DO 1\n#2 = 0\nWHILE [#2 LT 1] DO 2\nG01 X1. F0.2\nEND 2\n"
                + "#1 = #1 + 1\nEND 1\nM30\n";
        Run r = run("fanuc-a", program);
        Diagnostic e = r.found().stream().filter(d -> d.code() == Code.E149_MACRO_ENDLESS_LOOP).findFirst()
                .orElseThrow(() -> new AssertionError(r.found().toString()));
        assertEquals(4, e.span().line(), "the inner WHILE, the one still turning");
        assertTrue(r.handedOn() <= 3, "blocks handed on " + r.handedOn());
    }

    @Test
    void aNestedWhileWhoseInnerCounterNeverReachesItsBoundMeetsItsOwnLimit() throws IOException {
        // a short body whose counter changes every pass: 100,000 passes of the inner loop, long before the budget
        String program = "#1 = 0\nWHILE [#1 LT 1] DO 1\n#2 = 0\nWHILE [#2 GE 0] DO 2\nG01 X1. F0.2\n#2 = #2 + 1\nEND 2\n"
                + "#1 = #1 + 1\nEND 1\nM30\n";
        Run r = run("fanuc-a", program);
        Diagnostic e = r.found().stream().filter(d -> d.code() == Code.E149_MACRO_ENDLESS_LOOP).findFirst()
                .orElseThrow(() -> new AssertionError(r.found().toString()));
        assertEquals(4, e.span().line(), "the inner WHILE, the one still turning");
        assertEquals(String.valueOf(ProgramFlow.LOOP_LIMIT), e.args().get(2));
        assertTrue(r.steps() <= budget(program) + 1, "steps " + r.steps());
    }

    @Test
    void aLoopThatEndsWithinTheBudgetRunsAllItsPasses() throws IOException {
        String program = "#1 = 0\nWHILE [#1 LT 5000] DO 1\nG01 X#1 F0.2\n#1 = #1 + 1\nEND 1\nM30\n";
        Run r = run("fanuc-a", program);
        assertEquals(List.of(), r.found().stream().filter(d -> d.severity() == gcnc.diag.Severity.ERROR).toList());
        assertEquals(5001, r.handedOn(), "5000 moves and M30");
    }
}
