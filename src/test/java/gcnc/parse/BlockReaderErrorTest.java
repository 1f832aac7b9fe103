package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Each lexical/syntax error number of the parse stage, with its exact line, column and args. */
class BlockReaderErrorTest {

    private static void expect(String source, List<String> errors, List<String> blocks) {
        Parsed p = Parsed.of(source);
        assertEquals(errors, p.errors(), "diagnostics of: " + source);
        assertEquals(blocks, p.shapes(), "blocks of: " + source);
    }

    @Test
    void gWithoutNumberIsError1() {
        expect("N10 G X5\n", List.of("1:5 E001 []"), List.of("1: N10 !"));
    }

    @Test
    void mWithoutNumberIsError2() {
        expect("N10\nm\n", List.of("2:1 E002 []"), List.of("1: N10", "2: !"));
    }

    @Test
    void illegalCharacterIsError3WithTheCharacter() {
        expect("N10 X5 $ Z3\n", List.of("1:8 E003 [$]"), List.of("1: N10 X5 !"));
        expect("X5\"\n", List.of("1:3 E003 [\"]"), List.of("1: X5 !"));
        expect("N1 é\n", List.of("1:4 E003 [é]"), List.of("1: N1 !"));
        expect("N1\u0001\n", List.of("1:3 E003 [U+0001]"), List.of("1: N1 !"));
    }

    @Test
    void theParserReadsEveryLetterAndLeavesError4ToTheChecker() {
        expect("G00 Y10\n", List.of(), List.of("1: G00 Y10"));
        expect("a1 q-2.5\n", List.of(), List.of("1: A1 Q-2.5"));
    }

    @Test
    void commentNotClosedAtEndOfFileIsError5AtItsParenthesis() {
        expect("N10 X5\nN20 (open\nstill open\n", List.of("2:5 E005 []"), List.of("1: N10 X5", "2: N20"));
    }

    @Test
    void emptyWordNumberIsError6WithTheLetter() {
        expect("G01 X Z5\n", List.of("1:5 E006 [X]"), List.of("1: G01 !"));
        expect("f\n", List.of("1:1 E006 [F]"), List.of("1: !"));
        expect("N\n", List.of("1:1 E006 [N]"), List.of("1: !"));
        expect("G00 Y Z5\n", List.of("1:5 E006 [Y]"), List.of("1: G00 !"));
        expect("q\n", List.of("1:1 E006 [Q]"), List.of("1: !"));
    }

    @Test
    void strayNumberSignPointOrPunctuationIsError10() {
        for (String stray : List.of("5", ".", "+", "-", ":", ",", "*", "=", ")")) {
            // after a comment: 'N10 5' would be N105, the control ignores spaces (E600)
            expect("N10 (c) " + stray + " X1\n", List.of("1:9 E010 ['" + stray + "']"), List.of("1: N10 !"));
        }
    }

    @Test
    void aSlashAfterOtherWordsMarksTheRestOfTheBlock() {
        // Haas, Fanuc: with the switch on the block runs up to the '/' (the checker decides)
        expect("G00 /X1\n", List.of(), List.of("1: G00 /1 X1"));
        expect("N10 G00 /X1\n", List.of(), List.of("1: N10 G00 /1 X1"));
        expect("X1 N10/\n", List.of(), List.of("1: X1 N10 /1"));
        expect("N10 X1 /2\n", List.of(), List.of("1: N10 X1 /2"));
        expect(":10/X1\n", List.of(), List.of("1: O10 /1 X1"));
        assertEquals(5, Parsed.of("G00 /X1\n").blocks().get(0).deleteColumn());
        assertEquals(0, Parsed.of("N10 /X1\n").blocks().get(0).deleteColumn(), "after a first N: the whole block");
    }

    @Test
    void aSecondBlockDeleteOnALineIsError10() {
        expect("/N10 /X1\n", List.of("1:6 E010 ['/']"), List.of("1: /1 N10 !"));
        expect("G00 X1 /Z2 /M08\n", List.of("1:12 E010 ['/']"), List.of("1: G00 X1 /1 Z2 !"));
        expect("//X1\n", List.of("1:2 E010 ['/']"), List.of("1: /1 !"));
    }

    @Test
    void theSkipLevelIsOneDigitFromOneToNine() {
        expect("/0 X1\n", List.of("1:2 E010 ['0']"), List.of("1: /1 !"));
        expect("/12 X1\n", List.of("1:3 E010 ['2']"), List.of("1: /1 !"));
    }

    @Test
    void aColonNotFollowedByADigitIsError10() {
        expect(":O100\n", List.of("1:1 E010 [':']"), List.of("1: !"));
    }

