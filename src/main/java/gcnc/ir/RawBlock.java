package gcnc.ir;

import gcnc.diag.Span;
import java.util.List;

/**
 * One block (one source line with at least one word) as the parser read it, words in source order.
 * {@code malformed} says the parser already reported this block's first error: the checker counts
 * the block (M30 must be last) but checks nothing else in it. {@code last} is the start of the
 * last word, where the thesis reports end-of-block errors.
 */
public record RawBlock(int line, List<Word> words, Span last, boolean malformed) {
    public RawBlock {
        words = List.copyOf(words);
    }
}
