package gcnc.parse;

import gcnc.diag.Code;
import gcnc.diag.Diagnostics;
import gcnc.diag.Span;

/**
 * The closing '%' (end of tape), as a Fanuc or Haas control reads it, for {@link BlockReader} (the
 * line it reads now is given to {@link #betweenTapes}): a '%' line after the first block ends the
 * tape, and the lines after it are not read until one starts the next program (an O word);
 * anything else there is the note E705, once.
 */
final class TapeEnd {
    /** Blocks handed on so far: a '%' line after the first block is the end of the tape. */
    private int blocks;
    /** The line of the closing '%' while between tapes (0: reading a tape); whether E705 was said since. */
    private int tapeEndLine;
    private boolean skippedNoted;

    /** One more block was handed on. */
    void block() {
        blocks++;
    }

    /**
     * The closing '%' (end of tape): a Fanuc or Haas control stops reading there. Whether the
     * current line is that mark or a line after it before the next program: a line starting with
     * an O word ({@code O2000}, {@code :2000}; a file holding several programs, or a '%' opening
     * another tape) is read again. Anything else after the mark (a note, a DOS end-of-file byte)
     * is not read: the note E705, once, at its first character (a lone DOS end-of-file byte is silent).
     */
    boolean betweenTapes(LineSource source, Diagnostics diagnostics) {
        int at = firstNonBlank(source);
        char c = at < 0 ? ' ' : source.chars()[at];
        if (tapeEndLine == 0) {
            if (blocks > 0 && c == '%') {
                tapeEndLine = source.number();
                skippedNoted = false;
                return true;
            }
            return false;
        }
        if ((c == 'O' || c == 'o' || c == ':') && at + 1 < source.length() && Character.isDigit(source.chars()[at + 1])) {
            tapeEndLine = 0;
            return false;
        }
        if (at >= 0 && c != '%' && !skippedNoted) {
            skippedNoted = true;
            diagnostics.report(new gcnc.diag.Diagnostic(Code.E705_AFTER_TAPE_END, gcnc.diag.Severity.NOTE,
                    Span.of(source.number(), at + 1), java.util.List.of(Integer.toString(tapeEndLine))));
        }
        return true;
    }

    /**
     * The index of the current line's first character that is not a blank, or -1. The DOS
     * end-of-file byte (Ctrl-Z) a file sent from Windows ends with counts as a blank here: it is no
     * text, and after the closing '%' it needs no note.
     */
    private static int firstNonBlank(LineSource source) {
        char[] cs = source.chars();
        for (int i = 0; i < source.length(); i++) {
            if (cs[i] != ' ' && cs[i] != '\t' && cs[i] != '\u001a') {
                return i;
            }
        }
        return -1;
    }
}
