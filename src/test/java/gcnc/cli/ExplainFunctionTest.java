package gcnc.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * {@code gcnc explain G71 --machine haas}: a G or M code as the control of that machine runs it,
 * the text the studio's hover shows (issue 34).
 */
class ExplainFunctionTest {
    @Test
    void aGCodeOnTheMachinesControl() {
        CliTest.Run r = CliTest.gcnc("explain", "G71", "--machine", "haas");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().startsWith("G71 on control haas: Stock removal cycle O.D. / I.D.\n"), r.out());
        assertTrue(r.out().contains("  es: Ciclo de desbaste exterior / interior\n"), r.out());
        assertTrue(r.out().contains("  one-shot (this block only); gcnc reads it as turning_cycle;"), r.out());
        assertFalse(r.out().contains("fanuc"), r.out()); // that control only
    }

    @Test
    void theWordAsAProgramWritesIt() {
        // g1, G01 and G 1 are the same code
        CliTest.Run r = CliTest.gcnc("explain", "g1", "--control", "fanuc-b");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().startsWith("G01 on control fanuc-b: Linear interpolation\n"), r.out());
        assertTrue(r.out().contains("  modal (group 1); gcnc reads it as linear; parameter words X Z\n"), r.out());
    }

    @Test
    void anMCodeSaysWhenItActs() {
        CliTest.Run r = CliTest.gcnc("explain", "M08", "--machine", "fanuc");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("M08 on control fanuc-a: "), r.out());
        assertTrue(r.out().contains("acts at the start of its block (group 3)"), r.out());
    }

    @Test
    void withNeitherOptionEveryShippedControlThatHasIt() {
        CliTest.Run r = CliTest.gcnc("explain", "G71");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("G71 on control haas: "), r.out());
        assertTrue(r.out().contains("G71 on control fanuc-a: "), r.out());
        assertTrue(r.out().contains("G71 is not a code of control thesis-2004.\n"), r.out());
    }

    @Test
    void aCodeTheControlDoesNotHaveIsStatusTwo() {
        CliTest.Run r = CliTest.gcnc("explain", "G71", "--control", "thesis-2004");
        assertEquals(2, r.status(), r.out());
        assertTrue(r.out().contains("G71 is not a code of control thesis-2004: a program that uses it there gets an error."),
                r.out());
    }

    @Test
    void inSpanish() {
        CliTest.Run r = CliTest.gcnc("explain", "--lang", "es", "M00", "--machine", "haas");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().startsWith("M00 en el control haas: Paro del programa\n  en: Stop program\n"), r.out());
    }

    /** --control alone names the control (issue 34 item 6): M00 as Fanuc system A runs it. */
    @Test
    void aControlAloneIsEnough() {
        CliTest.Run r = CliTest.gcnc("explain", "M00", "--control", "fanuc-a");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().startsWith("M00 on control fanuc-a: Program stop\n  es: Paro programado\n"), r.out());
        assertTrue(r.out().contains("gcnc reads it as stop"), r.out());
    }

    @Test
    void codesOfBothKindsAtOnceAreAUsageError() {
        CliTest.Run r = CliTest.gcnc("explain", "G71", "E642");
        assertEquals(2, r.status(), r.out());
        assertTrue(r.err().contains("explain G and M codes or diagnostic codes, not both at once"), r.err());
    }

    @Test
    void aBrokenProfileIsReportedNotThrown() {
        CliTest.Run r = CliTest.gcnc("explain", "G71", "--machine", "no-such-lathe");
        assertEquals(2, r.status(), r.out());
        assertTrue(r.err().contains("no-such-lathe"), r.err());
        assertFalse(r.err().contains("Exception"), r.err());
    }
}
