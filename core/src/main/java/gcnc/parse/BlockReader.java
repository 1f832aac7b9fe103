package gcnc.parse;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Origin;
import gcnc.diag.Span;
import gcnc.ir.Letter;
import gcnc.ir.RawBlock;
import gcnc.ir.ShortLists;
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
 * <p>Recovery (thesis §10 [REC], fixing §12 items 2-4): only the first error of a line is reported
 * (a Fanuc macro character, error 111, takes the place of any earlier one); the line then comes
 * back {@code malformed} with the words read before its first bad token, and the next line is read
 * normally. The rest of a bad line is still tokenised, only so that a comment opened
 * there is followed onto the next lines. Where a typing slip explains the error (the letter O
 * for a zero, a decimal comma: {@link Slips}), the hint that names the fix takes its place.
 */
public final class BlockReader implements BlockSource {
    private final LineSource source;
    private final Diagnostics diagnostics;
    private final LineCharStream stream = new LineCharStream();
    /** The lexer's view of a line with its typing slips fixed ({@link #slip}). */
    private final LineCharStream probe = new LineCharStream();
    /** Made on the first line the fast scanner leaves to it: most programs never load ANTLR. */
    private GCodeLexer lexer;
    private final List<Word> words = new ArrayList<>();
    /** The number texts of the fast scanner's words, shared where they repeat. */
    private final NumberTexts texts = new NumberTexts();
    /** Try {@link FastScanner} before the ANTLR lexer (off only in tests that compare the two). */
    private final boolean fastPath;
    /**
     * The control has Fanuc macro B: a macro statement line is handed on whole, as
     * {@link RawBlock#macro}, for gcnc.flow to run; else it is error 111.
     */
    private final boolean macros;
    /**
     * Haas and Fanuc: a comment ends at the first ')' or at the end of its line; a '(' inside it is
     * text. Else (the thesis's control) a comment may span lines and a '(' inside it is error 54.
     */
    private final boolean lineComments;
    /**
     * Where a DOS end-of-file mark (Ctrl-Z) ended a line ({@link LineSource#cutEndOfFileMark}),
     * until a block on a later line is warned about (E602): a transfer program may stop at the mark.
     */
    private Span eofMark;
    /** The previous line ended inside a comment; where that comment's '(' stands. */
    private boolean inComment;
    private Span commentStart;
    /**
     * The current line's first error, or null; it is reported when the whole line has been read,
     * because a macro character later on the line takes its place (error 111).
     */
    private Span errorAt;
    private Code errorCode;
    private Object[] errorArgs;
    /** The current line's block delete level (0 = none). */
    private int blockDelete;
    /** The column of the current line's '/' when it stands in the middle of the block, else 0. */
    private int deleteColumn;
    /** The shop's waivers in the comments, {@code (GCNC ALLOW E642: reason)}, handed to the run's {@link gcnc.diag.Waivers}. */
    private final WaiverComments waivers;

    public BlockReader(Reader in, Diagnostics diagnostics) {
        this(in, diagnostics, true, false, false, Origin.PROGRAM);
    }

    /**
     * A reader for a control: it has Fanuc macro B when {@code macros} (its macro lines come back as
     * {@link RawBlock#macro}), and it stops at the closing '%' as a control does ({@link #tapeEnd}).
     * The other constructors read the whole text as the grammar does.
     */
    public static BlockReader forControl(Reader in, Diagnostics diagnostics, boolean macros) {
        return forControl(in, diagnostics, macros, false);
    }

    /**
     * A reader for a control: with Fanuc macro B when {@code macros}; with {@code lineComments},
     * a comment ends at the end of its line at the latest and a '(' inside it is text (Haas, Fanuc);
     * it stops at the closing '%' as a control does ({@link #tapeEnd}).
     */
    public static BlockReader forControl(Reader in, Diagnostics diagnostics, boolean macros, boolean lineComments) {
        return forControl(in, diagnostics, macros, lineComments, Origin.PROGRAM);
    }

    /** {@link #forControl(Reader, Diagnostics, boolean, boolean)} for the file {@code origin} names (its waivers' file). */
    public static BlockReader forControl(Reader in, Diagnostics diagnostics, boolean macros, boolean lineComments,
                                         Origin origin) {
        BlockReader r = new BlockReader(in, diagnostics, true, macros, lineComments, origin);
        r.tapeEnd = new TapeEnd();
        return r;
    }

    BlockReader(Reader in, Diagnostics diagnostics, boolean fastPath) {
        this(in, diagnostics, fastPath, false, false, Origin.PROGRAM);
    }

    BlockReader(Reader in, Diagnostics diagnostics, boolean fastPath, boolean macros, boolean lineComments,
                Origin origin) {
        this.source = new LineSource(in);
        this.diagnostics = diagnostics;
        this.fastPath = fastPath;
        this.macros = macros;
        this.lineComments = lineComments;
        this.waivers = new WaiverComments(diagnostics, lineComments, origin.file());
    }

