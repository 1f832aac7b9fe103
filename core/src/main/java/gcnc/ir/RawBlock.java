package gcnc.ir;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Origin;
import gcnc.diag.Span;
import java.util.List;

/**
 * One block (one source line with at least one word) as the parser read it, words in source order.
 * {@code malformed} says the parser already reported this block's first error: the checker counts
 * the block (M30 must be last) but checks nothing else in it. {@code last} is the start of the
 * last word, where the thesis reports end-of-block errors. {@code blockDelete} is the block's
 * block delete mark: 0 for none, else the skip level 1-9 ({@code /} is level 1, {@code /3} level 3).
 * {@code depth} is how many subprogram calls deep the block runs (0: the main program; set by
 * gcnc.flow, which hands a called program's blocks on once per call): N numbers are the main
 * program's labels only there. {@code macro} is the text of a Fanuc macro B statement line
 * ({@code #101 = [#1 + 2.5] * 2}, {@code X[#1 + 2.]}, {@code IF [..] GOTO 20}) as the parser
 * hands it on where the control has macros, null for any other block: gcnc.flow runs it and
 * hands the checker the words it comes to, never the statement. {@code deleteColumn} is the column
 * of a block delete '/' in the middle of the block (Haas, Fanuc: with the switch on, the block runs
 * up to it and the rest is skipped), 0 when the '/' (if any) marks the whole block; its level is
 * {@code blockDelete}. {@code origin} is where the block comes from: the file it was read from
 * ({@link Origin#PROGRAM}: the program's own) and, as gcnc.flow hands it on, the calls that led to
 * it; the checker and the later stages place the block's findings there (E136).
 */
public record RawBlock(int line, List<Word> words, Span last, boolean malformed, int blockDelete, int depth,
                       String macro, int deleteColumn, Origin origin) {
    public RawBlock {
        words = List.copyOf(words);
        java.util.Objects.requireNonNull(origin);
        if (blockDelete < 0 || blockDelete > 9) {
            throw new IllegalArgumentException("block delete level is 0-9: " + blockDelete);
        }
        if (depth < 0) {
            throw new IllegalArgumentException("call depth is 0 or more: " + depth);
        }
        if (deleteColumn < 0 || deleteColumn > 0 && blockDelete == 0) {
            throw new IllegalArgumentException("a mid-block '/' has a column and a level: " + deleteColumn);
        }
    }

    /**
     * An error at {@code at} in this block, placed in its file and calls: for a check that reports
     * on a block it held while the flow went on (a corner or an angle waiting for the next move,
     * which may come from a called program).
     */
    public Diagnostic error(Code code, Span at, Object... args) {
        return Diagnostic.error(code, at, args).in(origin);
    }

    /** A block of the program's own file. */
    public RawBlock(int line, List<Word> words, Span last, boolean malformed, int blockDelete, int depth,
                    String macro, int deleteColumn) {
        this(line, words, last, malformed, blockDelete, depth, macro, deleteColumn, Origin.PROGRAM);
    }

    /** A block whose '/' (if any) marks the whole block. */
    public RawBlock(int line, List<Word> words, Span last, boolean malformed, int blockDelete, int depth,
                    String macro) {
        this(line, words, last, malformed, blockDelete, depth, macro, 0);
    }

    /**
     * The block as it runs with the block delete switch on, when its '/' stands in the middle: the
     * words before the '/'; null when nothing is left of it.
     */
    public RawBlock beforeDelete() {
        List<Word> kept = words.stream().filter(w -> w.span().column() < deleteColumn).toList();
        return kept.isEmpty() ? null : new RawBlock(line, kept, kept.get(kept.size() - 1).span(), malformed, 0, depth,
                macro, 0, origin);
    }

    /** A block of words. */
    public RawBlock(int line, List<Word> words, Span last, boolean malformed, int blockDelete, int depth) {
        this(line, words, last, malformed, blockDelete, depth, null);
    }

    /** A macro statement line: its text, and where its first character is as {@code last}. */
    public static RawBlock macro(int line, String text, Span start) {
        return new RawBlock(line, List.of(), start, false, 0, 0, text);
    }

    /** A block of the main program. */
    public RawBlock(int line, List<Word> words, Span last, boolean malformed, int blockDelete) {
        this(line, words, last, malformed, blockDelete, 0);
    }

    /** A block of the main program without a block delete mark. */
    public RawBlock(int line, List<Word> words, Span last, boolean malformed) {
        this(line, words, last, malformed, 0, 0);
    }

    /** The same block run {@code depth} calls deep, with {@code words} only (the flow words taken out, or a macro line's words). */
    public RawBlock called(List<Word> words, Span last, int depth) {
        return new RawBlock(line, words, last, malformed, blockDelete, depth, null, deleteColumn, origin);
    }

    /** The same block coming from {@code origin} (this one when it already does). */
    public RawBlock from(Origin origin) {
        return origin == this.origin ? this
                : new RawBlock(line, words, last, malformed, blockDelete, depth, macro, deleteColumn, origin);
    }
}
