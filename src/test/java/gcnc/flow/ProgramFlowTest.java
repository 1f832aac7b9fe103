package gcnc.flow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.GnuRenderer;
import gcnc.galil.Dialect;
import gcnc.ir.RawBlock;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.parse.BlockReader;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;

/**
 * Subprograms, one tiny program per behaviour: the order the blocks run in (line and call depth),
 * and what is reported where. Programs are written the way Fanuc and Haas programs store
 * subprograms: after the main program's M30, each from its O word to its M99.
 */
class ProgramFlowTest {
    private static final Tables TABLES = Tables.builtIn();
    /** A folder of its own per test, for the files beside a program. */
    private Path dir;

    @BeforeEach
    void folder() throws IOException {
        dir = Files.createTempDirectory("gcnc-flow");
    }

    @AfterEach
    void removeFolder() throws IOException {
        try (java.util.stream.Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(java.util.Comparator.reverseOrder()).toList()) {
                Files.delete(p);
            }
        }
    }

    /** Lines 1-5 of a main program that has cut nothing yet; O1000, a called program of 5 lines. */
    private static final String START = "O0001\nG00 G21 G99\nT0101\nG97 S800 M03\nG00 X52. Z2.\n";
    private static final String O1000 = "O1000\nG01 Z-20. F0.2\nG00 X54.\nZ2.\nM99\n";

    private static MachineProfile machine(String control) {
        try {
            return ProfileLoader.load("generic", TableSource.builtIn(), TABLES, control);
        } catch (TableException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    /** The blocks as the flow hands them on: "line" or "line/depth" for a block in a call, space separated. */
    private static String order(String control, String program) {
        Diagnostics d = new Diagnostics();
        ProgramFlow flow = new ProgramFlow(new BlockReader(new StringReader(program), d), machine(control),
                d, Optional.empty());
        List<String> out = new ArrayList<>();
        try {
            for (RawBlock b = flow.next(); b != null; b = flow.next()) {
                out.add(b.depth() == 0 ? Integer.toString(b.line()) : b.line() + "/" + b.depth());
            }
        } catch (IOException e) {
            throw new AssertionError(e);
        }
        return String.join(" ", out);
    }

    private static Compiler.Result check(String control, String program, Optional<Path> folder) {
        Compiler.Settings s = new Compiler.Settings(TABLES, machine(control), Dialect.Kind.GALIL, Optional.empty());
        if (folder.isPresent()) {
            s = s.withPrograms(folder.get());
        }
        try {
            return Compiler.check(new StringReader(program), s);
        } catch (IOException e) {
            throw new AssertionError(e);
        }
    }

    /** Every finding as "line:column:Ennn" (with "file:" when it is in another file), in the order the CLI prints them. */
    private static String codes(String control, String program) {
        return codes(check(control, program, Optional.empty()));
    }

    private static String codes(Compiler.Result r) {
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            String file = d.origin().file() == null ? "" : Path.of(d.origin().file()).getFileName() + ":";
            out.add(file + d.span().line() + ":" + d.span().column() + ":" + d.code().id());
        }
        return String.join(", ", out);
    }

    /** The findings as the command line prints them for a program file p.nc. */
    static String messages(Compiler.Result r) {
        GnuRenderer g = new GnuRenderer(TABLES.messages().in(ErrorMessages.Lang.EN));
        List<String> out = new ArrayList<>();
        for (Diagnostic d : r.diagnostics().sorted()) {
            out.add(g.render("p.nc", d));
        }
        return String.join("\n", out);
    }

    // ---- calls and repeats ----

    @Test
    void m98RunsTheProgramAfterTheMainProgramsEndAndComesBack() {
        String p = START + "M98 P1000\nG00 X100. Z100.\nM30\n" + O1000;
        assertEquals("1 2 3 4 5 6 10/1 11/1 12/1 13/1 7 8", order("fanuc-a", p));
        assertEquals("", codes("fanuc-a", p));
        assertEquals("", codes("haas", p));
        assertEquals(12, check("haas", p, Optional.empty()).blocks(), "blocks as run: 8 of the main program, 4 of O1000");
    }

    @Test
    void fanucPWithMoreThanFourDigitsHoldsTheRepeatCount() {
        String p = START + "M98 P21000\nG00 X100. Z100.\nM30\n" + O1000;
        assertEquals("1 2 3 4 5 6 10/1 11/1 12/1 13/1 10/1 11/1 12/1 13/1 7 8", order("fanuc-a", p));
        assertEquals("", codes("fanuc-a", p));
        // on a Haas, P is the program number alone: O21000, which this file does not have
        assertEquals("6:5:E130, 9:1:E138", codes("haas", p));
    }

    @Test
    void lIsTheRepeatCount() {
        String p = START + "M98 P1000 L3\nG00 X100. Z100.\nM30\n" + O1000;
        String thrice = "1 2 3 4 5 6 10/1 11/1 12/1 13/1 10/1 11/1 12/1 13/1 10/1 11/1 12/1 13/1 7 8";
        assertEquals(thrice, order("haas", p));
        assertEquals(thrice, order("fanuc-a", p));
        assertEquals("", codes("haas", p));
    }

    @Test
    void aRepeatCountIsOneTo9999AndGivenOnce() {
        // the call is not made: O1000 (line 8) is never called
        assertEquals("6:11:E135, 8:1:E138", codes("haas", START + "M98 P1000 L0\nM30\n" + O1000));
        assertEquals("6:11:E135, 8:1:E138", codes("haas", START + "M98 P1000 L2.\nM30\n" + O1000));
        assertEquals("6:12:E143, 8:1:E138", codes("fanuc-a", START + "M98 P21000 L2\nM30\n" + O1000));
        assertEquals("6:5:E135, 8:1:E138", codes("fanuc-a", START + "M98 P100001000\nM30\n" + O1000));
    }

    @Test
    void theMoveOfACallBlockRunsBeforeTheCall() {
        String p = "O0001\nG00 G21 G99\nT0101\nG97 S800 M03\nG00 X52. Z2. M98 P1000\nG00 X100. Z100.\nM30\n" + O1000;
        assertEquals("1 2 3 4 5 9/1 10/1 11/1 12/1 6 7", order("haas", p));
        assertEquals("", codes("haas", p));
    }

    // ---- nesting ----

    @Test
    void callsNest() {
        String p = START + "M98 P1000\nM30\nO1000\nG01 Z-1. F0.2\nM98 P2000\nM99\nO2000\nG00 Z2.\nM99\n";
        assertEquals("1 2 3 4 5 6 9/1 10/1 13/2 14/2 11/1 7", order("fanuc-a", p));
        assertEquals("", codes("fanuc-a", p));
    }

    @Test
    void callsNestFourDeepAndNoDeeper() {
        StringBuilder p = new StringBuilder(START + "M98 P1001\nM30\n");
        int deepest = 5;
        for (int n = 1; n <= deepest; n++) {
            p.append("O100").append(n).append('\n');
            p.append(n < deepest ? "M98 P100" + (n + 1) + "\n" : "G00 Z2.\n").append("M99\n");
        }
        // O1001 at line 8, its M98 at line 9; O1004's M98 P1005 at line 18
        // the call is in O1004, four calls deep: a note for each; O1005 is never reached
        assertEquals("18:1:E134, 18:1:E136, 18:1:E136, 18:1:E136, 18:1:E136, 20:1:E138", codes("fanuc-a", p.toString()));
        assertTrue(messages(check("fanuc-a", p.toString(), Optional.empty()))
                .contains("p.nc:18:1: error[E134]: calls nested deeper than 4 levels (O1001 > O1002 > O1003 > O1004 > O1005)"));
        // four levels are fine (O1005 is then never called)
        String four = p.toString().replace("M98 P1005", "G00 Z3.");
        assertEquals("20:1:E138", codes("fanuc-a", four));
    }

    @Test
    void aProgramThatCallsItselfIsReportedAtTheCall() {
        String direct = START + "M98 P1000\nM30\nO1000\nG00 Z2.\nM98 P1000\nM99\n";
        assertEquals("10:1:E133, 10:1:E136", codes("fanuc-a", direct));
        String indirect = START + "M98 P1000\nM30\nO1000\nM98 P2000\nM99\nO2000\nM98 P1000\nM99\n";
        Compiler.Result r = check("fanuc-a", indirect, Optional.empty());
        assertEquals("12:1:E133, 12:1:E136, 12:1:E136", codes(r));
        assertTrue(messages(r).contains("p.nc:12:1: error[E133]: O1000 calls itself (O1000 > O2000 > O1000)"), messages(r));
        // the main program's own number
        assertEquals("6:1:E133", codes("fanuc-a", START + "M98 P1\nM30\n"));
    }

    // ---- issue 18: the origin of an end in a called program, what is not a file ----

    @Test
    void anEndCodeInACalledFileIsReportedThereNotOnTheCallersLines() throws IOException {
        // the caller's correct lines 7-10 were each E053 "M30 can only be at the end"
        Files.writeString(dir.resolve("O1000.nc"), "O1000\nG01 Z-10. F0.2\nM30\nM99\n");
        String p = START + "M98 P1000\nG00 X60. Z5.\nG01 Z-5. F0.2\nG00 X70.\nM30\n";
        Compiler.Result r = check("fanuc-a", p, Optional.of(dir));
        assertEquals("O1000.nc:3:1:E685, O1000.nc:3:1:E145", codes(r));
        assertTrue(messages(r).contains(":3:1: error[E685]: M30 in O1000 ends the whole program: the caller never"
                + " goes on after the call (a called program ends with M99)"), messages(r));
        // after the main program's end in the same file, with other words in the block
        assertEquals("9:16:E685, 9:16:E136", codes("fanuc-a", START + "M98 P1000\nM30\nO1000\nG01 Z-20. F0.2 M30\nM99\n"));
    }

    @Test
    void aCalledFileThatIsADirectoryIsSaidToBeOne() throws IOException {
        Files.createDirectory(dir.resolve("O1000.nc"));
        Compiler.Result r = check("fanuc-a", START + "M98 P1000\nM30\n", Optional.of(dir));
        assertEquals("6:1:E505", codes(r));
        assertTrue(messages(r).endsWith("O1000.nc is a directory or a device and not a program file"), messages(r));
    }

    @Test
    void aCalledFileWithALineTooLongIsCutThere() throws IOException {
        Files.writeString(dir.resolve("O1000.nc"), "O1000\n(" + "X".repeat(gcnc.parse.BoundedReader.LINE_LIMIT + 10)
                + ")\nM99\n");
        Compiler.Result r = check("fanuc-a", START + "M98 P1000\nM30\n", Optional.of(dir));
        assertTrue(codes(r).contains("O1000.nc:2:" + (gcnc.parse.BoundedReader.LINE_LIMIT + 1) + ":E503"), codes(r));
    }

    @Test
    void aLoopThatRepeatsAnErrorReportsItOnceWithItsPasses() {
        // 170 bytes that printed 1,249,222 identical E146 errors (2.9 GB)
        String p = "#2 = 0\nWHILE [#2 LT 20] DO2\n#1 = 0\nWHILE [#1 LT 30] DO1\nG01 X#24\n#1 = #1 + 1\nEND1\n"
                + "#2 = #2 + 1\nEND2\nM30\n";
        Compiler.Result r = check("fanuc-a", p, Optional.empty());
        assertTrue(messages(r).contains("p.nc:5:5: error[E146]: X#24 has no value: a vacant variable or a division by"
                + " zero or a function outside its domain\np.nc:5:5: note[E680]: the same in 600 passes of this block;"
                + " shown once"), messages(r));
        assertEquals(1, r.diagnostics().sorted().stream().filter(d -> d.code() == Code.E146_MACRO_NO_VALUE).count());
    }

    // ---- what is missing ----

    @Test
    void aCallOfNoProgramIsReportedAtItsP() {
        Compiler.Result r = check("fanuc-a", START + "M98 P1234\nM30\n" + O1000, Optional.empty());
        assertEquals("6:5:E130, 8:1:E138", codes(r));
        assertTrue(messages(r).contains("p.nc:6:5: error[E130]: no program O1234 to call"), messages(r));
        assertEquals("6:1:E132", codes("fanuc-a", START + "M98\nM30\n"));
    }

    @Test
    void aProgramNothingCallsIsOnlyParsedAndSaidSo() {
        // streaming: no call, the program after M30 is read and not held
        assertEquals("8:1:E138", codes("fanuc-a", START + "G00 X100.\nM30\n" + O1000));
        // its parse errors are still found
        assertEquals("8:1:E138, 9:16:E003", codes("fanuc-a", START + "G00 X100.\nM30\nO1000\nG01 Z-20. F0.2 $\nM99\n"));
    }

    @Test
    void aCalledProgramWithoutM99IsReportedAtItsOWord() {
        assertEquals("8:1:E140", codes("fanuc-a", START + "M98 P1000\nM30\nO1000\nG00 Z2.\n"));
        // it ends at the next program's O word
        assertEquals("8:1:E140, 10:1:E138", codes("fanuc-a", START + "M98 P1000\nM30\nO1000\nG00 Z2.\nO2000\nM99\n"));
    }

    @Test
    void twoProgramsWithOneNumberAreReported() {
        assertEquals("14:1:E142", codes("fanuc-a", START + "M98 P1000\nG00 X100. Z100.\nM30\n" + O1000 + O1000));
    }

    // ---- M99 ----

    @Test
    void m99InTheMainProgramEndsItWithAWarning() {
        assertEquals("6:1:E139", codes("haas", START + "M99\n"));
        assertEquals("6:1:E139, 7:1:E053", codes("haas", START + "M99\nG00 X10.\n"));
    }

    @Test
    void aCallAfterTheEndIsNeverRun() {
        assertEquals("7:1:E053, 8:1:E138", codes("fanuc-a", START + "M30\nM98 P1000\n" + O1000));
    }

    @Test
    void m99WithPIsNotSupportedYet() {
        assertEquals("10:5:E110, 10:5:E136", codes("fanuc-a", START + "M98 P1000\nM30\nO1000\nG00 Z2.\nM99 P20\n"));
    }

    // ---- the checker follows the program through the call ----

    @Test
    void theModalStateFlowsThroughTheCall() {
        // the spindle and the feed are set in O1000; the main program cuts after it returns
        String p = "O0001\nG00 G21 G99\nT0101\nG00 X52. Z2.\nM98 P1000\nG01 Z-30.\nM30\n"
                + "O1000\nG97 S800 M03\nG01 Z-20. F0.2\nG00 Z2.\nM99\n";
        assertEquals("", codes("haas", p));
        // without the call, the cut at line 5 has no feed
        assertEquals("5:1:E039", codes("haas", "O0001\nG00 G21 G99\nT0101\nG00 X52. Z2.\nG01 Z-30.\nM30\n"));
    }

    @Test
    void aFindingInACalledProgramNamesTheCall() {
        // the cut of O1000 (line 11) runs before the spindle starts
        String p = "O0001\nG00 G21 G99\nT0101\nG00 X52. Z2.\nM98 P1000\nG97 S800 M03\nM30\n"
                + "O1000\nG01 Z-20. F0.2\nM99\n";
        Compiler.Result r = check("haas", p, Optional.empty());
        assertEquals("9:1:E051, 9:1:E136", codes(r));
        assertTrue(messages(r).endsWith("p.nc:9:1: note[E136]: in O1000 called from line 5 (M98 P1000)"), messages(r));
    }

    @Test
    void aFindingInARepeatedProgramIsReportedOnce() {
        String p = START + "M98 P1000 L3\nM30\nO1000\nG01 Z-20. F0.2 Q1.\nM99\n";
        Compiler.Result r = check("haas", p, Optional.empty());
        assertEquals("9:16:E108, 9:16:E136, 9:16:E680", codes(r));
        assertTrue(messages(r).endsWith("p.nc:9:16: note[E680]: the same in 3 passes of this block; shown once"),
                messages(r));
    }

    @Test
    void nestedCallsGiveOneNotePerLevel() {
        String p = START + "M98 P1000\nM30\nO1000\nM98 P2000\nM99\nO2000\nG01 Z-2. Q1.\nM99\n";
        Compiler.Result r = check("haas", p, Optional.empty());
        assertTrue(messages(r).contains("p.nc:12:10: note[E136]: in O2000 called from line 9 (M98 P2000)\n"
                + "p.nc:12:10: note[E136]: in O1000 called from line 6 (M98 P1000)"), messages(r));
    }

    @Test
    void sequenceNumbersOfACalledProgramAreItsOwn() {
        // the N numbers of O1000 run twice and repeat the main program's: no E114
        String p = "N10 G00 G21 G99\nN20 T0101\nN30 G97 S800 M03\nN40 G00 X52. Z2.\nN50 M98 P1000 L2\nN60 M30\n"
                + "O1000\nN10 G01 Z-2. F0.2\nN20 G00 Z2.\nN30 M99\n";
        assertEquals("", codes("haas", p));
    }

    @Test
    void theThesisControlHasNoSubprograms() {
        assertEquals("1:1:E110", codes("thesis-2004", "M98 P1000\nM30\n"));
    }

    @Test
    void repeatsInsideRepeatsStopAtTheStepLimit() {
        // 9999 x 9999 x 9999 passes would never end: the run stops following calls at the limit
        String p = START + "M98 P1000 L9999\nM30\nO1000\nM98 P2000 L9999\nM99\nO2000\nM98 P3000 L9999\nM99\n"
                + "O3000\nG00 Z2.\nM99\n";
        Compiler.Result r = check("haas", p, Optional.empty());
        assertTrue(messages(r).contains("error[E149]: the program at line "), messages(r));
        assertEquals(1, r.diagnostics().errorCount(), messages(r));
    }

    // ---- Haas M97: a local subprogram by its N label ----

    private static final String LOCAL = "N100 G01 Z-20. F0.2\nG00 X54.\nZ2.\nM99\n";

    @Test
    void m97RunsTheBlocksFromItsLabelToM99() {
        String p = START + "M97 P100 L2\nG00 X100. Z100.\nM30\n" + LOCAL;
        assertEquals("1 2 3 4 5 6 9/1 10/1 11/1 12/1 9/1 10/1 11/1 12/1 7 8", order("haas", p));
        // the local subprogram after M30 is not "after the end" (no E053)
        assertEquals("", codes("haas", p));
    }

    @Test
    void blocksAfterM30ThatNoM97ReachesAreStillNeverRun() {
        String p = START + "M97 P100\nM30\n" + LOCAL + "N200 G00 X1.\n";
        assertEquals("12:1:E053", codes("haas", p));
    }

    @Test
    void m97ToALabelTheProgramDoesNotHave() {
        Compiler.Result r = check("haas", START + "M97 P300\nM30\n" + LOCAL, Optional.empty());
        assertEquals("6:5:E141, 8:1:E053", codes(r)); // E053 once for the blocks after the end (issue 31)
        assertTrue(messages(r).contains("p.nc:6:5: error[E141]: M97 P300: no N300 to go to in this program from line 6 on"),
                messages(r));
    }

    @Test
    void aFindingInALocalSubprogramNamesItsLabelAndTheCall() {
        Compiler.Result r = check("haas", START + "M97 P100\nM30\nN100 G01 Z-2. F0.2 Q1.\nM99\n", Optional.empty());
        assertTrue(messages(r).contains("p.nc:8:20: note[E136]: in N100 called from line 6 (M97 P100)"), messages(r));
    }

    @Test
    void m97InACalledProgramLooksInThatProgram() {
        String p = START + "M98 P1000\nM30\nO1000\nM97 P10\nM99\nN10 G00 Z2.\nM99\n";
        assertEquals("1 2 3 4 5 6 9/1 11/2 12/2 10/1 7", order("haas", p));
        assertEquals("", codes("haas", p));
    }

    @Test
    void aLocalSubprogramThatCallsItselfIsReported() {
        assertEquals("9:1:E133, 9:1:E136", codes("haas", START + "M97 P100\nM30\nN100 G00 Z2.\nM97 P100\nM99\n"));
    }

    // ---- files beside the program ----

    @Test
    void aProgramNotInTheFileIsReadFromAFileBesideIt() throws IOException {
        Files.writeString(dir.resolve("O1000.nc"), "%\nO1000\nG01 Z-20. F0.2\nG00 X54.\nZ2.\nM99\n%\n");
        String p = START + "M98 P1000\nG00 X100. Z100.\nM30\n";
        assertEquals("", codes(check("fanuc-a", p, Optional.of(dir))));
        // without a folder to look in, it is not found
        assertEquals("6:5:E130", codes(check("fanuc-a", p, Optional.empty())));
        Files.delete(dir.resolve("O1000.nc"));
        Files.writeString(dir.resolve("1000.nc"), "G01 Z-20. F0.2 Q1.\nG00 X54.\nZ2.\nM99\n");
        Compiler.Result r = check("fanuc-a", p, Optional.of(dir));
        assertEquals("1000.nc:1:16:E108, 1000.nc:1:16:E145", codes(r));
        String beside = dir.resolve("1000.nc").toString();
        assertTrue(messages(r).contains(beside + ":1:16: error[E108]: word Q has no meaning in a G01 block\n"
                + beside + ":1:16: note[E145]: in O1000 called from line 6 of the program file (M98 P1000)"), messages(r));
    }

    @Test
    void aMissingProgramNamesTheFilesLookedFor() {
        Compiler.Result r = check("fanuc-a", START + "M98 P100\nM30\n", Optional.of(dir));
        assertEquals("6:5:E131", codes(r));
        assertTrue(messages(r).contains("there is no file O0100.nc / 0100.nc / O100.nc / 100.nc"), messages(r));
    }

    @Test
    void theParseErrorsOfAFileBesideItAreInThatFile() throws IOException {
        Files.writeString(dir.resolve("O1000.nc"), "O1000\nG01 Z-20. F0.2 $\nM99\n");
        Compiler.Result r = check("fanuc-a", START + "M98 P1000\nM30\n", Optional.of(dir));
        assertEquals("O1000.nc:2:16:E003", codes(r));
    }

    // ---- memory ----

    @Test
    void onlyAProgramThatCallsIsHeldAndOnlyUpToTheLimit() throws IOException {
        StringBuilder longer = new StringBuilder(START);
        for (int i = 0; i < 40; i++) {
            longer.append("G00 X52. Z").append(i + 2).append(".\n");
        }
        String noCall = longer + "M30\n";
        assertEquals("", flowCodes(noCall, 10), "a program without a call streams: no limit");
        String call = START + "M98 P1000\n" + longer.substring(START.length()) + "M30\n" + O1000;
        assertEquals("6:1:E137", flowCodes(call, 10));
        assertEquals("", flowCodes(call, 100));
    }

    /** Codes reported by the flow stage alone with a hold limit of {@code limit} blocks. */
    private static String flowCodes(String program, int limit) throws IOException {
        Diagnostics d = new Diagnostics();
        ProgramFlow flow = new ProgramFlow(new BlockReader(new StringReader(program), d), machine("fanuc-a"),
                d, Optional.empty(), limit);
        while (flow.next() != null) {
            // run through
        }
        List<String> out = new ArrayList<>();
        for (Diagnostic x : d.sorted()) {
            out.add(x.span().line() + ":" + x.span().column() + ":" + x.code().id());
        }
        return String.join(", ", out);
    }
}