    /** The next block, or null at the end of the input (or of the tape: {@link #tapeEnd}). */
    @Override
    public RawBlock next() throws IOException {
        while (source.next()) {
            int mark = source.cutEndOfFileMark();
            if (mark >= 0 && eofMark == null) {
                eofMark = Span.of(source.number(), mark + 1);
            }
            if (tapeEnd != null && !inComment && tapeEnd.betweenTapes(source, diagnostics)) {
                continue;
            }
            waivers.line(source.chars(), source.length(), source.number());
            RawBlock block = readLine();
            if (block != null) {
                waivers.block(block.line());
                if (eofMark != null && eofMark.line() < block.line()) {
                    diagnostics.report(Diagnostic.warning(Code.E602_TEXT_AFTER_END_OF_FILE_MARK, eofMark));
                    eofMark = null;
                }
                if (tapeEnd != null) {
                    tapeEnd.block();
                }
                return block;
            }
        }
        waivers.end();
        if (inComment) {
            inComment = false;
            diagnostics.error(Code.E005_COMMENT_NOT_CLOSED, commentStart);
        }
        return null;
    }

    /** Where the closing '%' ends the tape: a control's reading stops there; null: the grammar's reading goes on. */
    private TapeEnd tapeEnd;

    /** Lines read so far (at the end: the number of lines in the input). */
    @Override
    public int lines() {
        return source.number();
    }

    /** The current line as a block; null for a line with no word and no error (blank, comments, '/'). */
    private RawBlock readLine() {
        words.clear();
        errorAt = null;
        boolean open = inComment;
        if (!open && fastPath && FastScanner.scan(source.chars(), source.length(), source.number(), words, texts)) {
            return words.isEmpty() ? null : new RawBlock(source.number(), ShortLists.copyOf(words), lastSpan(), false, 0, 0, null);
        }
        if (!open && DenfordLines.isSetUp(source.chars(), source.length())) {
            int at = MacroLines.firstNonBlank(source.chars(), source.length());
            diagnostics.report(Diagnostic.warning(Code.E261_DENFORD_SETUP_LINE, Span.of(source.number(), at + 1),
                    DenfordLines.text(source.chars(), source.length())));
            return null;
        }
        if (!open && macros && MacroLines.isStatement(source.chars(), source.length())) {
            int at = MacroLines.firstNonBlank(source.chars(), source.length());
            return RawBlock.macro(source.number(), new String(source.chars(), 0, source.length()),
                    Span.of(source.number(), at + 1));
        }
        words.clear();
        blockDelete = 0;
        deleteColumn = 0;
        inComment = false;
        boolean startsInComment = open;
        for (int from = 0; from >= 0; open = true) {
            from = lexSegment(from, open);
        }
        if (errorAt != null) {
            slip(startsInComment);
            diagnostics.error(errorCode, errorAt, errorArgs);
        } else if (words.isEmpty()) {
            return null; // blank, comments, a lone '/'
        }
        Span last = words.isEmpty() ? errorAt : lastSpan();
        return new RawBlock(source.number(), ShortLists.copyOf(words), last, errorAt != null, blockDelete, 0, null, deleteColumn);
    }

    private Span lastSpan() {
        return words.get(words.size() - 1).span();
    }

