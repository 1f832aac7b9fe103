package gcnc.flow;

import static gcnc.flow.MacroTest.check;
import static gcnc.flow.MacroTest.run;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * The macro call G65 P L with its arguments (Fanuc 0i-F custom macro, "Macro call"; the Haas macro
 * manual's G65): one tiny program per rule, the blocks the checker is given ("line: words", " | "
 * between them) and the findings after "//". O1000 is after the main program's M30.
 */
class MacroCallTest {
    @Test
    void theArgumentsAreTheCalledProgramsLocalsBySpecificationI() {
        // A #1, B #2, I #4, K #6, X #24, Z #26, U #21, R #18
        assertEquals("1:  | 4: X40. Z-20. | 5: U1.5 R3. I2.5 K-1. | 6:  | 2: M30",
                run("G65 P1000 X40. Z-20. A1. B2. U1.5 R3. I2.5 K-1.\nM30\nO1000\nX#24 Z#26\nU#21 R#18 I#4 K#6\nM99\n"));
    }

    @Test
    void theCallerGetsItsOwnLocalsBackAtTheReturn() {
        // #1 is 5 in the main program, the argument A7. in O1000 (which sets it to 8), 5 again after the M99
        assertEquals("2:  | 6: X7. | 8:  | 3: X5. | 4: M30",
                run("#1 = 5\nG65 P1000 A7.\nX#1\nM30\nO1000\nX#1\n#1 = 8\nM99\n"));
    }

    @Test
    void anAddressNotGivenIsVacantInTheCalledProgram() {
        // #2 (B) vacant: the caller's #2 is not seen; a word with a vacant variable is E146 (at Z#2, in the call)
        assertEquals("2:  | 5: X1. | 6:  | 3: M30 // 5:5:E146, 5:5:E136", run("#2 = 9\nG65 P1000 A1.\nM30\nO1000\nX#1 Z#2\nM99\n"));
        // a macro's own test of an optional argument
        assertEquals("2:  | 6: X1. | 7: N10 | 3: M30", // #2 vacant in O1000: no jump past X#1
                run("#2 = 9\nG65 P1000 A1.\nM30\nO1000\nIF [#2 NE #0] GOTO 10\nX#1\nN10 M99\n"));
    }

    @Test
    void anM98InsideAMacroCallSharesItsLevelAndNestedCallsEachHaveTheirOwn() {
        String p = "G65 P1000 A1.\nM30\n"
                + "O1000\nM98 P2000\nG65 P3000 A3.\nX#1\nM99\n" // 3-7
                + "O2000\nZ#1\nM99\n" // 8-10: O1000's #1
                + "O3000\nU#1\nM99\n"; // 11-13: a level of its own
        assertEquals("1:  | 4:  | 9: Z1. | 10:  | 5:  | 12: U3. | 13:  | 6: X1. | 7:  | 2: M30", run(p));
    }

    @Test
    void anArgumentWithoutAPointIsReadInTheLeastIncrementButMSAndTAsWritten() {
        // generic fanuc-a: G21 at power-up, a whole number is thousandths of a mm; under G20 ten-thousandths of an inch
        assertEquals("1:  | 4: X0.024 S1000 T3 M8 | 5:  | 2: M30",
                run("G65 P1000 X24 S1000 T3 M8\nM30\nO1000\nX#24 S#19 T#20 M#13\nM99\n"));
        assertEquals("1: G20 | 2:  | 5: X0.0024 | 6:  | 3: M30", run("G20\nG65 P1000 X24\nM30\nO1000\nX#24\nM99\n"));
    }

    @Test
    void anArgumentFromAVariableIsItsValue() {
        assertEquals("2:  | 5: X52. | 6:  | 3: M30", run("#100 = 52\nG65 P1000 X#100\nM30\nO1000\nX#24\nM99\n"));
    }

    @Test
    void whatIsNotFollowedYetIsNamedAtItsWord() {
        // argument specification II (I J K given again) and an address given twice: E110, the call does not run
        assertEquals("1:  | 2: M30 // 1:15:E110, 3:1:E138", run("G65 P1000 I1. I2.\nM30\nO1000\nX#4\nM99\n"));
        // a call repeated by L
        assertEquals("1:  | 2: M30 // 1:11:E110, 3:1:E138", run("G65 P1000 L2 A1.\nM30\nO1000\nX#1\nM99\n"));
        assertEquals("1:  | 4: X1. | 5:  | 2: M30", run("G65 P1000 L1 A1.\nM30\nO1000\nX#1\nM99\n"));
    }

    @Test
    void aCallWithoutItsProgramIsReportedAsAnM98Is() {
        assertEquals("1:  | 2: M30 // 1:1:E132", run("G65 A1.\nM30\n"));
        assertEquals("1: M30", run("G65 P1000 A1.\nM30\n").replaceAll(" //.*", "").replace("1:  | 2: M30", "1: M30"));
    }

    @Test
    void onAControlWithoutMacroCallsG65IsNoCall() {
        // the thesis's control has no G65: the checker reports the code, the block is not followed
        assertEquals("p.nc:1:1: error[E011]: undefined preparatory function G65",
                ProgramFlowTest.messages(check("thesis-2004", "G65 P1000 A1.\nM30\n")).lines().findFirst().orElse(""));
    }

    @Test
    void aHaasProgramWithAMacroCallChecksClean() {
        String p = "G20 G99\nT0101\nG97 S800 M03\nG00 X2. Z0.1\nG65 P9010 A1.5 B0.25 C3.\nG00 X3. Z1.\nM05\nM30\n"
                + "O9010 (GROOVES: #1 DIAMETER, #2 DEPTH, #3 COUNT)\n#10 = 0\nWHILE [#10 LT #3] DO1\n"
                + "G00 Z-[#10 * 0.2 + 0.2]\nX[#1 + 0.1]\nG01 X[#1 - #2 * 2] F0.002\nG00 X[#1 + 0.1]\n#10 = #10 + 1\nEND1\nM99\n";
        assertEquals("", ProgramFlowTest.messages(check("haas", p)));
    }
}
