package gcnc.send;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.Session;
import gcnc.machine.MachineProfile;
import java.io.BufferedReader;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Which block a poll of the program form names: a poll that finds thread 0 in one of the program's
 * routines (a limit switch sent it to #LIMSWI, then #FAULT, while the axes come to rest) names none,
 * and the block the last poll saw stands. It named the routine's line, of no block, and a limit trip in a
 * blended cut was reported "during line 0" when a poll (every 20 ms) fell inside the stop.
 */
class ProgramFormTest {
    /** ResumeTest's program (line 6 a feed, line 7 an arc) with the routines gcnc compiles after its EN. */
    static final List<String> DMC = routines();
    static final String MAP = ResumeTest.MAP;

    private static List<String> routines() {
        List<String> l = new ArrayList<>(ResumeTest.DMC);
        l.addAll(List.of("#LIMSWI", "MG \"LIMIT SWITCH AT G-CODE LINE\",gline", "JP #FAULT", "#FAULT", "ST", "AM XY",
                "CB1", "EN"));
        return l;
    }

    @Test
    void aPollInsideAFaultsRoutineNamesNoBlockAndTheLastOneStands() throws Exception {
        MachineProfile haas = Session.open(Session.Options.defaults().withMachine("haas")).profile();
        DmcProgram p = DmcProgram.read(DMC, MapReader.read(new BufferedReader(new StringReader(MAP))), haas);
        Download whole = Download.whole(p);
        int feed = lineHolding(whole, "VP 1000,0");
        int limswi = lineHolding(whole, "#LIMSWI");
        int fault = lineHolding(whole, "AM XY");
        int feeding = ProgramForm.executing(whole, feed, 1, p);
        assertEquals(6, p.sourceLine(feeding), "the feed of line 6 runs");
        assertEquals(-1, ProgramForm.executing(whole, limswi, 1, p), whole.lines().get(limswi));
        assertEquals(-1, ProgramForm.executing(whole, fault, 1, p), whole.lines().get(fault));

        Progress progress = new Progress(p, BlockTable.none(), e -> { });
        progress.at(feeding, null, new Operator());
        progress.at(ProgramForm.executing(whole, fault, 1, p), null, new Operator());
        assertEquals(6, progress.executingLine(), "stopped during line 6");
        assertEquals(new ResumePoint(6, 0), progress.resumePoint());
    }

    /** The controller's line (0-based) of the piece that holds {@code text}: where {@code _XQ0} would stand. */
    private static int lineHolding(Download piece, String text) {
        for (int i = 0; i < piece.lines().size(); i++) {
            if (piece.lines().get(i).contains(text)) {
                return i;
            }
        }
        throw new AssertionError(text + " in " + piece.lines());
    }
}