    /**
     * Puts a hint in the place of the line's error when a typing slip explains it (errors 120 and
     * 121, {@link Slips}): the error lies in a word with the letter O in its number or a decimal
     * comma, and the line, with its slips fixed, reads cleanly. A macro line stays error 111.
     */
    private void slip(boolean open) {
        if (errorCode == Code.E111_MACRO_NOT_SUPPORTED_YET) {
            return;
        }
        int end = source.length();
        char[] fixed = java.util.Arrays.copyOf(source.chars(), end);
        Slips.Slip s = Slips.find(fixed, end, open, errorAt.column() - 1);
        if (s != null && Slips.readsCleanly(lexer, probe, fixed, end, open)) {
            errorAt = Span.of(source.number(), s.at() + 1);
            errorCode = s.code();
            errorArgs = new Object[] {s.written(), s.meant()};
        }
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
                case GCodeLexer.SEQUENCE_WORD, GCodeLexer.INT_WORD, GCodeLexer.TAPE_PROGRAM,
                        GCodeLexer.FEED_WORD, GCodeLexer.COORD_WORD, GCodeLexer.COMMA_WORD -> word(t);
                case GCodeLexer.BLOCK_DELETE -> blockDelete(t);
                case GCodeLexer.BARE_LETTER -> bareLetter(start);
                case GCodeLexer.TEXT -> fail(Code.E109_TEXT_OUTSIDE_COMMENT, start, excerpt(start));
                case GCodeLexer.NOT_INTEGER -> notInteger(t, start);
                case GCodeLexer.BAD_NUMBER -> fail(Code.E014_DECIMAL_EXPECTED, start, letterAt(start));
                case GCodeLexer.MACRO -> macro(start);
                case GCodeLexer.STRAY -> fail(Code.E010_SYNTAX, start, "'" + text(start) + "'");
                case GCodeLexer.ILLEGAL -> fail(Code.E003_ILLEGAL_CHARACTER, start, text(start));
                case GCodeLexer.UNCLOSED_COMMENT -> {
                    openComment(start);
                    if (lineComments) {
                        // Haas, Fanuc: the end of the block ends the comment; the next lines are code
                        // (a virtual '(' goes on after a '(' inside the comment: its own '(' is commentStart)
                        if (errorAt == null) {
                            diagnostics.report(Diagnostic.warning(Code.E601_COMMENT_NOT_CLOSED_ON_ITS_LINE,
                                    stream.isVirtual(start) ? commentStart : span(start)));
                        }
                    } else {
                        inComment = true; // it runs to the end of the line, and on
                    }
                }
                case GCodeLexer.NESTED_COMMENT -> {
                    openComment(start);
                    if (!lineComments) {
                        fail(Code.E054_NESTED_COMMENT, t.getStopIndex());
                    } // else a '(' in a comment is text: the comment goes on to its ')'
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
        int stop = stream.offset(t.getStopIndex()) + 1;
        char[] buf = source.chars();
        boolean comma = buf[at] == ',';
        int l = comma ? SpacedNumbers.skipBlanks(buf, at + 1) : at;
        Letter letter = letter(buf[l]);
        Span span = Span.of(source.number(), at + 1, stop + 1);
        String number = SpacedNumbers.number(letter, buf, at, l + 1, stop, source.number(), diagnostics);
        words.add(comma ? Word.comma(letter, number, span) : new Word(letter, number, span));
    }

    /**
     * A block delete '/' (with its level), once per line (grammar rule {@code block}): the first
     * thing on the line or right after a first N word, it marks the whole block; after other words
     * it marks the rest of the block (Haas, Fanuc: with the switch on the block runs up to the '/').
     * A second '/' is error 10.
     */
    private void blockDelete(Token t) {
        if (errorAt != null) {
            return;
        }
        int start = t.getStartIndex();
        if (blockDelete != 0) {
            fail(Code.E010_SYNTAX, start, "'" + text(start) + "'");
            return;
        }
        blockDelete = t.getStopIndex() > start ? source.chars()[stream.offset(start) + 1] - '0' : 1;
        boolean whole = words.isEmpty() || words.size() == 1 && words.get(0).letter() == Letter.N;
        deleteColumn = whole ? 0 : stream.offset(start) + 1;
    }

    /**
     * Fanuc macro B ('#', '[' or ']'): error 111. The first one on a line is the line's error even
     * when an earlier error was found: a macro line is reported as what it is.
     */
    private void macro(int start) {
        if (errorAt == null || errorCode != Code.E111_MACRO_NOT_SUPPORTED_YET) {
            errorAt = null; // takes the place of an earlier error
            fail(Code.E111_MACRO_NOT_SUPPORTED_YET, start, excerpt(start));
        }
    }

    /** A letter with no number: thesis errors 1 (G) and 2 (M); error 6 for the others. */
    private void bareLetter(int start) {
        Letter letter = letter(source.chars()[stream.offset(start)]);
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

    /**
     * A G, M, N, O, S or T word with a sign or a point: E013; but a G code written with a decimal
     * point (G12.1, G54.1, G50.3) is a code of the Fanuc manual gcnc does not follow yet: E702 names it.
     */
    private void notInteger(Token t, int start) {
        String s = t.getText();
        if (DOTTED_G.matcher(s).matches()) {
            fail(Code.E702_DOTTED_G_NOT_SUPPORTED, start, "G" + s.substring(1));
        } else {
            fail(Code.E013_INTEGER_EXPECTED, start, letterAt(start));
        }
    }

    private static final java.util.regex.Pattern DOTTED_G = java.util.regex.Pattern.compile("[Gg][0-9]+\\.[0-9]+");

    /**
     * Keeps the line's first error, reported at the end of the line; later ones on the same line
     * are dropped (thesis §10).
     */
    private void fail(Code code, int index, Object... args) {
        if (errorAt == null) {
            errorAt = span(index);
            errorCode = code;
            errorArgs = args;
        }
    }

    private Span span(int index) {
        return Span.of(source.number(), stream.offset(index) + 1);
    }

    private String letterAt(int index) {
        return letter(source.chars()[stream.offset(index)]).name();
    }

    /** The letter a word starts with; ':' is Fanuc's tape form of O. */
    private static Letter letter(char c) {
        return c == ':' ? Letter.O : Letter.of(c);
    }

    /** What the user wrote from a stream index on, for errors 109 and 111. */
    private String excerpt(int index) {
        return Chars.excerpt(source.chars(), stream.offset(index), source.length());
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