    @Test
    void decimalOrSignInIntegerWordIsError13() {
        expect("N1.5 G01\n", List.of("1:1 E013 [N]"), List.of("1: !"));
        expect("G01 S-100\n", List.of("1:5 E013 [S]"), List.of("1: G01 !"));
        expect("g1.\n", List.of("1:1 E013 [G]"), List.of("1: !"));
        expect("T.1\n", List.of("1:1 E013 [T]"), List.of("1: !"));
        expect(":12.5\n", List.of("1:1 E013 [O]"), List.of("1: !"));
    }

    @Test
    void aGCodeWithADecimalPointIsNamedAsNotSupportedYet702() {
        // Fanuc G12.1 polar interpolation, G54.1 P added work coordinates: codes of the manual, named
        expect("G12.1\n", List.of("1:1 E702 [G12.1]"), List.of("1: !"));
        expect("G54.1 P10\n", List.of("1:1 E702 [G54.1]"), List.of("1: !"));
        expect("X1. g50.3\n", List.of("1:5 E702 [G50.3]"), List.of("1: X1. !"));
        // no digit after the point, or another letter: still E013
        expect("G1.\n", List.of("1:1 E013 [G]"), List.of("1: !"));
        expect("M3.5\n", List.of("1:1 E013 [M]"), List.of("1: !"));
    }

    @Test
    void malformedNumberIsError14() {
        for (String bad : List.of("X+", "X.", "X1.2.3", "X--1", "x-.", "F-1", "F+0.2", "Z1-2", "P1.2.", "y+-1")) {
            String letter = bad.substring(0, 1).toUpperCase();
            expect("G01 " + bad + " F1\n", List.of("1:5 E014 [" + letter + "]"), List.of("1: G01 !"));
        }
    }

    @Test
    void textOutsideACommentIsError109WithTheText() {
        expect("roughing pass\n", List.of("1:1 E109 [roughing pass]"), List.of("1: !"));
        expect("G00 Xabc\n", List.of("1:5 E109 [Xabc]"), List.of("1: G00 !"));
        expect("N10 finish  here (done)\n", List.of("1:5 E109 [finish  here]"), List.of("1: N10 !"));
        expect("GO HOME; now\n", List.of("1:1 E109 [GO HOME]"), List.of("1: !"));
        expect("Mind X1 % tape\n", List.of("1:1 E109 [Mind X1]"), List.of("1: !"));
    }

    @Test
    void longTextIsCutAtThirtyCharacters() {
        expect("this note is much longer than thirty characters\n",
                List.of("1:1 E109 [this note is much longer than...]"), List.of("1: !"));
        expect("abcdefghijklmnopqrstuvwxyzabcd\n", List.of("1:1 E109 [abcdefghijklmnopqrstuvwxyzabcd]"), List.of("1: !"));
        expect("abcdefghijklmnopqrstuvwxyzabcde\n",
                List.of("1:1 E109 [abcdefghijklmnopqrstuvwxyzabcd...]"), List.of("1: !"));
    }

    @Test
    void aMacroVariableIsError111WithTheMacroText() {
        expect("#501=350.(FLANGE DIA.)\n", List.of("1:1 E111 [#501=350.]"), List.of("1: !"));
        expect("  #502=-23 ; depth\n", List.of("1:3 E111 [#502=-23]"), List.of("1: !"));
        expect("G0X#501\n", List.of("1:4 E111 [#501]"), List.of("1: G0 !"));
    }

    @Test
    void aMacroExpressionIsError111AtItsBracket() {
        expect("G1Z[#502]F0.35\n", List.of("1:4 E111 [[#502]F0.35]"), List.of("1: G1 !"));
        expect("N1 ]\n", List.of("1:4 E111 []]"), List.of("1: N1 !"));
        expect("G0G96X[#501]Z[#505+50.]S250M3M8(ROUGH SPIGOT)\n",
                List.of("1:7 E111 [[#501]Z[#505+50.]S250M3M8]"), List.of("1: G0 G96 !"));
        expect("X[#504+#505*#506/#507-#508+#509]\n",
                List.of("1:2 E111 [[#504+#505*#506/#507-#508+#509...]"), List.of("1: !"));
    }

    @Test
    void aMacroCharacterIsTheLineErrorEvenAfterAnotherError() {
        expect("N10 X5 $ Y#1\n", List.of("1:11 E111 [#1]"), List.of("1: N10 X5 !"));
        expect("N10 G X[#1]\n", List.of("1:8 E111 [[#1]]"), List.of("1: N10 !"));
    }

    @Test
    void aMacroCharacterInACommentIsNothing() {
        expect("N10 (#1 [x]) X1 ; #2\n", List.of(), List.of("1: N10 X1"));
    }

