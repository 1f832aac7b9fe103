package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.Compiler;
import gcnc.Session;
import java.io.StringReader;
import org.junit.jupiter.api.Test;

/**
 * The blocks {@code gcnc run} says it runs are the blocks the compile counted ({@code N blocks ->}): the
 * whole program's, or those from the resume line on in the order the program runs them, a subprogram's
 * once per call. The run used to count the lines that made DMC lines, so one program was "30 blocks" to
 * compile and "17 blocks" to run.
 */
class BlockCountTest {
    /** Lines 1-10 the main program (line 5 and line 7 call O100 of lines 11-14), then the subprogram. */
    static final String CALLS = String.join("\n",
            "O1000", "G21 G99", "T0101", "G97 S1000 M03", // 1-4
            "M98 P100", // 5: the three blocks O100 gives the checker
            "G00 X60. Z5.", // 6
            "M98 P100", // 7: the same three again
            "(a comment line: no block)", // 8
            "M05", "M30", // 9, 10
            "O100", "G01 X50. Z-5. F0.2", "G00 X60. Z5.", "M99", ""); // 11-14

    @Test
    void theRunCountsTheBlocksTheCompileCountedFromWhereItStarts() throws Exception {
        Session session = Session.open(Session.Options.defaults().withMachine("haas"));
        CompiledRun seen = new CompiledRun();
        Compiler.Result r = session.compile(new StringReader(CALLS), java.util.Optional.of(session.simulation()), false,
                line -> { }, seen);
        BlockTable t = seen.blocks(CALLS);
        assertEquals(15, r.blocks(), "nine main-program blocks (the comment line is none) and O100's three twice");
        assertEquals(r.blocks(), t.blocksFrom(0), "the whole program: the compile's count");
        assertEquals(6, t.blocksFrom(7), "line 7's call, O100's three blocks, M05, M30");
        assertEquals(11, t.blocksFrom(5), "both calls with O100's blocks each time, line 6 between them, M05, M30");
        assertEquals(2, t.blocksFrom(9), "M05, M30");
    }
}
