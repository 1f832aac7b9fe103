package gcnc.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import gcnc.ir.Word;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * What a Haas or Fanuc control reads although the thesis's lexer did not: spaces inside a word,
 * Haas's comma words (,C ,R ,A), a DOS end-of-file mark, and comments that end at their line's end
 * (docs/grammar.md, "Leniency"). Each case: the program, its diagnostics and its blocks.
 */
class BlockReaderLeniencyTest {

    private static void expect(String source, List<String> diagnostics, List<String> blocks) {
        expect(source, false, diagnostics, blocks);
    }

    private static void expect(String source, boolean lineComments, List<String> diagnostics, List<String> blocks) {
        Parsed p = Parsed.of(source, lineComments);
        assertEquals(diagnostics, p.errors(), "diagnostics of: " + source);
        assertEquals(blocks, p.shapes(), "blocks of: " + source);
    }

    @Test
    void aSpaceAfterTheLetterOrTheSignIsIgnored() {
        expect("G 01 X 57. Z- 2.5 F 0.25\n", List.of(), List.of("1: G01 X57. Z-2.5 F0.25"));
        expect("x -2.\tz\t+.5\n", List.of(), List.of("1: X-2. Z+.5"));
        expect("N 10 M 03 S 1200\n", List.of(), List.of("1: N10 M03 S1200"));
    }

    @Test
    void aSpaceInsideANumberJoinsItAndIsWarnedAboutButNotInAToolWord() {
        expect("T1 01\n", List.of(), List.of("1: T101"));
        expect("X10 5 Z1\n", List.of("1:4 E600 [X10 5, X105]"), List.of("1: X105 Z1"));
        expect("Z-1 .5\n", List.of("1:4 E600 [Z-1 .5, Z-1.5]"), List.of("1: Z-1.5"));
        expect("N10 5\n", List.of("1:4 E600 [N10 5, N105]"), List.of("1: N105"));
    }

    @Test
    void aWordWithSpacesKeepsItsColumnsAndTheSpanCoversIt() {
        Word w = Parsed.of("G00 X 5.\n").blocks().get(0).words().get(1);
        assertEquals(5, w.span().column());
        assertEquals(9, w.span().endColumn());
    }

    @Test
    void whatStaysMalformedWithSpaces() {
        // a sign after a number is no number (the control alarms): error 14 on the word
        expect("X10 -5\n", List.of("1:1 E014 [X]"), List.of("1: !"));
        expect("X1. 2.\n", List.of("1:1 E014 [X]"), List.of("1: !"));
        expect("S 12 00.\n", List.of("1:1 E013 [S]"), List.of("1: !"));
        // a letter then a letter is still text, a lone letter still error 6
        expect("G00 X Z5\n", List.of("1:5 E006 [X]"), List.of("1: G00 !"));
    }

    @Test
    void commaWordsAreHaasChamferRoundAndAngle() {
        expect("G01 X20. ,C1. F.2\n", List.of(), List.of("1: G01 X20. ,C1. F.2"));
        expect("G01 Z-5.,R0.5\n", List.of(), List.of("1: G01 Z-5. ,R0.5"));
        expect("G01 X20. , a30.\n", List.of(), List.of("1: G01 X20. ,A30."));
        Word w = Parsed.of("G01 X20.,C1.\n").blocks().get(0).words().get(2);
        assertTrue(w.comma());
        assertEquals(9, w.span().column());
        // any other letter after a comma: error 10 at the comma, as before
        expect("G01 X20. ,X1.\n", List.of("1:10 E010 [',']"), List.of("1: G01 X20. !"));
    }

    @Test
    void aDosEndOfFileMarkAtTheEndIsIgnored() {
        expect("G00 X1.\nM30\n\u001A", List.of(), List.of("1: G00 X1.", "2: M30"));
        expect("M30\u001A\u001A  \n", List.of(), List.of("1: M30"));
        expect("M30\n%\u001A\n", List.of(), List.of("1: M30"));
    }

    @Test
    void aBlockAfterTheEndOfFileMarkIsWarnedAboutOnce() {
        expect("M30\n\u001A\nG00 X1.\nX2.\n", List.of("2:1 E602 []"), List.of("1: M30", "3: G00 X1.", "4: X2."));
        // with text after it on its own line it stays an illegal character
        expect("M30 \u001A X1.\n", List.of("1:5 E003 [U+001A]"), List.of("1: M30 !"));
    }

    @Test
    void haasAndFanucCommentsEndAtTheirLine() {
        // no ')': the comment ends at the end of the line, the next line is code (E601 at the '(')
        expect("G00 X1. (open\nZ5.\n", true, List.of("1:9 E601 []"), List.of("1: G00 X1.", "2: Z5."));
        // the thesis's control: it spans lines, and the end of the input finds it open (E005)
        expect("G00 X1. (open\nZ5.\n", false, List.of("1:9 E005 []"), List.of("1: G00 X1."));
    }

    @Test
    void haasAndFanucReadAParenthesisInsideACommentAsText() {
        expect("G00 X1. (DIA (REF) Z5.\n", true, List.of(), List.of("1: G00 X1. Z5."));
        // the first ')' ends the comment: what follows is code again
        expect("(TOOL (3) OD FINISH)\n", true, List.of("1:11 E109 [OD FINISH)]"), List.of("1: !"));
        expect("(DIA (REF))\n", true, List.of("1:11 E010 [')']"), List.of("1: !"));
        // a '(' inside a comment with no ')' at all: warned at the comment's own '('
        expect("X1. (DIA (REF\nZ5.\n", true, List.of("1:5 E601 []"), List.of("1: X1.", "2: Z5."));
        // the thesis's control: error 54 at the inner '('
        expect("G00 X1. (DIA (REF) Z5.\n", false, List.of("1:14 E054 []"), List.of("1: G00 X1. !"));
    }
}