    @Test
    void theLetterOForAZeroIsError120WithTheNumberMeant() {
        // without the hint: error 13 for 'O.', 6 for a bare O, 109 for 'OX1.', 10 for a stray '.'
        expect("G01 Z-3O. F.2\n", List.of("1:5 E120 [Z-3O., Z-30.]"), List.of("1: G01 Z-3 !"));
        expect("G01 Z-3O\n", List.of("1:5 E120 [Z-3O, Z-30]"), List.of("1: G01 Z-3 !"));
        expect("G0OX1.\n", List.of("1:1 E120 [G0O, G00]"), List.of("1: G0 !"));
        expect("G00 z-1o0. (rough)\n", List.of("1:5 E120 [z-1o0., z-100.]"), List.of("1: G00 Z-1 !"));
        expect("G00 ZO\n", List.of("1:5 E120 [ZO, Z0]"), List.of("1: G00 !"));
        expect("S1OOO M3\n", List.of("1:1 E120 [S1OOO, S1000]"), List.of("1: S1 !"));
    }

    @Test
    void aDecimalCommaIsError121WithTheNumberWrittenWithAPoint() {
        expect("G00 Z-30,5\n", List.of("1:5 E121 [Z-30,5, Z-30.5]"), List.of("1: G00 Z-30 !"));
        expect("G00 Z,15\n", List.of("1:5 E121 [Z,15, Z.15]"), List.of("1: G00 !"));
        expect("G01 X1,5 F0,2\n", List.of("1:5 E121 [X1,5, X1.5]"), List.of("1: G01 X1 !"));
        // both slips in one word: the O first, the fix shows both
        expect("Z-3O,5\n", List.of("1:1 E120 [Z-3O,5, Z-30.5]"), List.of("1: Z-3 !"));
    }

    @Test
    void aSlipIsNamedOnlyWhenFixingItMakesTheLineRead() {
        // text stays text; a thousands separator in an integer word, a comma between words and a
        // second, unrelated error keep their own errors; a macro line stays a macro line
        expect("GO HOME\n", List.of("1:1 E109 [GO HOME]"), List.of("1: !"));
        expect("GOTO\n", List.of("1:1 E109 [GOTO]"), List.of("1: !"));
        expect("S1,200\n", List.of("1:3 E010 [',']"), List.of("1: S1 !"));
        expect("X10,Z5\n", List.of("1:4 E010 [',']"), List.of("1: X10 !"));
        expect("Z-30,5 $\n", List.of("1:5 E010 [',']"), List.of("1: Z-30 !"));
        expect("Z-3O. #1\n", List.of("1:7 E111 [#1]"), List.of("1: Z-3 !"));
        // two slips on a line: the one where the lexer stumbled is named, the line reads once both are fixed
        expect("G00 X5O (note) X1,5\n", List.of("1:5 E120 [X5O, X50]"), List.of("1: G00 X5 !"));
        // a slip that is not where the line's error is does not take its place
        expect("X1O5 N10 /X1 /Z2\n", List.of("1:14 E010 ['/']"), List.of("1: X1 O5 N10 /1 X1 !"));
    }

    @Test
    void parenthesisInsideCommentIsError54AtTheInnerParenthesis() {
        expect("N10 (a (b) c) X5\nN20\n", List.of("1:8 E054 []"), List.of("1: N10 !", "2: N20"));
    }

    @Test
    void nestedParenthesisOnALaterLineOfACommentLeavesTheCommentOpenUntilItsEnd() {
        expect("N10 (one\ntwo ( three\nfour) X5\n", List.of("2:5 E054 []"), List.of("1: N10", "2: !", "3: X5"));
    }

    @Test
    void onlyTheFirstErrorOfALineIsReported() {
        expect("N10 $ Y5 X+ G\n", List.of("1:5 E003 [$]"), List.of("1: N10 !"));
    }

    @Test
    void aCommentOpenedAfterAnErrorIsStillFollowed() {
        expect("X1.2.3 (note\nX5) Z1\n", List.of("1:1 E014 [X]"), List.of("1: !", "2: Z1"));
    }

    @Test
    void severalBadBlocksAreEachReportedOnTheirOwnLine() {
        String src = "N10 G00 X0\nN20 X1$\nN30 G01 Z-5 F0.2\nN40 #1=2\n\nN50 X1..\nN60 M30\n";
        expect(src, List.of("2:7 E003 [$]", "4:5 E111 [#1=2]", "6:5 E014 [X]"),
                List.of("1: N10 G00 X0", "2: N20 X1 !", "3: N30 G01 Z-5 F0.2", "4: N40 !", "6: N50 !", "7: N60 M30"));
    }
}
