package gcnc.diag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.Session;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/**
 * Waivers a shop signs in its program (issue 31; docs/language.md, "Waivers"): (GCNC ALLOW E642:
 * reason) on a block or on its own line before it, (GCNC ALLOW E642 FILE: reason) for the rest of
 * the file; applied once by gcnc.Session, so every front end reports the same.
 */
class WaiverTest {
    private static final String START = "G21 G40 G99\nG50 S2000\nT0101\nG97 S500 M03\nG00 X50. Z2.\n";
    private static final String CYCLE = "G71 U2. R0.5\nG71 P10 Q20 U0.4 W0.1 F0.25\nN10 G00 X20.\nN20 G01 Z-15.\n";

    private static Session session(String machine) throws TableException {
        return Session.open(Session.Options.defaults().withMachine(machine));
    }

    private static Compiler.Result check(String machine, String program) throws IOException, TableException {
        return session(machine).check(new StringReader(program));
    }

    private static Compiler.Result compile(String machine, String program) throws IOException, TableException {
        Session s = session(machine);
        return s.compile(new StringReader(program), Optional.of(s.simulation()), false, line -> { });
    }

    /** Each finding as line:code, "~" after a waived one's code. */
    private static String found(Compiler.Result r) {
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            out.add(d.span().line() + ":" + d.code().id() + (d.waived() ? "~" : ""));
        }
        return String.join(" ", out);
    }

    private static String gnu(Diagnostic d) {
        return new GnuRenderer(gcnc.tables.Tables.builtIn().messages().in(ErrorMessages.Lang.EN)).render("part.nc", d);
    }

    @Test
    void aWaiverOnItsOwnLineWaivesItsCodeOnTheNextBlockAndSaysSoAsANote() throws Exception {
        String program = Files.readString(Path.of("src/test/resources/waivers/g70-u.fanuc.nc"));
        Compiler.Result r = check("fanuc", program);
        assertEquals("13:E642~", found(r));
        assertEquals(1, r.diagnostics().waivedCount());
        Diagnostic d = r.diagnostics().sorted().get(0);
        assertEquals(Severity.WARNING, d.severity(), "its severity is kept (JSON, SARIF)");
        assertEquals("our post writes U and W in every G70; the control ignores them", d.waiver());
        assertEquals("part.nc:13:13: note[E642] waived: our post writes U and W in every G70; the control ignores them:"
                + " G70: U0.4 does nothing in a G70: the control ignores it (the finishing pass follows the contour as"
                + " written; the allowances belong to the roughing cycle)", gnu(d));
        // without the waiver the same finding is a warning of the run
        Compiler.Result plain = check("fanuc", program.replaceAll("\\(GCNC ALLOW[^)]*\\)", "(a comment)"));
        assertEquals("13:E642", found(plain));
        assertEquals(0, plain.diagnostics().waivedCount());
    }

    @Test
    void aBlockWaiverCoversItsOwnBlockOnlyAndAFileWaiverTheRestOfTheFile() throws Exception {
        String twice = START + CYCLE + "G70 P10 Q20 U0.4 (GCNC ALLOW E642: the post)\nG70 P10 Q20 W0.1\n";
        assertEquals("10:E642~ 11:E642", found(check("fanuc", twice + "M30\n")));
        String file = START + CYCLE + "G70 P10 Q20 U0.4\n(GCNC ALLOW E642 FILE: the post writes them)\n"
                + "G70 P10 Q20 W0.1\nG70 P10 Q20 U0.2\nM30\n";
        assertEquals("10:E642 12:E642~ 13:E642~", found(check("fanuc", file)), "from the waiver's line on, not before");
    }

    @Test
    void aCommentThatSpansLinesIsOneWaiverForTheBlockWhereItEnds() throws Exception {
        String program = "N10 G21 G90\n(GCNC ALLOW E006:\n  the control\n  reads it) N20 G01 X F0.2\nN30 G01 Z F0.2\nN40 M30\n";
        Compiler.Result r = check("thesis-2004", program);
        assertEquals("4:E006~ 5:E006", found(r));
        assertEquals("the control reads it", r.diagnostics().sorted().get(0).waiver());
        assertEquals(1, r.diagnostics().errorCount(), "the waived error is not counted; the other is");
    }

    @Test
    void aWaiverWithoutAReasonOrForAnUnknownCodeOrThatWaivesNothingIsAWarningAndWaivesNothing() throws Exception {
        String program = START + CYCLE + "G70 P10 Q20 U0.4 (GCNC ALLOW E642)\n"
                + "G01 Z-10. F0.2 (GCNC ALLOW E642: nothing here)\n(GCNC ALLOW E999: another tool's)\n"
                + "(GCNC ALLOW everything)\n(GCNC ALLOW E642 FILE: none after)\n(GCNC ALLOW E672 FILE: quiet)\nM30\n";
        assertEquals("10:E642 10:E670 11:E672 12:E671 13:E676 14:E673 15:E677", found(check("fanuc", program)));
    }

    @Test
    void aWaivedErrorPassesCheckButCompileWritesNoDmcWithoutItsBlock() throws Exception {
        String program = START + "G01 X F0.2 (GCNC ALLOW E006: the control reads it)\nM30\n";
        Compiler.Result checked = check("haas", program);
        assertTrue(checked.ok(), found(checked));
        assertEquals("6:E006~", found(checked));
        Compiler.Result compiled = compile("haas", program);
        assertFalse(compiled.ok());
        assertEquals("6:E006~ 6:E675", found(compiled));
    }

    /** A waiver cannot hide a collision: the simulator's E3xx errors stay errors, and the waiver is a warning. */
    @Test
    void aSimulatorCollisionCannotBeWaived() throws Exception {
        String program = START + "G00 X160.\nG00 Z-155. (GCNC ALLOW E303: the chuck is smaller)\nG00 X100.\nM30\n";
        Compiler.Result r = compile("haas", program);
        assertFalse(r.ok(), found(r));
        assertTrue(found(r).contains(":E303 ") || found(r).endsWith(":E303"), found(r));
        assertFalse(found(r).contains("E303~"), found(r));
        assertTrue(found(r).contains("7:E674"), found(r));
        // check, which does not simulate, says the same of the waiver
        assertEquals("7:E674", found(check("haas", program)));
    }

    /** A waiver in a called program's own file waives the findings in that file. */
    @Test
    void aWaiverInACalledProgramsFileWaivesThere() throws Exception {
        Path dir = Files.createTempDirectory("gcnc-waiver");
        Files.writeString(dir.resolve("O1000.nc"), "O1000\nG70 P10 Q20 U0.4 (GCNC ALLOW E642: the post)\nM99\n");
        String main = START + CYCLE + "M98 P1000\nM30\n";
        Compiler.Result r = session("fanuc").withPrograms(Optional.of(dir)).check(new StringReader(main));
        List<Diagnostic> waived = r.diagnostics().sorted().stream().filter(Diagnostic::waived).toList();
        assertEquals(1, waived.size(), found(r));
        assertTrue(waived.get(0).origin().file().endsWith("O1000.nc"), waived.get(0).origin().toString());
    }

    /** The codes that cannot be waived are exactly the simulator's errors in errors.csv (and the waivers' own). */
    @Test
    void theUnwaivableCodesAreTheSimulatorsErrors() throws Exception {
        for (gcnc.tables.CodeTable.Entry e : gcnc.tables.CodeTable.load(gcnc.tables.TableSource.builtIn()).entries()) {
            int n = e.code().number();
            boolean expected = n >= 300 && n <= 399 && e.severity() == Severity.ERROR || n >= 670 && n <= 679;
            assertEquals(expected, Waivers.unwaivable(e.code()), e.code().id());
        }
    }
}
