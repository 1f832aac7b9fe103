package gcnc.ir;

import gcnc.diag.Span;
import java.util.List;

/**
 * One block (one source line with at least one word) as the parser read it, words in source order.
 * {@code malformed} says the parser already reported this block's first error: the checker counts
 * the block (M30 must be last) but checks nothing else in it. {@code last} is the start of the
 * last word, where the thesis reports end-of-block errors. {@code blockDelete} is the block's
 * block delete mark: 0 for none, else the skip level 1-9 ({@code /} is level 1, {@code /3} level 3).
 */
public record RawBlock(int line, List<Word> words, Span last, boolean malformed, int blockDelete) {
    public RawBlock {
        words = List.copyOf(words);
        if (blockDelete < 0 || blockDelete > 9) {
            throw new IllegalArgumentException("block delete level is 0-9: " + blockDelete);
        }
    }

    /** A block without a block delete mark. */
    public RawBlock(int line, List<Word> words, Span last, boolean malformed) {
        this(line, words, last, malformed, 0);
    }
}
