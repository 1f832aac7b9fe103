package gcnc.parse;

import java.io.IOException;
import java.io.Reader;

/**
 * Physical lines of a reader, one at a time, in a reused buffer: memory holds one line, never the
 * file. Line ends are LF, CRLF or a lone CR. A byte-order mark at the start of the input is dropped.
 */
final class LineSource {
    private final Reader in;
    private final char[] chunk = new char[1 << 16];
    private int pos;
    private int limit;
    private boolean started;
    private char[] line = new char[256];
    private int length;
    private int number;

    LineSource(Reader in) {
        this.in = in;
    }

    /** Reads the next line; false at the end of the input. */
    boolean next() throws IOException {
        length = 0;
        boolean any = false;
        while (true) {
            if (pos == limit && !fill()) {
                if (any) {
                    number++;
                }
                return any;
            }
            any = true;
            int start = pos;
            while (pos < limit) {
                char c = chunk[pos];
                if (c == '\n' || c == '\r') {
                    append(start, pos);
                    pos++;
                    if (c == '\r') {
                        skipLf();
                    }
                    number++;
                    return true;
                }
                pos++;
            }
            append(start, pos);
        }
    }

    private void skipLf() throws IOException {
        if (pos == limit && !fill()) {
            return;
        }
        if (chunk[pos] == '\n') {
            pos++;
        }
    }

    private boolean fill() throws IOException {
        int n;
        do {
            n = in.read(chunk, 0, chunk.length);
        } while (n == 0);
        pos = 0;
        limit = Math.max(n, 0);
        if (!started && limit > 0) {
            started = true;
            if (chunk[0] == '\uFEFF') {
                pos = 1;
                return limit > 1 || fill();
            }
        }
        return limit > 0;
    }

    private void append(int from, int to) {
        int n = to - from;
        if (length + n > line.length) {
            line = java.util.Arrays.copyOf(line, Math.max(line.length * 2, length + n));
        }
        System.arraycopy(chunk, from, line, length, n);
        length += n;
    }

    /** The current line's characters (valid up to {@link #length()}), without its line end. */
    char[] chars() {
        return line;
    }

    int length() {
        return length;
    }

    /**
     * A DOS end-of-file mark (Ctrl-Z, 0x1A) with nothing but more marks, spaces and tabs after it
     * on the current line: the end of the file as DOS editors and transfer programs wrote it. The
     * line is cut there; returns the mark's offset, or -1 when the line has none. A mark with text
     * after it stays on the line (an illegal character, error 3).
     */
    int cutEndOfFileMark() {
        int mark = -1;
        for (int i = length - 1; i >= 0; i--) {
            char c = line[i];
            if (c == '\u001A') {
                mark = i;
            } else if (c != ' ' && c != '\t') {
                break;
            }
        }
        if (mark >= 0) {
            length = mark;
        }
        return mark;
    }

    /** 1-based number of the current line; lines read so far. */
    int number() {
        return number;
    }
}
