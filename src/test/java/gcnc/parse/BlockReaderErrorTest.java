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
    void letterOutsideTheLanguageIsError4WithTheLetter() {
        expect("G00 Y10\n", List.of("1:5 E004 [Y]"), List.of("1: G00 !"));
        expect("a1\n", List.of("1:1 E004 [a]"), List.of("1: !"));
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
    }

    @Test
    void strayNumberSignPointOrPunctuationIsError10() {
        for (String stray : List.of("5", ".", "+", "-", ":", ",", "*", "/", "=", "#", ")", "[", "]")) {
            expect("N10 " + stray + " X1\n", List.of("1:5 E010 ['" + stray + "']"), List.of("1: N10 !"));
        }
    }

    @Test
    void decimalOrSignInIntegerWordIsError13() {
        expect("N1.5 G01\n", List.of("1:1 E013 [N]"), List.of("1: !"));
        expect("G01 S-100\n", List.of("1:5 E013 [S]"), List.of("1: G01 !"));
        expect("g1.\n", List.of("1:1 E013 [G]"), List.of("1: !"));
        expect("T.1\n", List.of("1:1 E013 [T]"), List.of("1: !"));
    }

    @Test
    void malformedNumberIsError14() {
        for (String bad : List.of("X+", "X.", "X1.2.3", "X--1", "x-.", "F-1", "F+0.2", "Z1-2")) {
            String letter = bad.substring(0, 1).toUpperCase();
            expect("G01 " + bad + " F1\n", List.of("1:5 E014 [" + letter + "]"), List.of("1: G01 !"));
        }
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
        String src = "N10 G00 X0\nN20 X1$\nN30 G01 Z-5 F0.2\nN40 Y1\n\nN50 X1..\nN60 M30\n";
        expect(src, List.of("2:7 E003 [$]", "4:5 E004 [Y]", "6:5 E014 [X]"),
                List.of("1: N10 G00 X0", "2: N20 X1 !", "3: N30 G01 Z-5 F0.2", "4: N40 !", "6: N50 !", "7: N60 M30"));
    }
}
