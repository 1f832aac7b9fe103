package gcnc.parse;

import org.antlr.v4.runtime.CharStream;
import org.antlr.v4.runtime.IntStream;
import org.antlr.v4.runtime.misc.Interval;

/**
 * The ANTLR lexer's view of part of one line, reused for every line (no copy, no allocation).
 * With {@code open} set it shows a virtual '(' before the text, so that a line which starts
 * inside a comment continued from the previous line is lexed by the grammar's comment rules.
 */
final class LineCharStream implements CharStream {
    private char[] buf = new char[0];
    private int from;
    private int size;
    private boolean open;
    private int p;

    void reset(char[] buf, int from, int end, boolean open) {
        this.buf = buf;
        this.from = from;
        this.open = open;
        this.size = end - from + (open ? 1 : 0);
        this.p = 0;
    }

    /** Offset in the line buffer of stream index {@code i} (-1 for the virtual '('). */
    int offset(int i) {
        return from + i - (open ? 1 : 0);
    }

    /** Whether stream index {@code i} is the virtual '(' of a continued comment. */
    boolean isVirtual(int i) {
        return open && i == 0;
    }

    private char charAt(int i) {
        return isVirtual(i) ? '(' : buf[offset(i)];
    }

    @Override
    public int LA(int i) {
        if (i == 0) {
            return 0;
        }
        int at = i > 0 ? p + i - 1 : p + i;
        return at < 0 || at >= size ? IntStream.EOF : charAt(at);
    }

    @Override
    public void consume() {
        if (p >= size) {
            throw new IllegalStateException("cannot consume EOF");
        }
        p++;
    }

    @Override
    public int mark() {
        return -1;
    }

    @Override
    public void release(int marker) {
        // everything stays in the buffer until the next line
    }

    @Override
    public int index() {
        return p;
    }

    @Override
    public void seek(int index) {
        p = Math.min(Math.max(index, 0), size);
    }

    @Override
    public int size() {
        return size;
    }

    @Override
    public String getSourceName() {
        return IntStream.UNKNOWN_SOURCE_NAME;
    }

    @Override
    public String getText(Interval interval) {
        int a = Math.max(interval.a, 0);
        int b = Math.min(interval.b, size - 1);
        StringBuilder sb = new StringBuilder(Math.max(b - a + 1, 0));
        for (int i = a; i <= b; i++) {
            sb.append(charAt(i));
        }
        return sb.toString();
    }
}
