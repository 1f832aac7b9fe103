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

    /** Issue 22: a warning repeated elsewhere with the same code and arguments is kept once, with E115 and the lines. */
    @Test
    void aRepeatedWarningIsFoldedIntoItsFirstWithTheLaterLines() {
        Diagnostics d = new Diagnostics();
        for (int line : new int[] {4, 10, 12}) {
            d.report(Diagnostic.warning(Code.E204_SPINDLE_VOLTS_CLAMPED, Span.of(line, 1), "4000", "10.0000"));
        }
        d.report(Diagnostic.warning(Code.E204_SPINDLE_VOLTS_CLAMPED, Span.of(14, 1), "3999", "9.9990"));
        d.error(Code.E051_SPINDLE_DIRECTION, Span.of(20, 1));
        d.error(Code.E051_SPINDLE_DIRECTION, Span.of(21, 1));
        assertEquals("4:1:E204, 4:1:E115, 14:1:E204, 20:1:E051, 21:1:E051", codes(d));
        Diagnostic note = d.sorted().get(1);
        assertEquals(List.of("2", "10, 12"), note.args());
        assertEquals("2 later blocks have the same cause (lines 10, 12)", gcnc.tables.Tables.builtIn().messages()
                .render(note.code(), note.args(), gcnc.tables.ErrorMessages.Lang.EN));
        assertEquals(2, d.errorCount(), "errors are not folded across places");
    }

    @Test
    void aFoldedWarningsNotesAndItsLaterLinesSurviveAWithdrawal() {
        Diagnostics d = new Diagnostics();
        d.report(Diagnostic.warning(Code.E660_FEED_SPINDLE_STOPPED_NOT_JUDGED, Span.of(3, 1), "M05"));
        d.report(Diagnostic.warning(Code.E107_NO_DECIMAL_POINT, Span.of(5, 5), "X20", "0.02", "mm", "20"));
        for (int line = 6; line < 20; line++) {
            d.report(Diagnostic.warning(Code.E107_NO_DECIMAL_POINT, Span.of(line, 5), "X20", "0.02", "mm", "20"));
        }
        d.withdraw(x -> x.code() == Code.E660_FEED_SPINDLE_STOPPED_NOT_JUDGED);
        assertEquals("5:5:E107, 5:5:E115", codes(d));
        assertEquals(List.of("14", "6, 7, 8, 9, 10, 11, 12, 13, 14, 15, ..."), d.sorted().get(1).args());
        d.report(Diagnostic.warning(Code.E107_NO_DECIMAL_POINT, Span.of(30, 5), "X20", "0.02", "mm", "20"));
        assertEquals(List.of("15", "6, 7, 8, 9, 10, 11, 12, 13, 14, 15, ..."), d.sorted().get(1).args());
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
            // a different M each time: the same warning with the same words elsewhere would be folded
            d.report(Diagnostic.warning(Code.E113_M_WITHOUT_OUTPUT, Span.of(line, 1), line, "generic"));
        }
        assertEquals(Diagnostics.OTHER_CAP + 1, d.size());
        assertEquals(1, d.sorted().stream().filter(x -> x.code() == Code.E681_OTHER_CAP).count());
        assertEquals(0, d.errorCount());
    }
}
