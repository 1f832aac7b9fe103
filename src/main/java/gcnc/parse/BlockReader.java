package gcnc.parse;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.Word;
import gcnc.parse.gen.GCodeLexer;
import java.io.IOException;
import java.io.Reader;
import java.util.ArrayList;
import java.util.List;
import org.antlr.v4.runtime.BaseErrorListener;
import org.antlr.v4.runtime.RecognitionException;
import org.antlr.v4.runtime.Recognizer;
import org.antlr.v4.runtime.Token;

/**
 * The parse stage: reads a part program one physical line at a time and returns each line that
 * holds words as a {@link RawBlock} (grammar/GCode.g4, rule {@code block}). Memory holds one line.
 *
 * <p>Recovery (thesis §10 [REC], fixing §12 items 2-4): only the first error of a line is reported;
 * the line then comes back {@code malformed} with the words read before the error, and the next
 * line is read normally. The rest of a bad line is still tokenised, only so that a comment opened
 * there is followed onto the next lines.
 */
public final class BlockReader {
    private final LineSource source;
    private final Diagnostics diagnostics;
    private final LineCharStream stream = new LineCharStream();
    /** Made on the first line the fast scanner leaves to it: most programs never load ANTLR. */
    private GCodeLexer lexer;
    private final List<Word> words = new ArrayList<>();
    /** Try {@link FastScanner} before the ANTLR lexer (off only in tests that compare the two). */
    private final boolean fastPath;
    /** The previous line ended inside a comment; where that comment's '(' stands. */
    private boolean inComment;
    private Span commentStart;
    /** The current line's first error, or null. */
    private Span errorAt;

    public BlockReader(Reader in, Diagnostics diagnostics) {
        this(in, diagnostics, true);
    }

    BlockReader(Reader in, Diagnostics diagnostics, boolean fastPath) {
        this.source = new LineSource(in);
        this.diagnostics = diagnostics;
        this.fastPath = fastPath;
    }

    /** The next block, or null at the end of the input. */
    public RawBlock next() throws IOException {
        while (source.next()) {
            RawBlock block = readLine();
            if (block != null) {
                return block;
            }
        }
        if (inComment) {
            inComment = false;
            diagnostics.error(Code.E005_COMMENT_NOT_CLOSED, commentStart);
        }
        return null;
    }

    /** Lines read so far (at the end: the number of lines in the input). */
    public int lines() {
        return source.number();
    }

    /** The current line as a block; null for a blank, whitespace- or comment-only line. */
    private RawBlock readLine() {
        words.clear();
        errorAt = null;
        boolean open = inComment;
        if (!open && fastPath && FastScanner.scan(source.chars(), source.length(), source.number(), words)) {
            return words.isEmpty() ? null : new RawBlock(source.number(), words, lastSpan(), false);
        }
        words.clear();
        inComment = false;
        for (int from = 0; from >= 0; open = true) {
            from = lexSegment(from, open);
        }
        if (words.isEmpty() && errorAt == null) {
            return null;
        }
        Span last = words.isEmpty() ? errorAt : lastSpan();
        return new RawBlock(source.number(), words, last, errorAt != null);
    }

    private Span lastSpan() {
        return words.get(words.size() - 1).span();
    }

    /**
     * Lexes the line from buffer offset {@code from} to its end, {@code open} = inside a comment.
     * Returns -1 at the end of the line, or the offset to go on from inside a comment after a
     * nested '(' (the comment stays open until its ')').
     */
    private int lexSegment(int from, boolean open) {
        stream.reset(source.chars(), from, source.length(), open);
        if (lexer == null) {
            lexer = new GCodeLexer(stream);
            lexer.removeErrorListeners();
            lexer.addErrorListener(new ToDiagnostics());
        }
        lexer.setInputStream(stream);
        for (Token t = lexer.nextToken(); t.getType() != Token.EOF; t = lexer.nextToken()) {
            int start = t.getStartIndex();
            switch (t.getType()) {
                case GCodeLexer.INT_WORD, GCodeLexer.FEED_WORD, GCodeLexer.COORD_WORD -> word(t);
                case GCodeLexer.BARE_LETTER -> bareLetter(start);
                case GCodeLexer.NOT_INTEGER -> fail(Code.E013_INTEGER_EXPECTED, start, letterAt(start));
                case GCodeLexer.BAD_NUMBER -> fail(Code.E014_DECIMAL_EXPECTED, start, letterAt(start));
                case GCodeLexer.UNDEFINED_LETTER -> fail(Code.E004_UNDEFINED_FUNCTION, start, text(start));
                case GCodeLexer.STRAY -> fail(Code.E010_SYNTAX, start, "'" + text(start) + "'");
                case GCodeLexer.ILLEGAL -> fail(Code.E003_ILLEGAL_CHARACTER, start, text(start));
                case GCodeLexer.UNCLOSED_COMMENT -> {
                    openComment(start);
                    inComment = true; // it runs to the end of the line
                }
                case GCodeLexer.NESTED_COMMENT -> {
                    openComment(start);
                    fail(Code.E054_NESTED_COMMENT, t.getStopIndex());
                    return stream.offset(t.getStopIndex()) + 1;
                }
                default -> { } // NEWLINE, SPANNING_COMMENT: a line holds no line end
            }
        }
        return -1;
    }

    private void word(Token t) {
        if (errorAt != null) {
            return; // the rest of a bad line is skipped
        }
        int start = t.getStartIndex();
        int at = stream.offset(start);
        int length = t.getStopIndex() - start + 1;
        Letter letter = Letter.of(source.chars()[at]);
        words.add(new Word(letter, new String(source.chars(), at + 1, length - 1), span(start)));
    }

    /** A word letter with no number: thesis errors 1 (G) and 2 (M); error 6 for the others. */
    private void bareLetter(int start) {
        Letter letter = Letter.of(source.chars()[stream.offset(start)]);
        if (letter == Letter.G) {
            fail(Code.E001_G_NUMBER_EXPECTED, start);
        } else if (letter == Letter.M) {
            fail(Code.E002_M_NUMBER_EXPECTED, start);
        } else {
            fail(Code.E006_NUMBER_EXPECTED, start, letter.name());
        }
    }

    /** Remembers where a comment was opened, in case it is never closed (error 5). */
    private void openComment(int start) {
        if (!stream.isVirtual(start)) {
            commentStart = span(start);
        }
    }

    /** Reports the line's first error; later ones on the same line are dropped (thesis §10). */
    private void fail(Code code, int index, Object... args) {
        if (errorAt == null) {
            errorAt = span(index);
            diagnostics.error(code, errorAt, args);
        }
    }

    private Span span(int index) {
        return Span.of(source.number(), stream.offset(index) + 1);
    }

    private String letterAt(int index) {
        return Letter.of(source.chars()[stream.offset(index)]).name();
    }

    /** The character at a stream index as users should read it in a message. */
    private String text(int index) {
        return Chars.show(source.chars(), stream.offset(index), source.length());
    }

    /** The lexer cannot fail (every character has a rule), but nothing of ANTLR's reaches stderr. */
    private final class ToDiagnostics extends BaseErrorListener {
        @Override
        public void syntaxError(Recognizer<?, ?> recognizer, Object offendingSymbol, int line,
                int charPositionInLine, String msg, RecognitionException e) {
            fail(Code.E010_SYNTAX, Math.max(stream.index(), 0), msg);
        }
    }
}
