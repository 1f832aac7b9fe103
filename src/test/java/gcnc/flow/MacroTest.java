package gcnc.flow;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.Compiler;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.GnuRenderer;
import gcnc.galil.Dialect;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.machine.MachineProfile;
import gcnc.machine.ProfileLoader;
import gcnc.parse.BlockReader;
import gcnc.tables.ErrorMessages;
import gcnc.tables.TableException;
import gcnc.tables.TableSource;
import gcnc.tables.Tables;
import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Fanuc macro B, one tiny program per construct: the blocks the checker is given (their words,
 * values worked out) and what is reported where.
 */
class MacroTest {
    private static final Tables TABLES = Tables.builtIn();

    private static MachineProfile machine(String control) {
        try {
            return ProfileLoader.load("generic", TableSource.builtIn(), TABLES, control);
        } catch (TableException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    /** The blocks handed to the checker, "line: words", separated by " | "; then the findings. */
    static String run(String program) {
        Diagnostics d = new Diagnostics();
        ProgramFlow flow = new ProgramFlow(BlockReader.forControl(new StringReader(program), d, true), machine("fanuc-a"), d,
                Optional.empty());
        List<String> out = new ArrayList<>();
        try {
            for (RawBlock b = flow.next(); b != null; b = flow.next()) {
                List<String> words = new ArrayList<>();
                for (Word w : b.words()) {
                    words.add(w.toString());
                }
                out.add(b.line() + ": " + (b.blockDelete() > 0 ? "/" + b.blockDelete() + " " : "") + String.join(" ", words));
            }
        } catch (IOException e) {
            throw new AssertionError(e);
        }
        String blocks = String.join(" | ", out);
        List<String> found = new ArrayList<>();
        for (Diagnostic x : d.sorted()) {
            found.add(x.span().line() + ":" + x.span().column() + ":" + x.code().id());
        }
        return found.isEmpty() ? blocks : blocks + " // " + String.join(", ", found);
    }

    /** The value a word gets from an expression, as the checker is given it. */
    private static String value(String expression) {
        String r = run("X[" + expression + "]\n");
        return r.startsWith("1: X") ? r.substring(4) : r;
    }

    static Compiler.Result check(String control, String program) {
        try {
            return Compiler.check(new StringReader(program),
                    new Compiler.Settings(TABLES, machine(control), Dialect.Kind.GALIL, Optional.empty()));
        } catch (IOException e) {
            throw new AssertionError(e);
        }
    }

    // ---- variables and words ----

    @Test
    void anAssignmentSetsAVariableThatAWordUses() {
        assertEquals("3: G00 X109. Z-14.", run("#1 = 52.\n#101 = [#1 + 2.5] * 2\nG00 X#101 Z-[#1 / 4 + 1]\n"));
        // spaces do not matter, and a comment may follow
        assertEquals("3: G0 G96 X350. Z50. S250 M3", run("#501=350.(FLANGE DIA.)\n#505=0\nG0G96X[#501]Z[#505+50.]S250M3\n"));
    }

    @Test
    void aVariableValueIsNeverReadInLeastIncrements() {
        // X#1 with #1 = 5 is 5 mm on a Fanuc: the word gets a decimal point
        assertEquals("2: X5.", run("#1 = 5\nX#1\n"));
        assertEquals("2: Z-0.1235", run("#1 = 0.12345\nZ-#1\n"));
    }

    @Test
    void integerAddressesTakeWholeValues() {
        assertEquals("2: M3 S800 T101", run("#1 = 3\nM#1 S[#1 * 200 + 200] T[101]\n"));
        assertEquals(" // 2:1:E013", run("#1 = 1.5\nG#1\n"));
    }

    @Test
    void precedenceAndBrackets() {
        assertEquals("14.", value("2 + 3 * 4"));
        assertEquals("20.", value("[2 + 3] * 4"));
        assertEquals("1.", value("7 - 2 * 3"));
        assertEquals("-6.", value("-[2 * 3]"));
        assertEquals("1.", value("7 MOD 3"));
        assertEquals("2.5", value("10 / 4"));
    }

    @Test
    void functions() {
        assertEquals("0.5", value("SIN[30]"));
        assertEquals("0.5", value("COS[60]"));
        assertEquals("1.", value("TAN[45]"));
        assertEquals("45.", value("ATAN[1]/[1]"));
        assertEquals("225.", value("ATAN[-1,-1]"));
        assertEquals("30.", value("ASIN[0.5]"));
        assertEquals("4.", value("SQRT[16]"));
        assertEquals("3.", value("ABS[-3]"));
        assertEquals("3.", value("ROUND[2.5]"));
        assertEquals("-3.", value("ROUND[-2.5]"));
        assertEquals("-1.", value("FIX[-1.7]"));
        assertEquals("2.", value("FUP[1.2]"));
        assertEquals("-2.", value("FUP[-1.2]"));
        assertEquals("1.", value("LN[EXP[1]]"));
    }

    @Test
    void indirectVariables() {
        assertEquals("3: X7.", run("#1 = 100\n#100 = 7\nX#[#1]\n"));
    }

    @Test
    void aVacantVariableIsZeroInArithmeticAndNoValueInAWord() {
        assertEquals("2: X1.", run("#2 = #1 + 1\nX#2\n"));
        // the control would leave X out of the block; gcnc reports it
        assertEquals("2: G00 // 2:5:E146", run("#1 = #0\nG00 X#1\n"));
    }

    @Test
    void whatOnlyTheMachineKnowsIsRefused() {
        assertEquals(" // 1:3:E147", run("X[#5001 + 1]\n"));
        assertEquals(" // 1:6:E147", run("#1 = #4001\n"));
        assertEquals(" // 1:6:E147", run("#1 = #3001\n"));
        // a common or kept variable this program has not set holds what came before it
        assertEquals(" // 1:6:E147", run("#1 = #100\n"));
        assertEquals(" // 1:6:E147", run("#1 = #500\n"));
        Compiler.Result r = check("haas", "#1 = #5021\nM30\n");
        assertTrue(ProgramFlowTest.messages(r).contains("p.nc:1:6: error[E147]: #5021 is known only when the machine runs"), ProgramFlowTest.messages(r));
    }

    @Test
    void writingASystemVariableIsNotSupportedYet() {
        assertEquals(" // 1:1:E111", run("#3006 = 1 (STOP)\n"));
    }

    @Test
    void noValueForADivisionByZeroOrAFunctionOutsideItsDomain() {
        assertEquals(" // 1:6:E146", run("#1 = 1 / 0\n"));
        assertEquals(" // 1:6:E146", run("#1 = SQRT[-1]\n"));
    }

    @Test
    void alarm3000IsAnErrorWithItsText() {
        Compiler.Result r = check("fanuc-a", "#3000 = 12 (TOOL WORN)\nM30\n");
        assertEquals("p.nc:1:1: error[E148]: alarm 12 (#3000): TOOL WORN", ProgramFlowTest.messages(r));
    }

    @Test
    void aNumberNoMacroVariableHoldsIsAlarm111() {
        // 400 nines: an infinity as a double; it threw NumberFormatException formatting the word
        String nines = "9".repeat(400);
        Compiler.Result r = check("fanuc-a", "G00 X[" + nines + "]\nM30\n");
        assertEquals("p.nc:1:7: error[E683]: 999999999999999999999999999999... comes to >1.8E+308: a macro value"
                + " is 0 or between 10^-29 and 10^47 in size; the control stops (alarm 111)", ProgramFlowTest.messages(r));
        // an overflow, an underflow, at the start of the operation that comes to it
        assertEquals(" // 2:6:E683", run("#1 = 10000000\n#2 = #1*#1*#1*#1*#1*#1*#1\n"));
        assertEquals(" // 2:6:E683", run("#1 = 0.0000001\n#2 = #1*#1*#1*#1*#1\n"));
        // up to 10^47 and down to 10^-29 are values; vacant minus vacant is 0, not NaN
        assertEquals("3: X0.", run("#1 = 10000000\n#2 = #1*#1*#1*#1*#1*#1\nX[#2 - #2]\n"));
        assertEquals("1: X0.", run("X[#1 - #1]\n"));
    }

    @Test
    void anyRunOfSignsIsReadWithoutRecursion() {
        // 10,000 minus signs overflowed the stack
        assertEquals("3: X-1.", run("#1 = 1\n#2 = " + "-".repeat(10_001) + "#1\nX#2\n"));
        assertEquals("3: X1.", run("#1 = 1\n#2 = " + "-".repeat(10_000) + "#1\nX#2\n"));
        assertEquals("1: X-5.", run("X[-+-+-5]\n"));
    }

    @Test
    void alarm3000TakesAnAlarmNumberFrom0To200() {
        Compiler.Result r = check("fanuc-a", "#3000 = 1000000000000000000000 (BAD)\nM30\n");
        assertEquals("p.nc:1:1: error[E682]: #3000 = 1E+21: an alarm number is a whole number from 0 to 200; the control"
                + " stops with an alarm of its own", ProgramFlowTest.messages(r));
        assertEquals(" // 1:1:E682", run("#3000 = -1\n"));
        assertEquals(" // 1:1:E148", run("#3000 = 200 (LAST)\n"));
    }

    @Test
    void aWhileEnteredWithoutItsEndIsReported() {
        // it passed silently: the body ran once and the program went on
        Compiler.Result r = check("fanuc-a", "#1 = 0\nWHILE [#1 LT 3] DO1\nG00 X[40 + #1]\n#1 = #1 + 1\nM30\n");
        assertTrue(ProgramFlowTest.messages(r).startsWith(
                "p.nc:2:1: error[E141]: WHILE [#1 LT 3] DO1: no END 1 to go to in this program from line 1 on"),
                ProgramFlowTest.messages(r));
    }

    // ---- flow ----

    @Test
    void ifGotoJumpsOnlyWhenItHolds() {
        String p = "#1 = 12\nIF [#1 GT 10] GOTO 20\nX1.\nN20 X2.\n";
        assertEquals("4: N20 X2.", run(p));
        assertEquals("3: X1. | 4: N20 X2.", run(p.replace("#1 = 12", "#1 = 5")));
        // the label may be computed
        assertEquals("3: N10 X2.", run("GOTO [5 + 5]\nX1.\nN10 X2.\n"));
    }

    @Test
    void gotoJumpsBack() {
        String p = "#1 = 0\nN10 #1 = #1 + 1\nX#1\nIF [#1 LT 3] GOTO 10\nM30\n";
        assertEquals("3: X1. | 3: X2. | 3: X3. | 5: M30", run(p));
    }

    @Test
    void ifThenAssigns() {
        assertEquals("3: X2.", run("#1 = 1\nIF [#1 EQ 1] THEN #1 = 2\nX#1\n"));
        assertEquals("3: X1.", run("#1 = 1\nIF [#1 NE 1] THEN #1 = 2\nX#1\n"));
    }

    @Test
    void whileLoopsRunWhileTheConditionHolds() {
        String p = "#1 = 0\nWHILE [#1 LT 3] DO 1\nX[#1 * 10]\n#1 = #1 + 1\nEND 1\nM30\n";
        assertEquals("3: X0. | 3: X10. | 3: X20. | 6: M30", run(p));
        assertEquals("6: M30", run(p.replace("#1 = 0", "#1 = 5")));
    }

    @Test
    void loopsNest() {
        String p = "#1 = 0\nWHILE [#1 LT 2] DO 1\n#2 = 0\nWHILE [#2 LT 2] DO 2\nX#1 Z#2\n#2 = #2 + 1\nEND 2\n"
                + "#1 = #1 + 1\nEND 1\n";
        assertEquals("5: X0. Z0. | 5: X0. Z1. | 5: X1. Z0. | 5: X1. Z1.", run(p));
    }

    @Test
    void anEndlessLoopIsReportedAtItsWhile() {
        Compiler.Result r = check("fanuc-a", "#1 = 0\nWHILE [#1 LT 3] DO 1\n#2 = 1\nEND 1\nM30\n");
        // #1 never changes: the loop comes round with every variable as it was, endless at its second pass
        assertEquals("p.nc:2:1: error[E149]: WHILE [#1 LT 3] DO 1 at line 2 has run 2 times without ending:"
                + " an endless loop", ProgramFlowTest.messages(r));
        assertEquals(" // 1:4:E149", run("N1 GOTO 1\n"));
    }

    @Test
    void anAlarmAfterM30ThatAGotoNamesIsNotAfterTheEnd() {
        // the IF does not jump in this run; N90 is reached only when it does: not E053, a note
        String p = "#1 = 1\nIF [#1 NE 1] GOTO 90\nG00 X1.\nM30\nN90 #3000 = 1 (BAD)\nM30\n";
        assertEquals("3: G00 X1. | 4: M30 // 5:1:E138", run(p));
        // with a label nothing names, the blocks after M30 go to the checker (E053 there)
        assertEquals("3: G00 X1. | 4: M30 | 5:  | 6: M30", run(p.replace("GOTO 90", "GOTO 80")));
    }

    @Test
    void aJumpWithNowhereToGoIsReported() {
        assertEquals("2: X1. // 1:1:E141", run("GOTO 99\nX1.\n"));
        assertEquals(" // 1:1:E141", run("END 1\n"));
        assertEquals(" // 1:1:E141", run("WHILE [1 GT 2] DO 1\n"));
    }

    @Test
    void aJumpBackBeforeTheFirstMacroStatementIsBeyondWhatIsHeld() {
        // the main program is held from the block before its first macro statement (line 2) on
        Compiler.Result r = check("fanuc-a", "N10 G00 X1.\nG00 X2.\n#1 = 1\nGOTO 10\nM30\n");
        assertEquals("p.nc:4:1: error[E141]: GOTO 10: no N10 to go to in this program from line 2 on", ProgramFlowTest.messages(r));
        assertEquals("2: N10 X2. | 3: X3. | 2: N10 X2. | 3: X3. | 6: M30",
                run("#1 = 0\nN10 X2.\nX3.\n#1 = #1 + 1\nIF [#1 LT 2] GOTO 10\nM30\n"));
    }

    @Test
    void aBlockDeleteMarkOnAMacroLine() {
        // the switch is off on fanuc-a: the statement runs; a block of words keeps its mark for the checker
        assertEquals("3: X2. | 4: /2 X2.", run("#1 = 1\n/#1 = 2\nX#1\n/2 X#1\n"));
        assertEquals("", ProgramFlowTest.messages(check("fanuc-a", "G00 G21 G99\n#1 = 52.\n/G00 X#1 Z2.\nM30\n")));
    }

    @Test
    void macroSyntaxErrorsAreLocated() {
        assertEquals(" // 1:4:E010", run("#1 + 2\n"));
        assertEquals(" // 1:14:E010", run("IF [#1 GT 2] GOTTO 5\n"));
        assertEquals(" // 1:7:E010", run("X[#1 +*]\n"));
    }

    @Test
    void bracketsNestFiveDeep() {
        assertEquals("1: X5.", run("X[[[[[5]]]]]\n"));
        assertEquals(" // 1:7:E010", run("X[[[[[[5]]]]]]\n"));
    }

    @Test
    void conditionsJoinedByAndOrAreNotSupportedYet() {
        assertEquals(" // 1:12:E111", run("IF [1 EQ 1 AND 2 EQ 2] GOTO 5\n"));
    }

    // ---- with subprograms and controls ----

    @Test
    void anEndCodeInAMacroLineEndsTheMainProgram() {
        // what follows is a program nothing calls, not more of the main program
        assertEquals("2: G00 X5. M30 // 3:1:E138", run("#1 = 5\nG00 X#1 M30\nO1000\nG00 X1.\nM99\n"));
    }

    @Test
    void aSubprogramSharesTheLocalVariablesOfItsCaller() {
        String p = "#1 = 5\nM98 P1000\nX#1\nM30\nO1000\nX#1\n#1 = 6\nM99\n";
        // the M98 and M99 blocks reach the checker without their flow words
        assertEquals("2:  | 6: X5. | 8:  | 3: X6. | 4: M30", run(p));
    }

    @Test
    void aControlWithoutMacrosReportsTheLineAsBefore() {
        Compiler.Result r = check("thesis-2004", "#1 = 2\nM30\n");
        assertEquals("p.nc:1:1: error[E111]: Fanuc macro B is not supported yet: '#1 = 2'", ProgramFlowTest.messages(r));
    }

    @Test
    void aProgramWithMacrosChecksLikeAnyOther() {
        String p = "G00 G21 G99\nT0101\nG97 S800 M03\n#1 = 52.\nG00 X#1 Z2.\n#2 = 0\n"
                + "WHILE [#2 LT 3] DO 1\nG01 Z-[#2 * 5 + 5] F0.2\nG00 X[#1 + 2]\nZ2.\nX#1\n#2 = #2 + 1\nEND 1\nM30\n";
        assertEquals("", ProgramFlowTest.messages(check("haas", p)));
        assertEquals(17, check("haas", p).blocks(), "4 blocks, 4 per turn three times, M30");
    }

    /**
     * A program with a subprogram and a macro loop compiles to the same Galil program as the same
     * blocks written out one after the other (the DMC text; the source lines differ).
     */
    @Test
    void aLoopInASubprogramCompilesAsTheBlocksWrittenOut() throws IOException {
        String start = "G00 G18 G21 G40 G80 G99\nT0101\nG50 S2000\nG97 S800 M03\nG00 X52. Z2.\n";
        String looped = start + "#1 = 0\nM98 P1000 L2\nG00 X100. Z100.\nM30\n"
                + "O1000\nWHILE [#1 LT 2] DO 1\nG01 Z-[10 + #1 * 5] F0.2\nG00 X54.\nZ2.\nX52.\n#1 = #1 + 1\nEND 1\n"
                + "#1 = 0\nM99\n";
        String pass = "G01 Z-10. F0.2\nG00 X54.\nZ2.\nX52.\nG01 Z-15. F0.2\nG00 X54.\nZ2.\nX52.\n";
        String written = start + pass + pass + "G00 X100. Z100.\nM30\n";
        assertEquals(dmc(written), dmc(looped));
        // and the loop's second turn did cut deeper than its first
        String sameDepth = start + pass + pass.replace("Z-15.", "Z-10.") + "G00 X100. Z100.\nM30\n";
        assertTrue(!dmc(sameDepth).equals(dmc(looped)), "the second turn cuts 5 mm deeper");
    }

    private static String dmc(String program) throws IOException {
        StringBuilder out = new StringBuilder();
        Compiler.Result r = Compiler.compile(new StringReader(program),
                new Compiler.Settings(TABLES, machine("haas"), Dialect.Kind.GALIL, Optional.empty()), l -> {
                    if (!(l.command() instanceof gcnc.dmc.Command.SetVariable)) {
                        out.append(l.text()).append('\n'); // gline=<line>: the source lines differ, as said
                    }
                });
        assertEquals("", ProgramFlowTest.messages(r));
        return out.toString();
    }

    /** Random macro and flow text never throws: every fault is a located finding. */
    @Test
    void randomMacroSoupOnlyEverReports() {
        String[] parts = {"#", "#1", "#100", "#5001", "#3000", "[", "]", "=", "+", "-", "*", "/", " ", "1", "2.5", "0",
            "X", "G", "M", "GOTO", "IF", "WHILE", "DO", "END", "EQ", "GT", "SIN", "ATAN", "SQRT", "(", ")", "N1", "THEN",
            "MOD", ",", "\n", "M98 P1000", "M98 P21000", "M99", "M97 P1", "L2", "O1000", "M30", "/", "G65 P1000", "A1.", "I2", "I3."};
        Random random = new Random(20261123);
        for (int n = 0; n < 300; n++) {
            StringBuilder p = new StringBuilder();
            for (int k = random.nextInt(40); k > 0; k--) {
                p.append(parts[random.nextInt(parts.length)]);
            }
            String program = p.append("\nM30\n").toString();
            try {
                check(n % 2 == 0 ? "fanuc-a" : "haas", program);
            } catch (RuntimeException e) {
                throw new AssertionError("seed 20261123, program " + n + ": " + program, e);
            }
        }
    }
}
