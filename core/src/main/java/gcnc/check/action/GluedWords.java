package gcnc.check.action;

import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import java.util.List;

/**
 * Words written with no space between them, as the block's text has them: an O glued to a number
 * ({@code Z-1O0}, Sa02) or a letter glued to the word before it (Sa03).
 */
final class GluedWords {
    private GluedWords() {
    }

    /**
     * The word written right after {@code w} with no space between them, or null. Only a number
     * can end a word, so an O there is a zero typed as a letter inside that number ({@code Z-1O0}).
     */
    static Word after(RawBlock block, Word w) {
        List<Word> ws = block.words();
        for (int i = 0; i + 1 < ws.size(); i++) {
            if (ws.get(i) == w) {
                Word next = ws.get(i + 1);
                return w.span().column() + 1 + w.number().length() == next.span().column() ? next : null;
            }
        }
        return null;
    }

    /** The word written right before {@code w} with no space between them, or null. */
    static Word before(RawBlock block, Word w) {
        List<Word> ws = block.words();
        for (int i = 1; i < ws.size(); i++) {
            if (ws.get(i) == w) {
                return after(block, ws.get(i - 1)) == w ? ws.get(i - 1) : null;
            }
        }
        return null;
    }
}
