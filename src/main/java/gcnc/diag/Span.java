package gcnc.diag;

/** A place in a source file: 1-based line and column, as editors count them. */
public record Span(int line, int column) implements Comparable<Span> {
    public Span {
        if (line < 1 || column < 1) {
            throw new IllegalArgumentException("span is 1-based: " + line + ":" + column);
        }
    }

    public static Span of(int line, int column) {
        return new Span(line, column);
    }

    @Override
    public int compareTo(Span o) {
        return line != o.line ? Integer.compare(line, o.line) : Integer.compare(column, o.column);
    }
}
