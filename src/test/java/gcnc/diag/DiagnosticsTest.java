package gcnc.diag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Folding and caps, for every stage alike (issue 18): one finding per cause and place, one cap per run. */
class DiagnosticsTest {
    private static String codes(Diagnostics d) {
        List<String> out = new ArrayList<>();
        for (Diagnostic x : d.sorted()) {
            out.add(x.span().line() + ":" + x.span().column() + ":" + x.code().id()
                    + (x.code() == Code.E680_FOLDED || x.code() == Code.E116_ERROR_CAP ? "(" + x.args().get(0) + ")" : ""));
        }
        return String.join(", ", out);
    }

    @Test
    void theSameErrorAtTheSamePlaceIsKeptOnceWithItsCount() {
        Diagnostics d = new Diagnostics();
        for (int pass = 0; pass < 2000; pass++) {
            d.error(Code.E146_MACRO_NO_VALUE, Span.of(7, 5), "X#24");
            d.error(Code.E011_UNDEFINED_G, Span.of(8, 1), "G07");
        }
        assertEquals("7:5:E146, 7:5:E680(2000), 8:1:E011, 8:1:E680(2000)", codes(d));
        assertEquals(2, d.errorCount(), "a folded repeat is not another error");
        assertEquals(2, d.size());
    }

    @Test
    void aNoteThatGoesWithAFoldedFindingGoesWithItAndTheCountComesAfterTheNotes() {
        Diagnostics d = new Diagnostics();
        for (int pass = 1; pass <= 3; pass++) {
            d.error(Code.E039_FEED_NOT_SET, Span.of(4, 1));
            d.report(new Diagnostic(Code.E165_CYCLE_PASS, Severity.NOTE, Span.of(4, 1), List.of("G71", "" + pass, "x")));
        }
        assertEquals("4:1:E039, 4:1:E165, 4:1:E680(3)", codes(d));
    }

    @Test
    void aCountFromAnotherCollectionAddsUp() {
        Diagnostics block = new Diagnostics();
        Diagnostics run = new Diagnostics();
        for (int pass = 0; pass < 3; pass++) {
            block.clear();
            block.error(Code.E146_MACRO_NO_VALUE, Span.of(2, 3), "X#1");
            block.error(Code.E146_MACRO_NO_VALUE, Span.of(2, 3), "X#1");
            for (Diagnostic x : block.sorted()) {
                run.report(x);
            }
        }
        assertEquals("2:3:E146, 2:3:E680(6)", codes(run));
    }

    @Test
    void pastTheCapOneE116AndNothingMoreIsKept() {
        Diagnostics d = new Diagnostics();
        for (int line = 1; line <= Diagnostics.ERROR_CAP + 500; line++) {
            d.error(Code.E146_MACRO_NO_VALUE, Span.of(line, 1), "X#1");
        }
        d.error(Code.E116_ERROR_CAP, Span.of(20_000, 1), 10_500); // the checker's own, once the cap is reached
        assertEquals(Diagnostics.ERROR_CAP + 1, d.size());
        assertEquals(Diagnostics.ERROR_CAP + 500, d.errorCount());
        assertTrue(d.capped());
        List<Diagnostic> all = d.sorted();
        assertEquals(1, all.stream().filter(x -> x.code() == Code.E116_ERROR_CAP).count(), "the cap's note once");
        assertEquals((Diagnostics.ERROR_CAP + 1) + ":1:E116", all.get(all.size() - 1).span().line() + ":1:"
                + all.get(all.size() - 1).code().id());
    }

    @Test
    void warningsAndNotesHaveACapOfTheirOwn() {
        Diagnostics d = new Diagnostics();
        for (int line = 1; line <= Diagnostics.OTHER_CAP + 10; line++) {
            d.report(Diagnostic.warning(Code.E113_M_WITHOUT_OUTPUT, Span.of(line, 1), 7, "generic"));
        }
        assertEquals(Diagnostics.OTHER_CAP + 1, d.size());
        assertEquals(1, d.sorted().stream().filter(x -> x.code() == Code.E681_OTHER_CAP).count());
        assertEquals(0, d.errorCount());
    }
}
