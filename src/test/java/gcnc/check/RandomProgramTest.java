package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.CheckedBlock;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.MachineProfile;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Seeded word soup: the checker never throws, and each block is either accepted without a
 * finding or rejected with exactly one numbered diagnostic; a rejected block keeps the state,
 * unless what it broke was only a prerequisite (the codes of end-of-block checks 7 and 8).
 */
class RandomProgramTest {
    private static final String[] NUMBERS = {"", "0", "1", "01", "03", "30", "00", "5", "10", "11", "20", "28",
        "29", "50", "92", "96", "97", "99", "1.5", "-2.", "+3", "-.5", ".", "-", "1.2.3", "0101", "9999999999999999999",
        "12345678901234567890.5", "x", "40.", "-30.", "1e5", "2500", "1200"};
    private static final Letter[] LETTERS = Letter.values();
    /** Codes of Eb07 and Eb08 (tables/block_checks.csv); 15 is also raised by other rules. */
    private static final java.util.Set<Integer> PREREQUISITE = java.util.Set.of(15, 37, 38, 39, 41, 48, 50, 51);
    /**
     * Codes of the move itself (MotionBuilder): the block's words were sound, so its end point may
     * stand (issue 17); and 25, the thesis's R on a G01, whose block is sound without it (issue 31).
     */
    private static final java.util.Set<Integer> MOVE = java.util.Set.of(15, 25, 101, 102, 103, 104, 105, 106, 117, 122);

    @ParameterizedTest(name = "seed {0}")
    @ValueSource(longs = {1, 2, 3, 42, 2004, 31337})
    void neverThrowsAndEveryRejectionIsOneDiagnostic(long seed) {
        Random rnd = new Random(seed);
        for (String profile : new String[] {"generic", "thesis-2004"}) {
            MachineProfile p = Run.profile(profile);
            for (int prog = 0; prog < 100; prog++) {
                Diagnostics out = new Diagnostics();
                Checker c = new Checker(Run.TABLES, p, out);
                for (int line = 1; line <= 40; line++) {
                    RawBlock b = block(rnd, line);
                    int before = out.errorCount();
                    ModalState state = c.state();
                    Optional<CheckedBlock> r = c.check(b).stream().findFirst();
                    String where = "seed " + seed + " " + profile + " program " + prog + " line " + line + ": " + b.words();
                    if (r.isPresent()) {
                        assertEquals(before, out.errorCount(), where);
                    } else if (out.errorCount() > before) {
                        // (no new error: a prerequisite broken again, folded into its first report, E115)
                        assertEquals(before + 1, out.errorCount(), where);
                        int l = line;
                        int code = out.sorted().stream().filter(d -> d.span().line() == l)
                                .filter(d -> d.severity() == gcnc.diag.Severity.ERROR).findFirst()
                                .orElseThrow().code().number();
                        if (!PREREQUISITE.contains(code)) {
                            assertOnlyModalWordsKept(state, c.state(), b, MOVE.contains(code), p, where);
                        }
                    }
                }
                c.finish(40);
                assertTrue(out.sorted().stream().allMatch(d -> d.code().number() > 0));
            }
        }
    }

    /**
     * A block rejected for its form keeps only its unambiguous modal words (Salvage): never a tool,
     * its motion G only when it is the block's one motion G, and a move only when its words were
     * sound and the move itself failed ({@code moved}: the codes of {@link #MOVE}), never beyond the travel.
     */
    private static void assertOnlyModalWordsKept(ModalState before, ModalState after, RawBlock b, boolean moved,
                                                 MachineProfile p, String where) {
        if (!moved) {
            assertEquals(before.position(), after.position(), where);
        } else {
            assertTrue(after.position().equals(before.position())
                    || p.x().inTravel(after.position().x()) && p.z().inTravel(after.position().z()), where);
        }
        List<Integer> motions = new ArrayList<>();
        for (Word w : b.words()) {
            if (w.letter() == Letter.G && !w.number().isEmpty() && w.code() >= 0 && w.code() <= 3) {
                motions.add((int) w.code());
            }
        }
        assertTrue(after.motion() == before.motion() || motions.size() == 1 && after.motion() == motions.get(0),
                where + ": motion " + after.motion());
        assertEquals(before.tool(), after.tool(), where);
        assertEquals(before.toolOffset(), after.toolOffset(), where);
        assertEquals(before.shift(), after.shift(), where);
        assertEquals(before.g28(), after.g28(), where);
        assertEquals(before.lastN(), after.lastN(), where);
        assertEquals(before.named(), after.named(), where);
        assertEquals(before.ended(), after.ended(), where);
    }

    private static RawBlock block(Random rnd, int line) {
        int n = 1 + rnd.nextInt(6);
        List<Word> words = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Letter l = LETTERS[rnd.nextInt(LETTERS.length)];
            words.add(new Word(l, NUMBERS[rnd.nextInt(NUMBERS.length)], Span.of(line, 1 + 6 * i)));
        }
        return new RawBlock(line, words, words.get(n - 1).span(), false);
    }
}
