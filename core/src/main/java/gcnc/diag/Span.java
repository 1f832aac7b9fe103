package gcnc.diag;

/**
 * A place in a source file: 1-based line and column, as editors count them, and where the text the
 * place is about ends on that line: {@code endColumn} is the column just after it (a word {@code X10.}
 * at column 5 ends at 9), as SARIF counts; 0 when only the start is known. Columns count UTF-16 code
 * units. Spans are ordered by where they start.
 */
public record Span(int line, int column, int endColumn) implements Comparable<Span> {
    public Span {
        if (line < 1 || column < 1) {
            throw new IllegalArgumentException("span is 1-based: " + line + ":" + column);
        }
        if (endColumn != 0 && endColumn <= column) {
            throw new IllegalArgumentException("a span ends after it starts: " + column + ".." + endColumn);
        }
    }

    /** A place whose end is not known. */
    public static Span of(int line, int column) {
        return new Span(line, column, 0);
    }

    /** The text from {@code column} up to (not including) {@code endColumn}. */
    public static Span of(int line, int column, int endColumn) {
        return new Span(line, column, endColumn);
    }

    /** Whether the end is known. */
    public boolean hasEnd() {
        return endColumn != 0;
    }

    @Override
    public int compareTo(Span o) {
        return line != o.line ? Integer.compare(line, o.line) : Integer.compare(column, o.column);
    }
}
