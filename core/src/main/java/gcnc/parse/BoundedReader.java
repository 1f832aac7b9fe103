package gcnc.parse;

import gcnc.diag.Code;
import gcnc.diag.Diagnostic;
import gcnc.diag.Diagnostics;
import gcnc.diag.Origin;
import gcnc.diag.Span;
import java.io.IOException;
import java.io.Reader;

/**
 * A program's text with two limits, so that no input can hold gcnc in memory or in time: a line
 * longer than {@link #LINE_LIMIT} characters is cut there (E503 at the first character past it; the
 * rest of the line is skipped, not kept), and a text longer than {@link #TEXT_LIMIT} characters
 * ends there (E504). {@code check /dev/zero}, a flood of NULs without a newline, a line of 300 MB:
 * each is refused at a located place after reading at most the limits, in a fixed amount of memory.
 *
 * <p>Lines are counted as the parser counts them: {@code \n}, {@code \r\n} and a lone {@code \r} each
 * end one. The findings are placed in {@code origin} (the program file, or a called program's file),
 * wherever the flow is when the text is read.
 */
public final class BoundedReader extends Reader {
    /** The longest line read: a block of a real program is under 200 characters, a long comment a few thousand. */
    public static final int LINE_LIMIT = 65_536;
    /** The longest text read: 1 GiB, ten times a program of five million blocks. */
    public static final long TEXT_LIMIT = 1L << 30;

    private final Reader in;
    private final Diagnostics diags;
    private final Origin origin;
    private final long textLimit;
    private final int lineLimit;
    private long read;
    private int line = 1;
    private int column;
    private boolean lastCr;
    /** Skipping the rest of a line cut at the limit. */
    private boolean skipping;
    private boolean ended;

    public BoundedReader(Reader in, Diagnostics diags, Origin origin) {
        this(in, diags, origin, LINE_LIMIT, TEXT_LIMIT);
    }

    BoundedReader(Reader in, Diagnostics diags, Origin origin, int lineLimit, long textLimit) {
        this.in = in;
        this.diags = diags;
        this.origin = origin;
        this.lineLimit = lineLimit;
        this.textLimit = textLimit;
    }

    @Override
    public int read(char[] out, int off, int len) throws IOException {
        if (len == 0) {
            return 0;
        }
        while (!ended) {
            // read straight into the caller's array and keep what passes in place (no second copy)
            int n = in.read(out, off, len);
            if (n < 0) {
                ended = true;
                break;
            }
            int kept = pass(out, off, n);
            if (kept > 0) {
                return kept;
            }
        }
        return -1;
    }

    /**
     * Keeps count of lines over the {@code n} characters read into {@code text} at {@code off}, moving
     * those kept to the front (a line's characters past the limit are dropped); how many were kept.
     */
    private int pass(char[] text, int off, int n) {
        // the counters in locals for the loop (every character of the program comes through here)
        int col = column;
        int ln = line;
        boolean cr = lastCr;
        boolean skip = skipping;
        // the characters that may still be read: the text limit is reached within this pass when fewer than n
        int room = (int) Math.min(n, textLimit - read);
        int end = off + room;
        int k = off;
        try {
            if (!skip) {
                // The usual case, no line cut yet: the characters stay where they are, and only line
                // ends and the length of the line are looked at. The first character past the line
                // limit, or any after it, goes to the loop below, which drops them.
                for (; k < end; k++) {
                    char c = text[k];
                    if (c == '\n') {
                        if (!cr) {
                            ln++;
                        }
                        cr = false;
                        col = 0;
                    } else if (c == '\r') {
                        ln++;
                        cr = true;
                        col = 0;
                    } else if (col < lineLimit) {
                        cr = false;
                        col++;
                    } else {
                        break;
                    }
                }
            }
            int w = k;
            for (; k < end; k++) {
                char c = text[k];
                if (c == '\n' || c == '\r') {
                    if (!(c == '\n' && cr)) {
                        ln++;
                    }
                    cr = c == '\r';
                    col = 0;
                    skip = false;
                    text[w++] = c;
                    continue;
                }
                cr = false;
                if (skip) {
                    continue;
                }
                if (++col > lineLimit) {
                    skip = true;
                    diags.report(new Diagnostic(Code.E503_LINE_TOO_LONG, gcnc.diag.Severity.ERROR, Span.of(ln, col),
                            java.util.List.of(Integer.toString(lineLimit)), origin));
                    continue;
                }
                text[w++] = c;
            }
            read += room;
            if (room < n) {
                ended = true;
                diags.report(new Diagnostic(Code.E504_TEXT_TOO_LONG, gcnc.diag.Severity.ERROR,
                        Span.of(ln, Math.max(1, col + 1)), java.util.List.of(Long.toString(textLimit)), origin));
            }
            return w - off;
        } finally {
            column = col;
            line = ln;
            lastCr = cr;
            skipping = skip;
        }
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
