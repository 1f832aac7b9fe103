package gcnc.galil;

/**
 * Writes one block's lines tagged with its source line, preceded by {@code NO L<line>} when the
 * source map goes inline (only if the block writes anything). Enforces the 80-character line limit
 * of Galil program memory: every line a dialect builds is short by construction, so a longer one
 * is a bug here, not bad input.
 */
final class BlockWriter {
    static final int MAX_LINE = 80;

    private final LineSink sink;
    private final int line;
    private boolean commented;

    BlockWriter(LineSink sink, int line, boolean inlineSourceMap) {
        this.sink = sink;
        this.line = line;
        this.commented = !inlineSourceMap;
    }

    void emit(String text) {
        if (!commented) {
            commented = true;
            sink.accept(new GalilLine("NO L" + line, line));
        }
        if (text.length() > MAX_LINE) {
            throw new IllegalStateException("DMC line longer than " + MAX_LINE + ": " + text);
        }
        sink.accept(new GalilLine(text, line));
    }

    /** The OF command with {@code value} in field {@code index} (0-based), earlier fields empty. */
    static String offset(int index, String value) {
        StringBuilder sb = new StringBuilder(16).append("OF ");
        for (int i = 0; i < index; i++) {
            sb.append(',');
        }
        return sb.append(value).toString();
    }
}
