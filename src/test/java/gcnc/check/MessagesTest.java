package gcnc.check;

import static org.junit.jupiter.api.Assertions.assertEquals;

import gcnc.diag.Diagnostic;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Messages that lead to the fix (issue 9): the limit a word broke and where it comes from, the
 * value that would have worked, the word as written, and a column at the word to blame. Programs
 * as in {@link ErrorsTest}: '|' separates lines, '$|' is its preamble, an M30 line is appended.
 */
class MessagesTest {
    /** Every finding as "line:column text", in English. */
    private static String messages(Run r) {
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics.sorted()) {
            out.add(d.span().line() + ":" + d.span().column() + " "
                    + Run.TABLES.messages().render(d.code(), d.args(), ErrorMessages.Lang.EN));
        }
        return String.join("\n", out);
    }

    private static String generic(String program) {
        return messages(ErrorsTest.run(program));
    }

    // ---- E015: the travel, in the block's own terms, and the machine it belongs to ----

    @Test
    void theTravelIsGivenFromTheWorkOriginWithXAsADiameter() {
        // generic: Z travel 0..350 mm with G54's work zero at Z 150; X -2..110 mm as a radius
        assertEquals("1:5 Z-170. is beyond the Z travel -150..200 of machine generic", generic("G00 Z-170."));
        assertEquals("1:5 X300. is beyond the X travel -4..220 of machine generic", generic("G00 X300."));
    }

    @Test
    void theTravelMovesWithTheBlocksOwnWorkAndToolOffsets() {
        // G55's work zero is at Z 140; tool offset 3 moves the origin 0.2 mm on both axes
        assertEquals("1:9 Z-150. is beyond the Z travel -140..210 of machine generic", generic("G55 G00 Z-150."));
        assertEquals("1:11 X221. is beyond the X travel -4.4..219.6 of machine generic", generic("T0303 G00 X221."));
    }

    @Test
    void theTravelIsInTheBlocksUnitsRoundedInward() {
        // -150 mm = -5.90551 in, shown -5.9055 (reachable), 200 mm = 7.87401 in, shown 7.874
        assertEquals("1:9 Z-6. is beyond the Z travel -5.9055..7.874 of machine generic", generic("G20 G00 Z-6."));
    }

    @Test
    void incrementalWordsAndG28AreNamedAgainstTheSameTravel() {
        assertEquals("2:5 U500. is beyond the X travel -4..220 of machine generic", generic("G00 X40.|G00 U500."));
        assertEquals("1:5 W-400. is beyond the Z travel -150..200 of machine generic", generic("G28 W-400."));
    }

    @Test
    void g53GivesTheTravelInMachineCoordinates() throws TableException {
        // generic's machine zero is its reference point (105, 340 mm): X -214..10 as a diameter, Z -340..10
        MachineProfile genericOnHaas = ProfileLoader.load("generic", TableSource.builtIn(), Run.TABLES, "haas");
        Run r = Run.of(genericOnHaas, "G53 X400.\nG53 Z-400.\nM30", Checker.ERROR_CAP);
        assertEquals("1:5 X400. is beyond the X travel -214..10 of machine generic\n"
                + "2:5 Z-400. is beyond the Z travel -340..10 of machine generic", messages(r));
    }

    @Test
    void anSAboveTheMachinesMaximumNamesItAndTheMachine() {
        assertEquals("2:1 S4500 is above the machine's maximum 4000 rpm (machine generic)", generic("G50 S5000|S4500"));
    }

    // ---- E101: the radius that would span the chord ----

    @Test
    void aShortRadiusIsToldTheSmallestThatSpansTheChord() {
        // X40 Z-30 to X50 Z-60: 5 mm across, 30 along, chord 30.4138 mm; half of it rounded up
        assertEquals("7:16 arc radius R3. cannot span a chord 30.414 long: the smallest radius is R15.207",
                generic("$|G00 X40. Z-30.|G02 X50. Z-60. R3. F100."));
        // the long way round keeps its sign; a whole radius keeps its point (R15 would be 0.015 mm)
        assertEquals("7:16 arc radius R-3. cannot span a chord 30 long: the smallest radius is R-15.",
                generic("$|G00 X40. Z-30.|G02 X40. Z-60. R-3. F100."));
    }

    // ---- columns: the word to blame, not the last word ----

    @Test
    void aCutBeforeItsPrerequisitesIsReportedAtItsMotionWord() {
        String noSpindle = "G21 G90 G98|G50 S2500|M11|T0101|";
        // the thesis reported these at the last word: F100. and X40.
        assertEquals("5:5:E051", ErrorsTest.run(noSpindle + "N50 G01 X40. F100.").errors());
        assertEquals("6:1:E039", ErrorsTest.run("$|G01 X40.").errors());
        // under a modal G01 the first axis word is the one that moves
        assertEquals("6:5:E051", ErrorsTest.run(noSpindle + "G01 F100.|N60 Z-10. F90.").errors());
        assertEquals("7:5:E660", ErrorsTest.run(noSpindle + "G01 X40. F100. M03|M05|N70 Z-10. F90.").errors());
        assertEquals("8:5:E037", ErrorsTest.run(noSpindle + "G01 X40. F100. M03|M05|G99|N70 Z-10. F0.2").errors());
    }

    @Test
    void anSRuleIsReportedAtTheS() {
        assertEquals("6:5:E048", ErrorsTest.run("$|M03 S3000").errors());
        assertEquals("1:5:E050", ErrorsTest.run("M03 S100").errors());
    }

    @Test
    void aMissingArcRadiusIsReportedAtTheArcsG() {
        assertEquals("7:5:E049", ErrorsTest.run("$|G00 X40. Z0.|N70 G02 X46. Z-33. F100.").errors());
    }

    // ---- the letter O for a zero where it still lexes: Z-1O0 is Z-1 and a program number O0 ----

    @Test
    void anOWrittenAgainstANumberIsAZeroTypedAsALetter() {
        String p = "G00 X40. Z2.\nG00 Z-1O0 X42.\nM30\n";
        // not "program name defined after the program has started", and no warning about Z-1's point
        assertEquals("p.nc:2:5: error[E120]: Z-1O0: the letter O in a number (did you mean Z-100?)",
                ControlRulesTest.messages("generic", "fanuc-a", p));
        // in the first block too: Z-1O5 is not Z-1 in a program named O5
        assertEquals("1:5:E120", ControlRulesTest.check("generic", "fanuc-a", "G00 Z-1O5 X42.\nM30\n"));
        // an O word on its own is still a program name in the wrong place
        assertEquals("2:5:E034", ControlRulesTest.check("generic", "fanuc-a", "G00 X40.\nG00 O100\nM30\n"));
    }

    // ---- numbers as written ----

    @Test
    void hugeNumbersComeBackExactlyAsTyped() {
        assertEquals("1:1 parameter S too large: 12345678901234567890 is above 99999",
                generic("S12345678901234567890"));
        assertEquals("1:1 tool number 123456789012345678 not defined", generic("T12345678901234567890"));
        assertEquals("1:1 parameter X too large: 123456789012345678901234567890. is above 20077.77777",
                generic("X123456789012345678901234567890."));
    }

    @Test
    void limitsAndWordsAreNotReformatted() {
        // the F limit is 0.0001, not Double's 1.0E-4; N0010 stays N0010
        assertEquals("1:1 parameter F too small: 0 is below 0.0001", generic("F0"));
        assertEquals("2:1 line number N0005 must be greater than the previous one: N10", generic("N0010|N0005"));
        assertEquals("1:1 tool offset 99 out of range", generic("T0199"));
    }
    // ---- E103: a feed in the program's terms (F as written, per minute in its units), counts second ----

    @Test
    void aFeedPerRevolutionAboveTheMaximumIsGivenPerRevolutionAndPerMinute() {
        // generic: feed.max 50000 counts/s at 1000 counts/mm = 3000 mm/min; F2. mm/rev at 2500 rpm is 5000 mm/min
        assertEquals("7:11 feed F2. mm/rev × 2500 rpm moves the tool at 5000 mm/min: above the machine's maximum feed"
                + " of 3000 mm/min (83333.333 counts/s; at most 50000)",
                generic("G21 G90 G99|G50 S2500|M11|T0101|S2500 M03|G00 X40. Z2.|G01 Z-10. F2."));
    }

    @Test
    void anInchFeedPerMinuteAboveTheMaximumIsGivenInInchesPerMinute() {
        // 200 in/min = 5080 mm/min; the maximum 3000 mm/min = 118.11 in/min
        assertEquals("7:10 feed F200. in/min moves the tool at 200 in/min: above the machine's maximum feed"
                + " of 118.11 in/min (84666.667 counts/s; at most 50000)",
                generic("G20 G90 G98|G50 S2500|M11|T0101|S1000 M03|G00 X1.6 Z0.1|G01 Z-1. F200."));
    }
}
